"""Thermal EHL of a line contact (per unit length of the contact line), SI in and out.

Thermal loop outside the EHL Newton (Habchi 2008, thesis INSA Lyon; Habchi 2018, *Finite
Element Modeling of Elastohydrodynamic Lubrication Problems*, Wiley, ch. 5):

1. isothermal FE line EHL at the bulk temperature (:func:`femgear.ehl.solve_line`);
2. energy equation of film and solids with the current pressure, film and viscosities
   (:func:`femgear.tehl.energy.solve_energy`);
3. if the film temperatures moved less than ``tol`` [K]: done; else relax them, pass the
   film-mean temperature to the Reynolds viscosity and density
   (:class:`ThermalRheology`) and re-solve the EHL by Newton from the previous state.

Reduced form (documented): the Reynolds equation uses the viscosity at the cross-film
mean temperature (no Yang & Wen 1990 cross-film integrals F0, F1 — J. Tribol. 112:631);
the traction uses the cross-film harmonic-mean viscosity of the layer temperatures.
With ``heat=False`` the sources vanish, step 2 returns T ≡ T_b and the isothermal solution
is returned unchanged (exact recovery, tested).
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, field

import numpy as np

from femgear.errors import ConvergenceError
from femgear.ehl import params as pr
from femgear.ehl.dimensional import EHLOil, solve_line_dimensional
from femgear.ehl.level import Level
from femgear.ehl.newton import newton_dense
from femgear.ehl.rheology import ROELANDS_P0
from femgear.lubrication.oil import OilLaw
from femgear.tehl.energy import EnergyState, ThermalProps, jaeger_matrix, solve_energy
from femgear.tehl.loop import thermal_loop
from femgear.tehl.rheology import ThermalRheology

X0, X1 = -4.5, 1.5  # domain in units of the Hertz half-width (as femgear.ehl.solve_line)


@dataclass(frozen=True)
class TEHLResult:
    """Thermal line-contact solution (SI)."""

    hc: float                 #: central film [m]
    hmin: float               #: minimum film [m]
    pmax: float               #: maximum pressure [Pa]
    hc_isothermal: float      #: central film of the isothermal solve [m]
    dT_max: float             #: maximum film temperature rise [K]
    dT_surface: float         #: maximum surface (flash) temperature rise, both bodies [K]
    mu: float                 #: sliding friction coefficient |μ_couette| [-]
    mu_couette: float         #: ∫τ_c dx / w', signed like v2 − v1 [-]
    mu_poiseuille: float      #: ∫(h/2) p' dx / w' (rolling part) [-]
    heat: dict                #: heat flows [W/m] and the relative balance error
    iterations: int           #: thermal iterations
    newton_iterations: int
    seconds: float
    seconds_isothermal: float
    b: float                  #: Hertz half-width [m]
    ph: float                 #: Hertz pressure [Pa]
    x: np.ndarray = field(repr=False)          #: EHL nodes [m]
    p: np.ndarray = field(repr=False)          #: pressure [Pa]
    h: np.ndarray = field(repr=False)          #: film [m]
    x_cells: np.ndarray = field(repr=False)    #: thermal cell centres [m]
    T_film: np.ndarray = field(repr=False)     #: film temperatures (nt, nz) [K]
    T_surface1: np.ndarray = field(repr=False)
    T_surface2: np.ndarray = field(repr=False)
    tau: np.ndarray = field(repr=False)        #: Couette shear stress on the cells [Pa]


def ehl_oil_at(oil: OilLaw, T_bulk: float, compressible: bool = True) -> EHLOil:
    """The isothermal EHL oil equal to ``oil`` at temperature ``T_bulk`` (same Roelands z)."""
    eta_b = float(oil.viscosity(0.0, T_bulk))
    if oil.model == "roelands":
        z = oil.z0
        return EHLOil(eta0=eta_b, alpha=z * (math.log(eta_b) + 9.67) / ROELANDS_P0, viscosity="roelands",
                      z=z, compressible=compressible)
    return EHLOil(eta0=eta_b, alpha=oil.alpha, viscosity="barus", compressible=compressible)


def solve_tehl_line(w: float, R: float, ue: float, srr: float, T_bulk: float, oil: OilLaw, E_red: float,
                    props: ThermalProps, *, model: str = "eyring", tau0: float = 5e6, limiting_shear: float = 0.0,
                    level: int = 5, nz: int = 8, cells: int = 192, heat: bool = True, compressible: bool = True,
                    tol: float = 0.1, relax: float = 0.8, max_iter: int = 100, max_rise: float = 400.0,
                    max_step: float = 25.0, newton_tol: float = 1e-8, x0: float = X0) -> TEHLResult:
    """Thermal EHL line contact: load per length ``w`` [N/m], reduced radius ``R`` [m],
    entrainment speed ``ue`` = (v1 + v2)/2 [m/s], ``srr`` = (v1 − v2)/ue, bulk temperature [K].

    Numerics: ``level`` of the EHL grid (16·2^level cells on [``x0`` b, 1.5 b], x0 = −4.5 by
    default; a longer inlet, e.g. −8, avoids the inlet starvation of fast contacts), ``cells`` x
    ``nz`` thermal finite volumes on the same band, thermal loop to ``tol`` [K] (Anderson
    acceleration with damping ``relax``, :mod:`femgear.tehl.loop`) with at most ``max_step``
    [K] per iteration, Newton tolerance
    ``newton_tol`` per EHL re-solve.  ``heat=False`` switches all heat sources off.
    Raises :class:`ConvergenceError` when the isothermal start, the Newton solves or the
    thermal loop fail (or temperatures run away beyond ``max_rise``); never returns NaN.
    """
    for name, v in (("w", w), ("R", R), ("ue", ue), ("T_bulk", T_bulk), ("E_red", E_red)):
        if not (v > 0 and math.isfinite(v)):
            raise ValueError(f"{name} must be positive and finite (got {v!r})")
    if not math.isfinite(srr):
        raise ValueError("srr must be finite")
    case = f"tehl line w={w:.4g} R={R:.4g} ue={ue:.4g} srr={srr:.4g} T={T_bulk:.4g}"
    t0 = time.perf_counter()
    v1, v2 = ue * (1 + srr / 2), ue * (1 - srr / 2)
    ehl_oil = ehl_oil_at(oil, T_bulk, compressible)
    iso = solve_line_dimensional(w, R, ue, E_red, ehl_oil, level=level, x0=x0)
    t_iso = time.perf_counter() - t0
    res = iso.result
    b, ph = iso.a, iso.ph
    hs = b * b / R
    rheo = ThermalRheology(pr.line_alpha_bar(res.M, res.L), viscosity=ehl_oil.viscosity, ph=ph,
                           z=ehl_oil.roelands_z() if ehl_oil.viscosity == "roelands" else 0.68,
                           compressible=compressible, T_bulk=T_bulk, s0=oil.s0 if oil.model == "roelands" else 0.0,
                           beta_t=oil.beta_t, expansion=oil.expansion, T_ref=oil.T0)
    X = np.linspace(x0, X1, 16 * 2**level + 1)
    lv = Level(rheo, pr.line_lam_bar(res.M), pr.LINE_LOAD, x=X, ad_factor=1.0, sd_factor=1.0)
    xf = np.linspace(x0, X1, cells + 1) * b
    xc = 0.5 * (xf[:-1] + xf[1:])
    J1 = jaeger_matrix(cells, (X1 - x0) * b, props.B1, v1)
    J2 = jaeger_matrix(cells, (X1 - x0) * b, props.B2, v2)
    sol = {"PI": res.P[lv.interior].copy(), "H0": res.H0, "P": res.P, "H": res.H}
    reuse: dict = {}  # LU factors kept across the thermal re-solves (newton_dense)

    def energy(theta):
        st = solve_energy(xf, np.interp(xf, X * b, sol["P"] * ph), np.interp(xc, X * b, sol["H"] * hs), v1, v2,
                          T_bulk, theta, oil, props, J1, J2, model=model, tau0=tau0, limiting_shear=limiting_shear,
                          heat=heat)
        return st, st.theta

    def resolve(theta):
        T_nodes = T_bulk + np.interp(X * b, xc, theta.mean(axis=1))
        rheo.state["node"] = T_nodes
        rheo.state["quad"] = lv.reynolds.basis.interpolate(T_nodes)
        sol["PI"], sol["H0"], hist = newton_dense(lv, sol["PI"], sol["H0"], tol=newton_tol, case=case,
                                                  reuse=reuse)
        sol["P"], sol["H"] = lv.film(sol["PI"], sol["H0"])
        return len(hist.residual)

    st, theta, it, newton_its = thermal_loop(energy, resolve, np.zeros((cells, nz)), tol=tol, relax=relax,
                                             max_step=max_step, max_rise=max_rise, max_iter=max_iter, case=case)
    P, H = sol["P"], sol["H"]
    return _result(st, theta, iso, X, P, H, b, ph, hs, xf, xc, w, T_bulk, it, newton_its, t0, t_iso)


def _result(st: EnergyState, theta, iso, X, P, H, b, ph, hs, xf, xc, w, T_bulk, it, newton_its, t0, t_iso):
    dx = xf[1] - xf[0]
    mu_c = float(st.tau_couette.sum() * dx / w)
    mu_p = float(st.tau_poiseuille.sum() * dx / w)
    i0 = int(np.argmin(np.abs(X)))
    out = TEHLResult(
        hc=float(H[i0] * hs), hmin=float(H.min() * hs), pmax=float(P.max() * ph), hc_isothermal=iso.hc,
        dT_max=float(max(theta.max(), 0.0)), dT_surface=float(max(st.surface1.max(), st.surface2.max(), 0.0)),
        mu=abs(mu_c), mu_couette=mu_c, mu_poiseuille=mu_p, heat=st.heat, iterations=it,
        newton_iterations=newton_its, seconds=time.perf_counter() - t0, seconds_isothermal=t_iso, b=b, ph=ph,
        x=X * b, p=P * ph, h=H * hs, x_cells=xc, T_film=T_bulk + theta, T_surface1=T_bulk + st.surface1,
        T_surface2=T_bulk + st.surface2, tau=st.tau_couette)
    scalars = [out.hc, out.hmin, out.pmax, out.dT_max, out.mu, out.mu_poiseuille]
    if not all(math.isfinite(s) for s in scalars) or not np.all(np.isfinite(out.T_film)):
        raise ConvergenceError("tehl line", "non-finite result")
    return out
