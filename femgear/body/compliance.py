"""FE tooth compliance along the path of contact (the ``fe`` mesh-stiffness level).

Each member is meshed once (the whole gear by default, graded: ``h·refine_ratio`` on
the loaded tooth, ``h`` elsewhere; P2, plane strain, bore clamped — the body of
Sainsot's foundation term) and its pyamg hierarchy is built once; every path
position is then one right-hand side.  A sector of a few teeth is not used by
default: with free cut sides it is far too soft (rim bending), with clamped or
roller sides too stiff near the root (−35 % at the start of contact, measured).

Load: a normal force F (per unit face width) spread uniformly over the flank facets
within ``patch`` of the contact point on the middle tooth, directed along the line
of action into the tooth.  Deflection: the displacement along the load averaged over
the tooth cross-section through the contact point (perpendicular to the centre line,
|y| ≤ 0.9 h_P) — the section whose motion the PEM beam energy describes.  Averaging
over the section keeps the local contact flattening under the patch small; it is
carried, as in the PEM level, by the Hertz term 4(1−ν²)/(πE) (Yang & Lin 1987).
(The point Q where the line of action crosses the centre line, used by some authors,
misses the bending between Q's and P's sections: 10–15 % stiffer, measured.)
References for this split: Sainsot et al. 2004; Chaari et al. 2009.
"""

from __future__ import annotations

import math
import time

import numpy as np

from femgear.body.elastic import ElasticProblem
from femgear.body.forms import traction
from femgear.geometry.gear import GearPair


class ToothFE:
    """One member's FE model, reused for all load positions."""

    def __init__(self, pair: GearPair, member: int, youngs_modulus: float, poisson_ratio: float,
                 h: float | None = None, n_teeth: int | None = None, bore_radius: float = 0.0,
                 plane: str = "strain", order: int = 2, refine_ratio: float = 0.5, solver: str = "lu"):
        from femgear.mesh.section import gear_section

        t0 = time.perf_counter()
        self.pair, self.member = pair, member
        rf = pair.rf1 if member == 1 else pair.rf2
        rbore = bore_radius if bore_radius > 0 else 0.5 * rf
        self.h = h or pair.m_n / 4
        ra = pair.ra1 if member == 1 else pair.ra2
        centre = (0.0, 0.5 * (rf + ra))
        self.mesh = gear_section(pair, member, self.h, n_teeth=n_teeth, bore_radius=rbore, refine_at=centre,
                                 refine_ratio=refine_ratio, refine_radius=1.2 * (ra - rf))
        self.mesh_seconds = time.perf_counter() - t0
        self.problem = ElasticProblem(self.mesh, youngs_modulus, poisson_ratio, plane, order=order, solver=solver)
        self.problem.fix(self.problem.boundary_dofs("bore"), 0.0)
        self.solve_seconds = 0.0
        # flank facets of the middle tooth, +x side
        f = self.mesh.boundaries["flank"]
        mid = self.mesh.p[:, self.mesh.facets[:, f]].mean(axis=1)
        self._flank = f[mid[0] > 0]
        self._flank_mid = mid[:, mid[0] > 0]

    def _geometry(self, u):
        """Contact point P, unit load direction d (into the tooth) and the points of P's cross-section (global)."""
        from femgear.stiffness.pem import contact_geometry, load_point

        r, alpha, _ = contact_geometry(self.pair, self.member, u)
        xP, hP, _ = load_point(self.pair, self.member, u)
        psi = np.arctan2(hP, xP)
        # tooth frame (x along the centre line): +x flank is the half y < 0 → global (X, Y) = (−y, x)
        P = np.array([hP, xP])
        # outward normal at the y<0 half: sinα e_r(−ψ) − cosα e_θ(−ψ)
        nx = math.sin(alpha) * math.cos(-psi) + math.cos(alpha) * math.sin(-psi)
        ny = math.sin(alpha) * math.sin(-psi) - math.cos(alpha) * math.cos(-psi)
        n = np.array([-ny, nx])
        ys = np.linspace(-0.9, 0.9, 15) * hP
        section = np.vstack([-ys, np.full(ys.shape, xP)])
        return P, -n, section

    def compliance(self, u: float, force: float = 1.0e5, patch: float | None = None) -> float:
        """Tooth compliance per unit face width at path position ``u`` [m/N · m].

        ``patch``: half-length of the loaded flank strip (default 0.15 m_n, independent of h).
        """
        u_, d, section = self.solve_load(u, force, patch)
        dx, dy = self._probe(u_, section)
        return float(np.mean(dx * d[0] + dy * d[1])) / force

    def solve_load(self, u: float, force: float, patch: float | None = None):
        """Displacement DOFs under the normal ``force`` per unit face width at path position ``u``:
        (displacements, load direction, P's cross-section points)."""
        from skfem import FacetBasis

        P, d, section = self._geometry(u)
        a = patch or 0.15 * self.pair.m_n
        dist = np.hypot(self._flank_mid[0] - P[0], self._flank_mid[1] - P[1])
        facets = self._flank[dist <= a]
        if facets.size == 0:
            facets = self._flank[[np.argmin(dist)]]
        fb = FacetBasis(self.mesh, self.problem.basis.elem, facets=facets)
        length = float(np.sum(fb.dx))
        x = fb.global_coordinates()[0]
        t = force / length
        f = traction.assemble(fb, tx=t * d[0] + 0 * x, ty=t * d[1] + 0 * x)
        u_, info = self.problem.solve(f, case=f"tooth compliance member {self.member} at u={u:.6g}")
        self.solve_seconds += info.seconds
        return u_, d, section

    def _probe(self, u_, points):
        (ux, bx), (uy, by) = self.problem.basis.split(u_)
        return bx.probes(points) @ ux, by.probes(points) @ uy

    @property
    def ndofs(self) -> int:
        return self.problem.ndofs


def fe_pair_stiffness_per_width(pair: GearPair, u: np.ndarray, youngs_modulus: float, poisson_ratio: float,
                                bore_radius: tuple[float, float] = (0.0, 0.0), h: float | None = None,
                                n_teeth: int | None = None, order: int = 2, plane: str = "strain",
                                refine_ratio: float = 0.5):
    """Transverse tooth-pair stiffness per unit face width at ``u`` from the FE teeth in series + Hertz.

    Returns (k [N/m per m], info) with the per-member compliances, DOF counts and times.
    """
    from femgear.stiffness.pem import hertz_compliance

    t0 = time.perf_counter()
    u = np.atleast_1d(np.asarray(u, float))
    comp, info = {}, {"ndofs": [], "h": None}
    for member in (1, 2):
        model = ToothFE(pair, member, youngs_modulus, poisson_ratio, h=h, n_teeth=n_teeth,
                        bore_radius=bore_radius[member - 1], plane=plane, order=order,
                        refine_ratio=refine_ratio)
        comp[member] = np.array([model.compliance(ui) for ui in u])
        info["ndofs"].append(model.ndofs)
        info["h"] = model.h
        info[f"solve_seconds_{member}"] = model.solve_seconds
        info[f"setup_seconds_{member}"] = model.problem.setup_seconds
    info["c1"], info["c2"] = comp[1], comp[2]
    info["seconds"] = time.perf_counter() - t0
    k = 1.0 / (hertz_compliance(youngs_modulus, poisson_ratio) + comp[1] + comp[2])
    return k, info
