"""Thermal EHL of a circular or elliptic point contact, strip-wise energy equation (reduced form).

Elliptic contacts (R_y != R_x): the frame has X along the entrainment, across the major
axis of the ellipse (for a gear pair: across the contact line), and the domain and the
stretched grid of :func:`femgear.physics.ehl.core.domain.default_domain`. The entrainment is taken
normal to the contact line; the oblique entrainment of a helical pair (angle beta_b to
that normal) is not modelled (see :mod:`femgear.physics.tehl.point_level`).

The Reynolds problem is the isothermal FE point EHL of :mod:`femgear.physics.ehl.point` (Q1,
Newton–Krylov with the multilevel preconditioner) with the temperature field in its
viscosity and density (:class:`ThermalRheology`, on every level of the preconditioner;
coarse levels by injection).  The energy equation is solved on each grid row y = const
through the contact with :func:`femgear.physics.tehl.energy.solve_energy`: at high Péclet number
heat conduction along the surfaces is negligible and the Jaeger surface-temperature
integral acts along x only (Jaeger 1942; Carslaw & Jaeger 1959 §10.7), so the strips are
independent.  Side flow (∂/∂y convection) is neglected in the energy equation — a
documented reduction.  Rows with p_max < 1e-3 p_h carry no heat (θ = 0).  The thermal
loop is :func:`femgear.physics.tehl.loop.thermal_loop`.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, field

import numpy as np

from femgear.errors import ConvergenceError, SceneError
from femgear.physics.contact.film import nvm_central
from femgear.physics.ehl.core import params as pr
from femgear.physics.ehl.core.domain import default_domain
from femgear.physics.ehl.core.grid import Grid
from femgear.physics.ehl.core.surface import apply_surface, evaluate, scene_features
from femgear.physics.ehl.dimensional import solve_point_dimensional
from femgear.physics.ehl.fe.level import Level
from femgear.physics.ehl.fe.newton import KeptPreconditioner, newton_krylov
from femgear.physics.lubrication.oil import OilLaw
from femgear.physics.tehl.energy import ThermalProps, jaeger_matrix, solve_energy
from femgear.physics.tehl.line import ehl_oil_at
from femgear.physics.tehl.loop import thermal_loop
from femgear.physics.tehl.rheology import ThermalRheology


@dataclass(frozen=True)
class TEHLPointResult:
    hc: float
    hmin: float
    pmax: float
    hc_isothermal: float
    dT_max: float
    dT_surface: float
    mu: float
    mu_couette: float
    mu_poiseuille: float
    heat: dict
    iterations: int
    newton_iterations: int
    seconds: float
    seconds_isothermal: float
    a: float
    ph: float
    x: np.ndarray = field(repr=False)
    y: np.ndarray = field(repr=False)
    p: np.ndarray = field(repr=False)
    h: np.ndarray = field(repr=False)
    T_mean: np.ndarray = field(repr=False)   #: film-mean temperature on the nodes (ny, nx) [K]


def solve_tehl_point(load: float, R: float, ue: float, srr: float, T_bulk: float, oil: OilLaw, E_red: float,
                     props: ThermalProps, *, Ry: float | None = None, model: str = "eyring", tau0: float = 5e6,
                     limiting_shear: float = 0.0, level: int = 2, nz: int = 6, heat: bool = True,
                     compressible: bool = True, tol: float = 0.1, relax: float = 0.8, max_iter: int = 40,
                     max_rise: float = 400.0, max_step: float = 25.0, newton_tol: float = 1e-5,
                     roughness=None) -> TEHLPointResult:
    """Thermal EHL of a point contact: load [N], radius R = R_x [m] along the entrainment,
    ``Ry`` across it (None: circular), entrainment speed, SRR, bulk temperature; options as
    :func:`femgear.physics.tehl.solve_tehl_line` (``level`` of the point grid).

    ``roughness``: a scene's ``[roughness]`` table; its stationary features (the paper's
    single peak, eq. 22, fixed at x0; a synthetic surface) enter the film of the thermal
    solve (:func:`rough_levels`); the isothermal start (``hc_isothermal``) is smooth."""
    Ry = R if Ry is None else Ry
    for name, v in (("load", load), ("R", R), ("Ry", Ry), ("ue", ue), ("T_bulk", T_bulk)):
        if not (v > 0 and math.isfinite(v)):
            raise ValueError(f"{name} must be positive and finite (got {v!r})")
    case = f"tehl point F={load:.4g} R={R:.4g} Ry={Ry:.4g} ue={ue:.4g} srr={srr:.4g} T={T_bulk:.4g}"
    t0 = time.perf_counter()
    v1, v2 = ue * (1 + srr / 2), ue * (1 - srr / 2)
    ehl_oil = ehl_oil_at(oil, T_bulk, compressible)
    ratio = R / Ry
    iso = solve_point_dimensional(load, R, Ry, ue, E_red, ehl_oil, level=level, dense_reuse=True)
    t_iso = time.perf_counter() - t0
    res, a, ph = iso.result, iso.a, iso.ph
    hs = a * a / R
    dom = default_domain(ratio, float(nvm_central(res.M, res.L, ratio)) / pr.point_h_moes_factor(res.M))
    levels, rheos = [], []
    for k in range(1, level + 1):
        rh = ThermalRheology(pr.point_alpha_bar(res.M, res.L), viscosity=ehl_oil.viscosity, ph=ph,
                             z=ehl_oil.roelands_z() if ehl_oil.viscosity == "roelands" else 0.68,
                             compressible=compressible, T_bulk=T_bulk, s0=oil.s0 if oil.model == "roelands" else 0.0,
                             beta_t=oil.beta_t, expansion=oil.expansion, T_ref=oil.T0)
        rheos.append(rh)
        levels.append(Level(rh, pr.point_lam_bar(res.M), pr.POINT_LOAD, grid=Grid.build(dom, k), ratio=ratio,
                            ad_factor=1.0, sd_factor=1.0))
    fine = levels[-1]
    g = fine.grid
    rough_levels(levels, roughness, R, a)
    xf = g.x * a
    nt = g.nx - 1
    J1 = jaeger_matrix(nt, (g.x[-1] - g.x[0]) * a, props.B1, v1)
    J2 = jaeger_matrix(nt, (g.x[-1] - g.x[0]) * a, props.B2, v2)
    dy = g.dy * a
    sol = {"PI": res.P.ravel()[fine.interior].copy(), "H0": res.H0, "P": res.P, "H": res.H}
    prec = KeptPreconditioner()      # the re-solves' preconditioner, kept across the thermal iterations

    def energy(theta):
        P2, H2 = sol["P"], sol["H"]
        new = np.zeros_like(theta)
        states = []
        for j in range(g.ny):
            if P2[j].max() < 1e-3:
                continue
            st = solve_energy(xf, P2[j] * ph, 0.5 * (H2[j, :-1] + H2[j, 1:]) * hs, v1, v2, T_bulk, theta[j], oil,
                              props, J1, J2, model=model, tau0=tau0, limiting_shear=limiting_shear, heat=heat)
            new[j] = st.theta
            states.append(st)
        return states, new

    def resolve(theta):
        Tc = theta.mean(axis=2)                                   # (ny, nt) cell centres
        Tn = np.empty((g.ny, g.nx))
        Tn[:, 1:-1] = 0.5 * (Tc[:, :-1] + Tc[:, 1:])
        Tn[:, 0], Tn[:, -1] = Tc[:, 0], Tc[:, -1]
        Tn = T_bulk + Tn
        for k, (lv, rh) in enumerate(zip(levels, rheos)):
            s = 2 ** (len(levels) - 1 - k)
            Tk = Tn[::s, ::s].ravel()
            rh.state["node"] = Tk
            rh.state["quad"] = lv.reynolds.basis.interpolate(Tk)
        sol["PI"], sol["H0"], hist = newton_krylov(levels, sol["PI"], sol["H0"], tol=newton_tol, case=case,
                                                   keep=prec)
        P, H = fine.film(sol["PI"], sol["H0"])
        sol["P"], sol["H"] = P.reshape(g.ny, g.nx), H.reshape(g.ny, g.nx)
        return len(hist.residual)

    states, theta, it, newton_its = thermal_loop(energy, resolve, np.zeros((g.ny, nt, nz)), tol=tol, relax=relax,
                                                 max_step=max_step, max_rise=max_rise, max_iter=max_iter, case=case)
    dx = xf[1] - xf[0]
    heat_tot = {k: float(sum(s.heat[k] for s in states) * dy) for k in
                ("generated", "shear", "compression", "solid1", "solid2", "convected")}
    scale = max(abs(heat_tot["shear"]), heat_tot["solid1"] + heat_tot["solid2"] + abs(heat_tot["convected"]), 1e-300)
    heat_tot["balance_error"] = (heat_tot["generated"] - heat_tot["solid1"] - heat_tot["solid2"]
                                 - heat_tot["convected"]) / scale
    mu_c = float(sum(s.tau_couette.sum() for s in states) * dx * dy / load)
    mu_p = float(sum(s.tau_poiseuille.sum() for s in states) * dx * dy / load)
    P, H = sol["P"], sol["H"]
    j0, i0 = int(np.argmin(np.abs(g.y))), int(np.argmin(np.abs(g.x)))
    surf = max([max(s.surface1.max(), s.surface2.max()) for s in states] + [0.0])   # the film's walls bound its peak too
    Tc = theta.mean(axis=2)
    out = TEHLPointResult(
        hc=float(H[j0, i0] * hs), hmin=float(H.min() * hs), pmax=float(P.max() * ph), hc_isothermal=iso.hc,
        dT_max=float(max(theta.max(), surf)), dT_surface=float(surf), mu=abs(mu_c), mu_couette=mu_c,
        mu_poiseuille=mu_p, heat=heat_tot, iterations=it, newton_iterations=newton_its,
        seconds=time.perf_counter() - t0, seconds_isothermal=t_iso, a=a, ph=ph, x=g.x * a, y=g.y * a, p=P * ph,
        h=H * hs, T_mean=T_bulk + np.concatenate([Tc, Tc[:, -1:]], axis=1))
    if not all(math.isfinite(v) for v in (out.hc, out.pmax, out.dT_max, out.mu)):
        raise ConvergenceError(case, "non-finite result")
    return out


def rough_levels(levels: list[Level], roughness, R: float, a: float) -> None:
    """Subtract the stationary roughness of the scene table ``roughness`` (metres; the
    contact of radius ``R`` along X and Hertz radius ``a``) from the gap of every level.
    A feature that moves with its flank needs the transient solver
    (:mod:`femgear.physics.ehl.transient`) and is refused here with the key that asks for it."""
    if roughness is None:
        return
    for key in ("peak", "synthetic"):
        if getattr(roughness, key) is not None and getattr(roughness, key).moving:
            raise SceneError(f"roughness.{key}.moving", "a steady point TEHL takes stationary roughness only "
                             "(set moving = false, or use femgear.physics.ehl.transient for a feature passing through)")
    g = levels[-1].grid
    feats = scene_features(roughness, R, a, extent=(float(g.x[0]), float(g.x[-1])), h=float(g.x[1] - g.x[0]))
    for lv in levels:
        total = sum(evaluate(f, lv.X, lv.Y) for f, _m, _mv in feats) if feats else None
        apply_surface(lv, total)
