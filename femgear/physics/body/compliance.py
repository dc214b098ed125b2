"""FE tooth compliance along the path of contact (the ``fe`` mesh-stiffness level).

Each member is meshed once (the whole gear by default, graded: ``h·refine_ratio`` on
the loaded tooth, ``h`` on its neighbours, then growing by :data:`GRADE` per unit distance
from the three middle teeth and per unit depth below the root, up to max(4 h, ¼ of the rim);
P2, plane strain, bore clamped — the body of Sainsot's foundation term) and factored once;
every path position is then one right-hand side.  Sizes are in module units
(:func:`section_size`), so similar gears get the same mesh: the marine wheel (z 97, a 40 m_n
rim) had 1 M DOF with the uniform h = m_n/4 of the whole gear (251 s, 9.6 GB).  A sector of a few teeth is not used by
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

from femgear.perf import Estimate, Progress, announce
from femgear.physics.body.elastic import ElasticProblem
from femgear.physics.body.forms import traction
from femgear.physics.geometry.gear import GearPair
from femgear.physics.mesh.segment import FAR_FRACTION

GRADE = 0.35   #: growth of the element size per unit distance beyond the three middle teeth and below the root


def section_size(pair: GearPair, level: int = 1) -> float:
    """Element size of the ``fe`` level's section on the teeth at body ``level``: m_n/(3 + level) (m_n/4 at the
    default level 1; half that at the contact), in module units like the 3-D bodies."""
    if level < 0:
        raise ValueError(f"level must be ≥ 0, got {level}")
    return pair.m_n / (3 + level)


def section_dofs(mesh, order: int) -> int:
    """Unknowns of a plane vector P``order`` model on the section ``mesh``."""
    return 2 * (mesh.p.shape[1] + (mesh.facets.shape[1] if order == 2 else 0))


def section_estimate(mesh, order: int, member: int, n_positions: int) -> Estimate:
    """Expected DOF, memory and time of one member's ``fe`` compliance: SuperLU (COLAMD) on the 2-D section,
    fitted on this 2-core machine (``python studies/benchmarks/estimates.py``, five zoo pairs, docs/cost.md):
    the process's 0.13 GB + 3.7 kB per DOF; 40 µs per DOF plus 3 µs per DOF and path position (measured
    CPU / estimate 0.8–1.2, peak memory / estimate 0.97–1.03 at 10–18 k DOF)."""
    dofs = section_dofs(mesh, order)
    return Estimate(f"fe stiffness, {'pinion' if member == 1 else 'gear'} section (P{order})", dofs,
                    0.13e9 + 3.7e3 * dofs, 4e-5 * dofs + 3e-6 * dofs * n_positions)


def coarser_fits(estimate: Estimate, level: int, budget: float) -> str:
    """The finest coarser ``fe`` level whose section fits ``budget`` [B] (the DOF scale as (3 + level)², h being
    m_n/(3 + level)), or the mesh-size key when none does."""
    for k in range(level - 1, -1, -1):
        dofs = estimate.dofs * ((3 + k) / (3 + level)) ** 2
        if 0.13e9 + 3.7e3 * dofs <= budget:
            return f"numerics.body_level = {k} fits (about {dofs / 1e3:.0f} k DOF)"
    return "no body level fits: give a larger stiffness.fe_mesh_size"


def _web_layout(pair: GearPair, member: int, bore: float, web: tuple[float, float, float], h: float,
                refine_ratio: float, far: tuple | None):
    """(split radius, grade) of a section with a web ``web`` = (b_s/b, r_hub, r_rim) above the bore [m]: the rim
    above r_rim is checked against ISO 6336-3's 0.5 h_t, embedded as a circle and gets its thin-rim size
    (:func:`femgear.physics.mesh.section.rim_size`) all round, the web too."""
    from femgear.physics.mesh.section import check_rim, rim_size

    thickness, hub, rim = web
    if not (0 < thickness <= 1 and bore <= hub < rim):
        raise ValueError(f"web = (b_s/b, r_hub, r_rim) = {web!r} needs 0 < b_s/b ≤ 1 and bore ≤ r_hub < r_rim "
                         f"(bore {bore * 1e3:.4g} mm)")
    check_rim(pair, member, rim)
    thin = rim_size(pair, member, rim)
    if thin is not None and far is not None:
        far = (far[0], min(far[1], max(thin, h * refine_ratio))) + tuple(far[2:])
    return rim, far


class ToothFE:
    """One member's FE model, reused for all load positions.

    ``support``: ``"clamped"`` (the bore held: a body on a rigid shaft, the default) or ``"distributed"`` (the
    bore's mean rigid motion held, :meth:`ElasticProblem.tie`: a free ring, the softest support).  ``web`` =
    (b_s/b, r_hub, r_rim): a webbed gear, the annulus r_hub < r < r_rim a central web b_s/b of the face width
    thick (plane stress), the rim above r_rim checked against ISO 6336-3's 0.5 h_t and meshed as a thin rim
    (``studies/body/thin_rim.py``)."""

    def __init__(self, pair: GearPair, member: int, youngs_modulus: float, poisson_ratio: float,
                 h: float | None = None, n_teeth: int | None = None, bore_radius: float = 0.0,
                 plane: str = "strain", order: int = 2, refine_ratio: float = 0.5, solver: str = "lu",
                 level: int = 1, grade: float | None = GRADE, n_positions: int = 9, support: str = "clamped",
                 web: tuple[float, float, float] | None = None):
        from femgear.physics.mesh.section import gear_section

        if support not in ("clamped", "distributed"):
            raise ValueError(f"support must be 'clamped' or 'distributed', got {support!r}")
        t0 = time.perf_counter()
        self.pair, self.member = pair, member
        rf = pair.rf1 if member == 1 else pair.rf2
        rbore = bore_radius if bore_radius > 0 else 0.5 * rf
        self.h = h or section_size(pair, level)
        ra = pair.ra1 if member == 1 else pair.ra2
        centre = (0.0, 0.5 * (rf + ra))
        far = None if grade is None else (grade, max(4.0 * self.h, FAR_FRACTION * (rf - rbore)), 3)
        split = None
        if web is not None:
            split, far = _web_layout(pair, member, rbore, web, self.h, refine_ratio, far)
        self.mesh = gear_section(pair, member, self.h, n_teeth=n_teeth, bore_radius=rbore, refine_at=centre,
                                 refine_ratio=refine_ratio, refine_radius=1.2 * (ra - rf), grade=far,
                                 split_radius=split)
        self.mesh_seconds = time.perf_counter() - t0
        self.estimate = section_estimate(self.mesh, order, member, n_positions)
        announce(self.estimate, "numerics.body_level", lambda budget: coarser_fits(self.estimate, level, budget))
        thin = None
        if web is not None:                     # the web: the elements between the hub and the rim
            r = np.hypot(*self.mesh.p[:, self.mesh.t].mean(axis=1))
            thin = ((r > web[1]) & (r < web[2]), web[0])
        self.problem = ElasticProblem(self.mesh, youngs_modulus, poisson_ratio, plane, order=order, solver=solver,
                                      thin=thin)
        if support == "distributed":            # the bore's mean rigid motion held (a free ring)
            self.problem.tie("bore")
        else:                                   # the bore (the hub of a web) held
            self.problem.fix(self.problem.boundary_dofs("bore"), 0.0)
        self.solve_seconds = 0.0
        # flank facets of the middle tooth, +x side
        f = self.mesh.boundaries["flank"]
        mid = self.mesh.p[:, self.mesh.facets[:, f]].mean(axis=1)
        self._flank = f[mid[0] > 0]
        self._flank_mid = mid[:, mid[0] > 0]

    def _geometry(self, u):
        """Contact point P, unit load direction d (into the tooth) and the points of P's cross-section (global)."""
        from femgear.physics.stiffness.pem import contact_geometry, load_point

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
                                refine_ratio: float = 0.5, level: int = 1, grade: float | None = GRADE):
    """Transverse tooth-pair stiffness per unit face width at ``u`` from the FE teeth in series + Hertz.

    Returns (k [N/m per m], info) with the per-member compliances, DOF counts and times.
    """
    from femgear.physics.stiffness.pem import hertz_compliance

    t0 = time.perf_counter()
    u = np.atleast_1d(np.asarray(u, float))
    comp, info = {}, {"ndofs": [], "h": None}
    for member in (1, 2):
        model = ToothFE(pair, member, youngs_modulus, poisson_ratio, h=h, n_teeth=n_teeth,
                        bore_radius=bore_radius[member - 1], plane=plane, order=order,
                        refine_ratio=refine_ratio, level=level, grade=grade, n_positions=u.size)
        progress = Progress(model.estimate.stage, u.size, model.estimate.seconds)
        comp[member] = np.empty(u.size)
        for i, ui in enumerate(u):
            comp[member][i] = model.compliance(ui)
            progress(i + 1)
        info["ndofs"].append(model.ndofs)
        info["h"] = model.h
        info[f"solve_seconds_{member}"] = model.solve_seconds
        info[f"setup_seconds_{member}"] = model.problem.setup_seconds
    info["c1"], info["c2"] = comp[1], comp[2]
    info["seconds"] = time.perf_counter() - t0
    k = 1.0 / (hertz_compliance(youngs_modulus, poisson_ratio) + comp[1] + comp[2])
    return k, info
