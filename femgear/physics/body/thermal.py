"""Steady heat conduction and thermo-elastic expansion of the gear body; flank deviation ζ_T.

Levels of the flank deviation (``physics.thermal``):

- ``analytic``: the paper's eqs. 3–5 idea in a consistent form.  The body between the
  bore r_o (shaft temperature rise ΔT_s) and the base circle r_b (flank temperature
  rise ΔT_f) is a free hollow disc in plane stress with the steady logarithmic
  temperature T(r) = ΔT_s + (ΔT_f − ΔT_s) ln(r/r_o)/ln(r_b/r_o); its radial
  displacement is Timoshenko & Goodier's (*Theory of Elasticity*, 3rd ed., §150)

      u(r) = (1+ν)λ/r ∫_a^r T ρ dρ + (1−ν)λ r/(b²−a²) ∫_a^b T ρ dρ + (1+ν)λ a²/((b²−a²) r) ∫_a^b T ρ dρ;

  above r_b the tooth is at ΔT_f, u(r) = u(r_b) + λ ΔT_f (r − r_b).  A radial
  displacement u(r) moves the involute along its outward normal by ζ = u(r) sin α(r)
  (n·e_r = sin α on an involute), i.e. λΔT ρ for a uniform rise.  The paper's printed
  eq. 3 adds a tooth-thickness term to the radial one; a radial field already
  thickens the tooth (rays diverge), so that term would count it twice — femgear
  drops it.  The paper's κ ("temperature rise coefficient") is read as ν.
- ``fe``: steady conduction (flank/fillet/tip at ΔT_f, bore at ΔT_s, cut sides
  insulated) on a gmsh section of 3 teeth, then plane-stress thermo-elasticity with
  rollers on the cut sides (cyclic symmetry of identical teeth), P2 elements, pyamg.
- ``fe3d``: the same conduction and thermo-elasticity in 3-D on the LTCA's member body (both
  helices, groove, ring, bore free), :mod:`femgear.physics.ltca.thermal`; along the path, the
  deviation averaged over the face of both helices.

ζ is positive when material is added along the flank's outward normal (less
backlash).  :func:`analytic_flank_deviation`, :func:`fe_flank_deviation` (and :func:`femgear.physics.ltca.thermal.fe3d_flank_deviation`) return it along the *normal* line of action
(ζ_n = ζ_t cos β_b) at path positions u, like the stiffness convention.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass

import numpy as np

from femgear.physics.body.conduction import solve_temperature
from femgear.physics.body.elastic import ElasticProblem
from femgear.physics.body.forms import thermal_load, thermal_modulus
from femgear.physics.geometry.gear import GearPair


# ---------------- analytic ----------------
def disk_temperature(r, a: float, b: float, Ta: float, Tb: float):
    """Steady radial conduction in a ring: T(r) = Ta + (Tb − Ta) ln(r/a)/ln(b/a)."""
    return Ta + (Tb - Ta) * np.log(np.asarray(r, float) / a) / math.log(b / a)


def disk_radial_displacement(r, a: float, b: float, Ta: float, Tb: float, expansion: float, nu: float):
    """Radial displacement of a free hollow disc (plane stress) with the log temperature profile [m]."""
    r = np.asarray(r, float)
    L = math.log(b / a)

    def integral(x):  # ∫_a^x T ρ dρ
        return Ta * (x**2 - a**2) / 2 + (Tb - Ta) / L * (x**2 / 2 * np.log(x / a) - x**2 / 4 + a**2 / 4)

    Ib = integral(b)
    lam = expansion
    return ((1 + nu) * lam / r * integral(r) + (1 - nu) * lam * r * Ib / (b**2 - a**2)
            + (1 + nu) * lam * a**2 * Ib / ((b**2 - a**2) * r))


def _member(pair: GearPair, member: int):
    return (pair.rb1, pair.rf1) if member == 1 else (pair.rb2, pair.rf2)


def flank_radius(pair: GearPair, member: int, u):
    from femgear.physics.stiffness.pem import contact_geometry

    return contact_geometry(pair, member, u)


def analytic_radial_displacement(pair: GearPair, member: int, r, dT_flank: float, dT_shaft: float,
                                 expansion: float, nu: float, bore_radius: float = 0.0):
    """u(r) of the analytic level for r ≥ r_b [m] (bore 0 → half the root radius)."""
    rb, rf = _member(pair, member)
    a = bore_radius if bore_radius > 0 else 0.5 * rf
    ub = float(disk_radial_displacement(rb, a, rb, dT_shaft, dT_flank, expansion, nu))
    return ub + expansion * dT_flank * (np.asarray(r, float) - rb)


# ---------------- FE ----------------
@dataclass(frozen=True)
class ThermoElasticResult:
    """Temperature rise and displacement fields of one body (skfem bases and DOF vectors)."""

    mesh: object
    basis_T: object
    T: np.ndarray        #: temperature rise [K] (P2 DOFs)
    basis_u: object
    u: np.ndarray        #: displacement [m] (vector P2 DOFs)
    plane: str
    seconds: dict

    def von_mises(self, youngs_modulus: float, poisson_ratio: float, expansion: float):
        """Element-mean von Mises stress [Pa] (plane stress), for VTK output."""
        from skfem.helpers import sym_grad

        from femgear.physics.body.forms import lame

        lam, mu = lame(youngs_modulus, poisson_ratio, self.plane)
        bT = thermal_modulus(youngs_modulus, poisson_ratio, expansion, self.plane)
        uu = self.basis_u.interpolate(self.u)
        TT = self.basis_T.interpolate(self.T)
        e = sym_grad(uu)
        tr = e[0, 0] + e[1, 1]
        sxx = 2 * mu * e[0, 0] + lam * tr - bT * TT
        syy = 2 * mu * e[1, 1] + lam * tr - bT * TT
        sxy = 2 * mu * e[0, 1]
        vm = np.sqrt(sxx**2 - sxx * syy + syy**2 + 3 * sxy**2)
        return np.sum(vm * self.basis_u.dx, axis=1) / np.sum(self.basis_u.dx, axis=1)


def determinate_support(problem: ElasticProblem, radius: float) -> None:
    """Fix 3 DOFs at bore nodes (r,0), (−r,0), (0,r): u_y, u_y, u_x = 0 (no reactions)."""
    problem.fix([problem.nearest_dof((radius, 0.0), "y"), problem.nearest_dof((-radius, 0.0), "y"),
                 problem.nearest_dof((0.0, radius), "x")], 0.0)


def thermo_elastic(mesh, temperature, youngs_modulus: float, poisson_ratio: float, expansion: float,
                   support: str, bore_radius: float | None = None, plane: str = "stress",
                   order: int = 2, tol: float = 1e-10) -> ThermoElasticResult:
    """Displacement of ``mesh`` under the temperature rise ``temperature`` = (basis_T, T).

    ``support``: ``"free"`` (statically determinate 3-DOF support on the bore circle of
    ``bore_radius``, which must pass through mesh nodes on the axes) or ``"rollers"``
    (zero normal displacement on the boundary ``sides``).
    """
    from skfem import Basis

    t0 = time.perf_counter()
    rollers = ("sides",) if support == "rollers" else ()
    if support not in ("free", "rollers"):
        raise ValueError(f"support must be 'free' or 'rollers', got {support!r}")
    prob = ElasticProblem(mesh, youngs_modulus, poisson_ratio, plane, order=order, rollers=rollers)
    if support == "free":
        if bore_radius is None:
            raise ValueError("support='free' needs bore_radius")
        determinate_support(prob, bore_radius)
    basis_T, T = temperature
    bT = thermal_modulus(youngs_modulus, poisson_ratio, expansion, plane)
    dT = Basis(mesh, basis_T.elem, quadrature=prob.basis.quadrature).interpolate(T)
    f = thermal_load.assemble(prob.basis, beta_T=bT, dT=dT)
    t1 = time.perf_counter()
    u, info = prob.solve(f, tol=tol, case="thermo-elastic")
    return ThermoElasticResult(mesh=mesh, basis_T=basis_T, T=T, basis_u=prob.basis, u=u, plane=plane,
                               seconds={"assemble": t1 - t0, "solve": info.seconds, "iterations": info.iterations,
                                        "setup": prob.setup_seconds})


def flank_displacement(result: ThermoElasticResult, pair: GearPair, member: int, r):
    """Outward normal displacement of the +x flank of the middle tooth at radii ``r`` [m] (transverse)."""
    from femgear.physics.geometry.profile import involute_half_angle

    mesh, basis = result.mesh, result.basis_u
    dofs = basis.get_dofs(mesh.boundaries["flank"])
    ix, iy = basis.split_indices()
    fd = dofs.flatten()
    dx_ = np.sort(fd[np.isin(fd, ix)])
    dy_ = np.sort(fd[np.isin(fd, iy)])
    X, Y = basis.doflocs[:, dx_]
    z = pair.z1 if member == 1 else pair.z2
    ang = np.arctan2(Y, X)
    sel = (X > 0) & (np.abs(ang - math.pi / 2) < math.pi / z)
    # x- and y-DOFs share locations; match them by position
    order_x = np.lexsort((basis.doflocs[1, dx_], basis.doflocs[0, dx_]))
    order_y = np.lexsort((basis.doflocs[1, dy_], basis.doflocs[0, dy_]))
    ux, uy = np.empty(dx_.size), np.empty(dx_.size)
    ux[order_x] = result.u[dx_[order_x]]
    uy[order_x] = result.u[dy_[order_y]]
    R = np.hypot(X, Y)[sel]
    o = np.argsort(R)
    R, ux, uy = R[o], ux[sel][o], uy[sel][o]
    r = np.asarray(r, float)
    rb = pair.rb1 if member == 1 else pair.rb2
    alpha = np.arccos(rb / r)
    psi = involute_half_angle(pair, member, r)
    # +x flank = tooth-frame half y < 0 rotated by +π/2; outward normal there
    nt_x = np.sin(alpha) * np.cos(-psi) + np.cos(alpha) * np.sin(-psi)     # sinα e_r(−ψ) − cosα e_θ(−ψ)
    nt_y = np.sin(alpha) * np.sin(-psi) - np.cos(alpha) * np.cos(-psi)
    nX, nY = -nt_y, nt_x
    return np.interp(r, R, ux) * nX + np.interp(r, R, uy) * nY


def analytic_flank_deviation(pair: GearPair, member: int, u, dT_flank: float, dT_shaft: float, expansion: float,
                             poisson_ratio: float = 0.3, bore_radius: float = 0.0) -> np.ndarray:
    """ζ_T [m] along the normal line of action at path positions ``u`` [m] of the free thermal expansion
    (the ``analytic`` level: the radial displacement of the section's disc, see module docstring)."""
    r, alpha, _ = flank_radius(pair, member, u)
    ur = analytic_radial_displacement(pair, member, r, dT_flank, dT_shaft, expansion, poisson_ratio, bore_radius)
    return ur * np.sin(alpha) * math.cos(pair.beta_b)


def fe_flank_deviation(pair: GearPair, member: int, u, dT_flank: float, dT_shaft: float, expansion: float,
                       youngs_modulus: float = 210e9, poisson_ratio: float = 0.3, conductivity: float = 46.0,
                       bore_radius: float = 0.0, h: float | None = None) -> np.ndarray:
    """ζ_T [m] at ``u`` [m] from the 2-D FE conduction and thermo-elasticity of the tooth section (the ``fe``
    level; ``h`` the mesh size)."""
    r, _, _ = flank_radius(pair, member, u)
    res = gear_thermo_elastic(pair, member, dT_flank, dT_shaft, expansion, youngs_modulus, poisson_ratio,
                              conductivity, bore_radius, h)
    return flank_displacement(res, pair, member, r) * math.cos(pair.beta_b)


def section_estimate(mesh, member: int):
    """Expected DOF, memory and time of one member's ``thermal = "fe"`` section (P2 conduction, then P2
    thermo-elasticity by SA-CG), fitted on this 2-core machine (``python studies/benchmarks/estimates.py``, five
    zoo pairs, 9–73 k DOF: CPU / estimate 0.8–1.1, peak memory / estimate 0.97–1.0): the process's 0.13 GB + 3 kB
    per DOF, 0.2 s + 53 µs per DOF."""
    from femgear.perf import Estimate
    from femgear.physics.body.compliance import section_dofs

    dofs = section_dofs(mesh, 2)
    return Estimate(f"fe thermal, {'pinion' if member == 1 else 'gear'} section (P2)", dofs, 0.13e9 + 3.0e3 * dofs,
                    0.2 + 5.3e-5 * dofs)


def gear_thermo_elastic(pair: GearPair, member: int, dT_flank: float, dT_shaft: float, expansion: float,
                        youngs_modulus: float = 210e9, poisson_ratio: float = 0.3, conductivity: float = 46.0,
                        bore_radius: float = 0.0, h: float | None = None, n_teeth: int | None = 3) -> ThermoElasticResult:
    """Conduction + thermo-elasticity on a gmsh section of ``member`` (3 teeth, rollers; or full gear)."""
    from femgear.physics.mesh.section import gear_section

    rf = pair.rf1 if member == 1 else pair.rf2
    rbore = bore_radius if bore_radius > 0 else 0.5 * rf
    mesh = gear_section(pair, member, h or pair.m_n / 5, n_teeth=n_teeth, bore_radius=rbore)
    from femgear.perf import announce

    announce(section_estimate(mesh, member), "thermal.mesh_size", lambda budget: "choose a larger thermal.mesh_size")
    temp = solve_temperature(mesh, conductivity, {"flank": dT_flank, "fillet": dT_flank, "tip": dT_flank,
                                                  "bore": dT_shaft})
    full = "sides" not in mesh.boundaries
    return thermo_elastic(mesh, temp, youngs_modulus, poisson_ratio, expansion,
                          support="free" if full else "rollers", bore_radius=rbore)
