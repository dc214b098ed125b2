"""Thermal EHL of a line contact (per unit length of the contact line), SI in and out.

Grids: the graded, nested grids of the isothermal FD solver (:mod:`femgear.physics.ehl.fd.line`),
whose level that solve picks for its tolerance; the thermal cells are the intervals of the same
nodes (the pressure at their faces, the film at their faces and centres), ``nz`` layers across
the film (:mod:`femgear.physics.tehl.energy`).

Thermal loop outside the EHL Newton (Habchi 2008, thesis INSA Lyon; Habchi 2018, *Finite Element
Modeling of Elastohydrodynamic Lubrication Problems*, Wiley, ch. 5), on each level:

1. the energy equation of film and solids with the current pressure, film and viscosities;
2. if the film temperatures moved less than ``thermal_tol`` [K]: done; else Anderson-accelerated
   relaxation (:mod:`femgear.physics.tehl.loop`), the film-mean temperature to the Reynolds
   viscosity and density (:class:`ThermalRheology`) and a Newton re-solve of the FD Reynolds
   equation from the previous state (its LU factors kept as GMRES preconditioner).

Nested iteration (Brandt 1977, Math. Comp. 31:333, applied to the thermal fixed point): the
loop runs on two levels below the isothermal solve's first (from the isothermal solution
injected there: the grids are nested), then on each finer level from the prolonged coarser state, the
layers across the film doubled with each level; the thermal films give the Richardson estimate of h_c
and h_min with their observed order (:data:`THERMAL_LEVELS`, :mod:`femgear.physics.ehl.core.accuracy`),
and when it exceeds ``tol`` the next finer level follows, up to ``max_level``.

Continuation (hot contacts, turbo speeds): when the loop fails on a level from the isothermal
state, the heat sources are switched on gradually (factor 1/4, 1/2, 1 of the viscous heating),
each stage starting from the last; a point that fails still raises with the temperature history.

Reynolds equation: ``reynolds="reduced"`` (the default where the surfaces move the same way) takes the
viscosity and density at the cross-film mean temperature; ``"generalised"`` the cross-film integrals of the
layer temperatures (Yang & Wen 1990, :mod:`femgear.physics.tehl.generalised`), which equal the reduced
equation for a film uniform across its thickness, and which the opposite-sliding solver
(:mod:`femgear.physics.tehl.opposite`, where |SRR| > 2) always uses: there the reduced equation has no
wedge.  (Measured with the generalised equation everywhere: the envelope benchmark's 54 of 60 points
converge as before, its median cost rises from 0.41 to 0.66 s and its largest to 5.0 s, the rolling films
rise by up to 6 % towards Gupta's factor; but the baseline's contact at 40 m/s, SRR 0.5 then heats into a
shear band 497 K hot where the reduced equation gives 134 K, which the energy solve's convection, the Couette
line plus a parabola rather than the generalised profile, may not represent: hence not the default.)
The traction uses the cross-film harmonic-mean viscosity of the layer temperatures; the convection is that
of the linear Couette profile plus the Poiseuille parabola carrying the rest of the Reynolds mass flux.  With ``heat=False`` the
sources vanish and the isothermal solution is returned unchanged (exact recovery, tested).
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, field, replace

import numpy as np

from femgear.errors import ConvergenceError
from femgear.physics.contact.film import moes_line
from femgear.physics.ehl.core import accuracy as acc
from femgear.physics.ehl.core import params as pr
from femgear.physics.ehl.core.rheology import ROELANDS_P0
from femgear.physics.ehl.dimensional import EHLOil
from femgear.physics.ehl.fd.line import (
    DEFAULT_TOL,
    MAX_LEVEL,
    NEWTON_TOL,
    LineProblem,
    _level_of,
    direction,
    solve_line_fd,
)
from femgear.physics.ehl.fd.line_grid import SPIKE_DENSITY, LineDomain
from femgear.physics.ehl.fe.newton import _newton
from femgear.physics.lubrication.oil import OilLaw
from femgear.physics.tehl import generalised as gf
from femgear.physics.tehl.energy import EnergyState, ThermalProps, _faces_of, solve_energy, surface_matrix
from femgear.physics.tehl.loop import ThermalRunaway, thermal_loop
from femgear.physics.tehl.rheology import ThermalRheology

#: thermal levels below and up to the isothermal solve's: three, so that the Richardson estimate of the thermal
#: films uses their observed order (clamped to 1..2; :func:`femgear.physics.ehl.core.accuracy.error_estimate`): the
#: minimum film of a hot contact converges at first order (1.5 GPa, 10 m/s, SRR 0.5, 240-260 K: h_min moves 4.1 and
#: 1.7 % per halving, while h_c moves 3.4 and 0.7 %), and the two-level estimate, which assumes second order,
#: would read it three times too small (when the coarsest thermal level is skipped, the two finer ones give the
#: estimate, order 2 assumed, rather than a third, costlier level above the isothermal one)
THERMAL_LEVELS = 3
DEFAULT_LAYERS = 16   #: layers across the film on the isothermal solve's level (and above) by default
MAX_LAYERS = 64       #: the most layers across the film a solve (or a path sequence) refines to
#: the accuracy of the film's peak temperature rise [K] a tolerance-driven solve refines for (its Richardson estimate
#: over the thermal levels, :func:`temperature_estimate`; issue 43: 2x refinement moves it by at most 1 K)
TEMPERATURE_TOL = 1.0
MIN_THERMAL_LEVEL = 2   #: the coarsest thermal level (65 nodes; where its loop does not settle, the hottest contacts, it is skipped)

#: the thermal cells are every THERMAL_STEP-th interval of the EHL grid (2: the nodes of the level below, a
#: quarter of the energy solve's cost; measured at 1.5 GPa, 10 m/s, SRR 0.5 the minimum film then converged to
#: 1 % only on 2049 nodes, against 513 with 1)
THERMAL_STEP = 1

#: the fractions of the film's temperature rise through which a hot contact that fails from the isothermal
#: state is continued (the fixed point θ = s G(θ), s up to 1)
CONTINUATION = (0.25, 0.5, 1.0)


@dataclass(frozen=True)
class TEHLResult:
    """Thermal line-contact solution (SI)."""

    hc: float                 #: central film [m]
    hmin: float               #: minimum film [m]
    pmax: float               #: maximum pressure [Pa]
    hc_isothermal: float      #: central film of the isothermal solve [m]
    dT_max: float             #: the film's peak temperature rise, its walls included (≥ ``dT_surface``, :func:`film_peaks`) [K]
    dT_surface: float         #: maximum surface (flash) temperature rise, both bodies [K]
    mu: float                 #: sliding friction coefficient |μ_couette| [-]
    mu_couette: float         #: ∫τ_c dx / w', signed like v2 − v1 [-]
    mu_poiseuille: float      #: ∫(h/2) p' dx / w' (rolling part) [-]
    heat: dict                #: heat flows [W/m] and the relative balance error
    iterations: int           #: thermal iterations (energy solves), all levels
    newton_iterations: int    #: Newton steps of the thermal re-solves, all levels
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
    hmin_isothermal: float = math.nan          #: minimum film of the isothermal solve [m]
    error_estimate: dict = field(default_factory=dict)  #: relative Richardson estimates of hc, hmin (thermal levels)
    levels: tuple = ()                         #: per thermal level: nodes, Hc, Hmin, mu, dT_max, dT_surface, iterations
    M: float = math.nan                        #: Moes load parameter at the bulk viscosity [-]
    L: float = math.nan                        #: Moes lubricant parameter at the bulk viscosity [-]
    nodes: int = 0                             #: EHL nodes of the finest level
    layers: int = 0                            #: layers across the film on the finest level
    isothermal_estimate: float | None = None   #: Richardson estimate of the isothermal start on its level [-]
    temperature_estimate: float | None = None  #: Richardson estimate of ``dT_max``'s error over the thermal levels [K]
    history: dict = field(default_factory=dict, repr=False)  #: temperature changes per level, continuation

    @property
    def thermal_ratio(self) -> float:
        """h_c / h_c,iso [-]."""
        return self.hc / self.hc_isothermal


def ehl_oil_at(oil: OilLaw, T_bulk: float, compressible: bool = True) -> EHLOil:
    """The isothermal EHL oil equal to ``oil`` at temperature ``T_bulk`` (same Roelands z)."""
    eta_b = float(oil.viscosity(0.0, T_bulk))
    if oil.model == "roelands":
        z = oil.z0
        return EHLOil(eta0=eta_b, alpha=z * (math.log(eta_b) + 9.67) / ROELANDS_P0, viscosity="roelands",
                      z=z, compressible=compressible)
    return EHLOil(eta0=eta_b, alpha=oil.alpha, viscosity="barus", compressible=compressible)


@dataclass(frozen=True)
class _Contact:
    """The dimensional set-up of one solve: Hertz scales, speeds, oil at the bulk temperature."""

    w: float
    R: float
    ue: float
    srr: float
    T_bulk: float
    E_red: float
    ehl_oil: EHLOil
    M: float
    L: float
    b: float
    ph: float
    flow: tuple | None = None   #: the surface speeds (v1, v2) [m/s] when ``ue`` is only the scaling speed

    @property
    def hs(self) -> float:
        return self.b * self.b / self.R

    @property
    def speeds(self) -> tuple[float, float]:
        if self.flow is not None:
            return self.flow
        return self.ue * (1 + self.srr / 2), self.ue * (1 - self.srr / 2)

    @classmethod
    def of(cls, w, R, ue, srr, T_bulk, oil: OilLaw, E_red: float, compressible: bool) -> _Contact:
        ehl_oil = ehl_oil_at(oil, T_bulk, compressible)
        Wl = w / (E_red * R)
        M, L = moes_line(Wl, ehl_oil.eta0 * ue / (E_red * R), ehl_oil.alpha * E_red)
        return cls(w, R, ue, srr, T_bulk, E_red, ehl_oil, float(M), float(L), R * math.sqrt(8.0 * Wl / math.pi),
                   E_red * math.sqrt(Wl / (2.0 * math.pi)))


def _rheology(c: _Contact, oil: OilLaw, compressible: bool):
    """The factory (M, frac) -> ThermalRheology of the Reynolds levels (temperature hook empty)."""
    z = c.ehl_oil.roelands_z() if c.ehl_oil.viscosity == "roelands" else 0.68

    def make(M_: float, frac: float) -> ThermalRheology:
        return ThermalRheology(pr.line_alpha_bar(M_, c.L) * frac, viscosity=c.ehl_oil.viscosity, ph=c.ph, z=z,
                               compressible=compressible, T_bulk=c.T_bulk,
                               s0=oil.s0 if oil.model == "roelands" else 0.0, beta_t=oil.beta_t,
                               expansion=oil.expansion, T_ref=oil.T0)
    return make


class _Level:
    """One thermal level: the FD Reynolds level with its own temperature field, the thermal cells and
    the solids' surface operators, and the current (P_I, H0)."""

    def __init__(self, prob: LineProblem, k: int, c: _Contact, props: ThermalProps, PI, H0, reuse: dict,
                 generalised=None):
        self.k, self.c, self.generalised = k, c, generalised
        self.lv = prob.level(k)
        self.lv.rheology = replace(self.lv.rheology, state={})
        self.PI, self.H0, self.reuse = PI, H0, reuse
        self.xf = self.lv.X[::THERMAL_STEP] * c.b
        self.xc = 0.5 * (self.xf[:-1] + self.xf[1:])
        self.energy_cache: dict = {}   # the energy system's factors, kept across the loop's solves
        v1, v2 = c.speeds
        self.J1 = surface_matrix(self.xf, v1, props.B1, props.k1)
        same = (v1, props.B1, props.k1) == (v2, props.B2, props.k2)   # pure rolling, one steel: one operator
        self.J2 = self.J1 if same else surface_matrix(self.xf, v2, props.B2, props.k2)

    def fields(self):
        P, H = self.lv.film(self.PI, self.H0)
        return P, H

    def thermal_film(self):
        """(p at the cell faces [Pa], h at the faces, h on the cells (the mean over the nodes in each) [m])."""
        P, H = self.fields()
        h = H * self.c.hs
        hf = h[::THERMAL_STEP]
        hc = (h[:-2:2] + 2.0 * h[1:-1:2] + h[2::2]) / 4.0 if THERMAL_STEP == 2 else 0.5 * (h[:-1] + h[1:])
        return P[::THERMAL_STEP] * self.c.ph, hf, hc

    def factors(self, theta: np.ndarray) -> dict:
        """The generalised Reynolds equation's nodal factors (:class:`ThermalRheology`) at the layer temperatures
        ``T_bulk + theta``: ε / ε_reduced and q_c / (ρ u_ref h), on the cells, linear between their centres."""
        oil, compressible = self.generalised
        c = self.c
        pf, _, h = self.thermal_film()
        p = 0.5 * (pf[:-1] + pf[1:])
        gen = gf.of_film(oil, p, h, c.T_bulk + theta, compressible)
        red = gf.reduced_of(oil, p, h, c.T_bulk + theta.mean(axis=1), compressible)
        X = self.lv.X * c.b
        wedge = gen.couette(*c.speeds) / (red.rho_h * c.ue)
        return {"eps_factor": np.interp(X, self.xc, gen.eps / red.eps), "wedge_factor": np.interp(X, self.xc, wedge)}

    def nodes_of(self, theta: np.ndarray) -> np.ndarray:
        """Film-mean temperature rise of the cells at the EHL nodes (linear between the cell centres)."""
        return np.interp(self.lv.X * self.c.b, self.xc, theta.mean(axis=1))

    def resolve(self, theta: np.ndarray, case: str) -> int:
        """Newton at the film-mean temperatures of ``theta`` (and, for the generalised equation, the factors of
        its layer temperatures); its iterations."""
        self.lv.rheology.state["node"] = self.c.T_bulk + self.nodes_of(theta)
        if self.generalised is not None:
            self.lv.rheology.state.update(self.factors(theta))
        self.PI, self.H0, hist = _newton(self.lv, self.PI, self.H0, direction(self.lv, self.reuse), 60, NEWTON_TOL,
                                         case)
        return len(hist.residual)


def _isothermal_start(c, factory, isothermal: dict | None, key: tuple, t0: float, *, min_level, **options):
    """(isothermal result, its Newton factors, its seconds) of contact ``c``: kept in ``isothermal`` under ``key``
    (:func:`solve_tehl_line`; the factors as the solve left them, 0 s) or solved (``options`` of
    :func:`solve_line_fd`) and kept there."""
    if isothermal is not None and key in isothermal:
        iso, kept = isothermal[key]
        return iso, dict(kept), 0.0
    reuse: dict = {}
    ehl = c.ehl_oil
    iso = solve_line_fd(c.M, c.L, viscosity=ehl.viscosity, **({} if min_level is None else {"min_level": min_level}),
                        ph=c.ph, z=ehl.roelands_z() if ehl.viscosity == "roelands" else 0.68, reuse=reuse,
                        rheology_factory=factory, **options)
    if isothermal is not None:
        isothermal[key] = (iso, dict(reuse))
    return iso, reuse, time.perf_counter() - t0


def solve_tehl_line(w: float, R: float, ue: float, srr: float, T_bulk: float, oil: OilLaw, E_red: float,
                    props: ThermalProps, *, model: str = "eyring", tau0: float = 5e6, limiting_shear: float = 0.0,
                    tol: float = DEFAULT_TOL, level: int | None = None, min_level: int | None = None,
                    max_level: int = MAX_LEVEL, nz: int = DEFAULT_LAYERS,
                    heat: bool = True, compressible: bool = True, thermal_tol: float = 0.1, relax: float = 0.8,
                    max_iter: int = 100, max_rise: float = 400.0, max_step: float = 25.0,
                    x0: float | None = None, estimate: bool = True, reynolds: str = "reduced",
                    spike: bool = False, spike_density: float = SPIKE_DENSITY, isothermal: dict | None = None,
                    temperature_tol: float = TEMPERATURE_TOL) -> TEHLResult:
    """Thermal EHL line contact: load per length ``w`` [N/m], reduced radius ``R`` [m], entrainment speed
    ``ue`` = (v1 + v2)/2 [m/s], ``srr`` = (v1 − v2)/ue, bulk temperature ``T_bulk`` [K].

    ``tol``: the relative accuracy of h_c and h_min (the isothermal solve picks its level for it, at least
    ``min_level``, the thermal levels are refined until their own Richardson estimate meets it, up to
    ``max_level``), and ``temperature_tol`` [K] that of the film's peak temperature rise: where either estimate
    misses and the isothermal start met ``tol`` on its level, the thermal levels are solved again with twice the
    ``nz`` layers across the film (up to :data:`MAX_LAYERS`), else on the next finer level; ``level``: the finest
    level instead (no refinement, ``nz`` kept).  Thermal loop to ``thermal_tol`` [K] with
    damping ``relax`` and at most ``max_step`` [K] per iteration; ``x0`` the inlet [b] (default: sized by
    the isothermal solver).  ``heat=False`` switches the heat sources off.  ``estimate=False``: the thermal
    loop on the isothermal solve's level only, no thermal error estimate (the points of a friction map, whose
    level the heaviest corner's estimated solve fixed).  ``reynolds``: "reduced" or "generalised" (module
    docstring).  ``spike``: grids that resolve the outlet pressure spike (the path sequences, whose peak pressure
    and film temperature are then smooth along the path; :func:`solve_line_fd`), its bump of amplitude
    ``spike_density``.  ``isothermal``: a dict
    the caller keeps across the solves of one set-up (oil, modulus, options), where the isothermal start of each
    contact is kept by its load, radius, entrainment, bulk temperature and grid options, so that the contacts that
    differ only in SRR (the points of a friction map) solve it once (``seconds_isothermal`` is then 0); with
    ``estimate=False`` it also keeps the converged thermal state of the latest such contact, from which the next
    one's loop starts (continuation in SRR: the neighbouring SRR's temperatures are far closer than the isothermal
    film's, a map's turbo contact converges in fewer iterations; the answer is the same fixed point to
    ``thermal_tol``; a warm start that fails is retried from the isothermal state, said in ``history``).  Surfaces moving in opposite directions (|``srr``| > 2, down to
    zero entrainment): :func:`femgear.physics.tehl.opposite.solve_tehl_opposite`, which carries the thermal wedge
    this reduced, single-direction solve lacks.  Raises
    :class:`ConvergenceError` with the history when the isothermal start, a Newton solve or the thermal
    loop fails (or temperatures run away beyond ``max_rise``); never returns NaN."""
    for name, v in (("w", w), ("R", R), ("ue", ue), ("T_bulk", T_bulk), ("E_red", E_red)):
        if not (v > 0 and math.isfinite(v)):
            raise ValueError(f"{name} must be positive and finite (got {v!r})")
    if not math.isfinite(srr):
        raise ValueError("srr must be finite")
    case = f"tehl line w={w:.4g} R={R:.4g} ue={ue:.4g} srr={srr:.4g} T={T_bulk:.4g}"
    t0 = time.perf_counter()
    c = _Contact.of(w, R, ue, srr, T_bulk, oil, E_red, compressible)
    factory = _rheology(c, oil, compressible)
    key = (w, R, ue, T_bulk, tol, level, min_level, max_level, x0, compressible, spike, spike_density)
    iso, reuse, t_iso = _isothermal_start(c, factory, isothermal, key, t0, tol=tol, level=level, max_level=max_level,
                                          x0=x0, min_level=min_level, compressible=compressible, spike=spike,
                                          spike_density=spike_density)
    start = isothermal.get(("thermal", key, heat, reynolds)) if isothermal is not None and not estimate else None
    prob = LineProblem(c.M, c.L, _domain_of(iso), {}, rheology_factory=factory)
    top = _level_of(iso)
    ks = [max(top - THERMAL_LEVELS + 1, MIN_THERMAL_LEVEL) if estimate else top, top]
    opts = dict(model=model, tau0=tau0, limiting_shear=limiting_shear, heat=heat)
    loop = dict(thermal_tol=thermal_tol, relax=relax, max_iter=max_iter, max_rise=max_rise, max_step=max_step)
    if reynolds not in ("generalised", "reduced"):
        raise ValueError(f"reynolds must be 'generalised' or 'reduced' (got {reynolds!r})")
    def fresh(layers: int = nz, before: _Run | None = None):
        r = _Run(prob, c, oil, props, opts, loop, layers, dict(reuse), case, (top, iso.P[1:-1], float(iso.H0)),
                 (oil, compressible) if reynolds == "generalised" else None)
        if before is not None:   # the same solve with more layers: its history and iteration counts go on
            r.history, r.its, r.newton_its = before.history, before.its, before.newton_its
        return r

    warm_failed = None
    if start is not None:
        run = fresh()
        try:
            state = run.level(top, start[1:], warm=True)
        except ConvergenceError as exc:   # runaway included: the cold start below decides
            warm_failed = f"warm start from SRR {start[0]:.4g} failed, solved from the isothermal state: {str(exc)[:160]}"
        else:
            run.history["warm_start"] = {"srr": start[0], "iterations": run.its}
            isothermal[("thermal", key, heat, reynolds)] = (srr, *state)
            return run.result(iso, t0, t_iso, {"Hc": None, "Hmin": None})
    run = fresh()
    if warm_failed:
        run.history["continuation"].append({"level": top, "reason": warm_failed})
    run, state, est, t_est = _thermal_levels(run, fresh, iso, prob, ks, level=level, max_level=max_level, tol=tol,
                                             temperature_tol=temperature_tol, thermal_tol=thermal_tol,
                                             estimate=estimate)
    if isothermal is not None and not estimate:
        isothermal[("thermal", key, heat, reynolds)] = (srr, *state)
    return run.result(iso, t0, t_iso, est, t_est)


def _thermal_levels(run: _Run, fresh, iso, prob, ks: list[int], *, level, max_level: int, tol: float,
                    temperature_tol: float, thermal_tol: float, estimate: bool):
    """The nested thermal levels of :func:`solve_tehl_line` from ``ks[0]`` up to the isothermal solve's level
    ``ks[-1]`` and on, refined until the estimates meet ``tol`` and ``temperature_tol`` (:func:`_refinement`;
    ``fresh(layers, run)``: the same solve anew with other layers); returns the run, its state, the films' and the
    peak rise's estimates."""
    top = ks[-1]
    state = _inject(iso, prob, ks[0])
    k = ks[0]
    t_est = z_change = before = None
    while True:
        try:
            state = run.level(k, state)
        except ThermalRunaway:
            raise
        except ConvergenceError:
            if k >= top or run.summaries:  # only the coarsest thermal level may fail: the next one starts afresh
                raise
            run.history["continuation"].append({"level": k, "reason": "skipped: the loop did not settle"})
            state = _inject(iso, prob, k + 1)
        if run.summaries and run.summaries[-1]["dT_max"] < thermal_tol and k < top:
            # no heating to speak of: the isothermal solution on its own level is the answer (one energy solve)
            k, state = top, _inject(iso, prob, top)
            run.level(k, state)
            est, t_est = dict(iso.error_estimate), 0.0
            break
        est = acc.error_estimate(run.summaries) if estimate else {"Hc": None, "Hmin": None}
        if not estimate:
            break
        t_est, t_asymptotic = temperature_estimate(run.summaries)
        skipped = any("skipped" in c["reason"] for c in run.history["continuation"])
        enough = len(run.summaries) >= THERMAL_LEVELS or level is not None or (skipped and len(run.summaries) >= 2)
        h_miss = not all(e is not None and e <= tol for e in est.values())
        if before is not None and k == before[0]:   # the level of the last doubling: what it moved
            z_change = _moved(before[1], run.summaries[-1])
        # the peak rise counts where its levels converge (an outlet spike that the plain grid does not resolve
        # moves the peak from level to level, and no refinement along x catches it: its estimate is reported)
        t_miss = t_est is not None and t_est > temperature_tol and t_asymptotic
        if (level is not None and k >= top) or (k >= top and enough and not (h_miss or t_miss)):
            break
        if k >= top and enough and level is None:
            step = _refinement(h_miss, t_miss, run.nz < MAX_LAYERS and _resolved_along(iso, tol), z_change, tol,
                               temperature_tol, k < max_level and (h_miss or k <= top))
            if step is None:
                break
            if step == "layers":
                # the excess lies across the film (the isothermal film is resolved on this level), which only more
                # layers reduce: the thermal levels again, with twice the layers
                run.history["continuation"].append({"level": k, "reason": (
                    f"{2 * run.nz} layers: estimates h {_fmt(est)}, peak rise {t_est:.3g} K on {run.nz}")})
                before = (k, run.summaries[-1])
                run = fresh(2 * run.nz, run)
                k, state = ks[0], _inject(iso, prob, ks[0])
                continue
        elif k >= max_level:
            break
        k += 1
    return run, state, est, t_est


def temperature_estimate(summaries: list[dict]) -> tuple[float | None, bool]:
    """Richardson estimate [K] of the film's peak temperature rise on the last of the thermal levels' ``summaries``
    (:func:`femgear.physics.ehl.core.accuracy.consecutive_levels`, :func:`~femgear.physics.ehl.core.accuracy.richardson`;
    None with one), and
    whether the levels are in the asymptotic range: three or more, the last two changes of one sign and the last at
    most half the one before (observed order ≥ 1)."""
    v = [s["dT_max"] for s in acc.consecutive_levels(summaries)]
    e = acc.richardson(v)
    d = np.diff(v)
    asymptotic = d.size >= 2 and d[-1] * d[-2] >= 0.0 and abs(d[-1]) <= 0.5 * abs(d[-2])
    return (None if e is None else e * abs(v[-1])), bool(asymptotic)


def _refinement(h_miss: bool, t_miss: bool, layers_ok: bool, z_change: dict | None, tol: float,
                temperature_tol: float, finer_ok: bool) -> str | None:
    """The next refinement of a solve that missed a tolerance (``h_miss``: a film's, ``t_miss``: the peak rise's):
    "layers" (twice the layers, where ``layers_ok``: the isothermal film is resolved and fewer than
    :data:`MAX_LAYERS`) first, and again while the last doubling moved a quantity that misses by more than half its
    tolerance (``z_change``: :func:`_moved`, None before any doubling): there the error lies across the film; else
    "level" (one finer along x, where ``finer_ok``: below the finest level, and for the peak alone at most one above
    the isothermal solve's); None: stop there."""
    if layers_ok and (z_change is None or (h_miss and z_change["h"] > 0.5 * tol)
                      or (t_miss and z_change["dT_max"] > 0.5 * temperature_tol)):
        return "layers"
    return "level" if finer_ok else None


def _moved(a: dict, b: dict) -> dict:
    """What a doubling of the layers moved between the level summaries ``a`` and ``b``: the films (relative, the
    larger of h_c and h_min) and the peak rise [K]."""
    return {"h": max(abs(b[q] / a[q] - 1.0) for q in ("Hc", "Hmin")), "dT_max": abs(b["dT_max"] - a["dT_max"])}


def _resolved_along(iso, tol: float) -> bool:
    """Whether the isothermal start met ``tol`` on its level (its films resolved along the contact)."""
    e = [v for v in iso.error_estimate.values() if v is not None]
    return bool(e) and max(e) <= tol


def _fmt(est: dict) -> str:
    return ", ".join("none" if v is None else f"{v:.2%}" for v in est.values())


def peak(values: np.ndarray, x: np.ndarray) -> float:
    """The largest value of a field given at the cell centres ``x`` (≥ 0): the vertex of the parabola through the
    largest cell value and its neighbours, never below that value.  The film's hottest point sits on the outlet
    pressure spike, which moves across the cells from one path position to the next; the cell maximum then steps
    along the path (up to 17 % of the peak between neighbouring positions of the baseline's path), the vertex far
    less."""
    i = int(np.argmax(values))
    top = float(max(values[i], 0.0))
    if 0 < i < values.size - 1:
        xs = x[i - 1:i + 2] - x[i]
        a, b, c0 = np.polyfit(xs, values[i - 1:i + 2], 2)
        if a < 0:
            top = max(top, float(c0 - b * b / (4.0 * a)))
    return top


def film_peaks(theta: np.ndarray, surface1: np.ndarray, surface2: np.ndarray, x: np.ndarray) -> dict:
    """The film's peak temperature rise ``dT_max``, over the film with its two walls, and the surfaces' (flash) peak
    ``dT_surface`` [K], each read at the :func:`peak` vertex, from the layer temperatures ``theta`` (cells x layers)
    and the two surface temperature rises on the cells ``x``.  The one film peak every summary reports (the
    result's and each thermal level's): a surface hotter than every layer centre (heat flowing back into the film
    near the outlet) bounds the film too, so ``dT_max >= dT_surface`` always holds."""
    surface = max(peak(surface1, x), peak(surface2, x))
    film = max(peak(np.maximum(theta.max(axis=1), np.maximum(surface1, surface2)), x), surface)
    return {"dT_max": film, "dT_surface": surface}


def _regrid(theta: np.ndarray, xc0: np.ndarray, xc: np.ndarray, nz: int) -> np.ndarray:
    """The film temperatures (cells ``xc0`` x layers) linearly interpolated to the cells ``xc`` and ``nz`` layers
    (along the layer centres ζ in (0, 1))."""
    along = np.stack([np.interp(xc, xc0, col) for col in theta.T], axis=1)
    z0 = (np.arange(theta.shape[1]) + 0.5) / theta.shape[1]
    z = (np.arange(nz) + 0.5) / nz
    return np.stack([np.interp(z, z0, row) for row in along], axis=0)


def _domain_of(iso) -> LineDomain:
    """The grids of the isothermal solve (its domain and grading)."""
    return LineDomain(*(float(v) for v in iso.history["domain"]))


def _inject(iso, prob: LineProblem, k: int):
    """(PI, H0, theta=None) on level ``k`` from the isothermal result (nested grids: every other node)."""
    X = prob.dom.nodes(k)
    step = (iso.x.size - 1) // (X.size - 1)
    P = iso.P[::step]
    return P[1:-1].copy(), float(iso.H0), None


class _Run:
    """The thermal levels of one solve: the loop on each, summaries, history."""

    def __init__(self, prob, c: _Contact, oil, props, opts, loop, nz, reuse, case, iso: tuple, generalised=None):
        self.prob, self.c, self.oil, self.props, self.opts, self.loop = prob, c, oil, props, opts, loop
        self.generalised = generalised   # (oil, compressible) of the generalised Reynolds equation, or None
        self.iso = iso     # (level, PI, H0) of the isothermal solution
        self.nz, self.reuse, self.case = nz, reuse, case
        self.summaries: list[dict] = []
        self.history: dict = {"temperature_change": [], "continuation": []}
        self.its = self.newton_its = 0
        self.last = None

    def energy(self, lv: _Level, scale: float = 1.0):
        c = self.c
        v1, v2 = c.speeds

        def run(theta):
            pf, hf, hc = lv.thermal_film()
            m = None
            if self.generalised is not None:
                T_faces = c.T_bulk + np.stack([_faces_of(col) for col in theta.T], axis=1)
                m = gf.mass_flux(lv.xf, pf, hf, T_faces, self.oil, v1, v2)
            st = solve_energy(lv.xf, pf, hc, v1, v2, c.T_bulk, theta, self.oil, self.props, lv.J1, lv.J2,
                              h_faces=hf, mass_flux=m, cache=lv.energy_cache, **self.opts)
            if scale != 1.0:   # continuation in the heating: the same field, a fraction of its rise
                st = replace(st, theta=scale * st.theta)
            return st, st.theta
        return run

    def level(self, k: int, state, warm: bool = False):
        """Solve the thermal loop on level ``k`` from ``state`` = (PI, H0, theta | None) of the level below
        (or injected from the isothermal solution); returns the state here.  On the isothermal solve's own
        level a cold start is that solution itself (exact: with the heat off the loop returns it untouched);
        any other start is re-solved at least once.  ``warm``: ``state`` is the converged state on this level of a
        contact that differs only in SRR, whose pressure and film then solve this contact's reduced Reynolds
        equation at its temperatures too (the equation sees the speeds only through u_e; the generalised one
        sees them all: re-solved first); it fails rather than falling back to the heating's continuation."""
        PI, H0, theta = state
        if self.last is not None and self.last.k == k - 1 and PI.size == self.last.lv.n - 2:
            X = self.prob.dom.nodes(k)
            PI = np.interp(X, self.last.lv.X, self.last.lv.full(PI))[1:-1]
            if theta is not None:
                Xt = X[::THERMAL_STEP]
                theta = _regrid(theta, self.last.xc, 0.5 * (Xt[:-1] + Xt[1:]) * self.c.b, self.layers(k))
        exact = k == self.iso[0] and (theta is None or not np.any(theta))
        if exact:
            PI, H0 = self.iso[1].copy(), self.iso[2]
        lv = _Level(self.prob, k, self.c, self.props, PI.copy(), H0, self.reuse, self.generalised)
        nt = lv.xf.size - 1
        theta = np.zeros((nt, self.layers(k))) if theta is None else theta
        cold = not np.any(theta) and not warm
        try:
            st, theta = self._loop(lv, theta, 1.0, solved=exact or (warm and self.generalised is None))
        except ThermalRunaway:
            raise
        except ConvergenceError as exc:
            if not cold:
                raise
            self.history["continuation"].append({"level": k, "reason": str(exc)[:200]})
            lv = _Level(self.prob, k, self.c, self.props, PI.copy(), H0, self.reuse, self.generalised)
            theta = np.zeros((nt, self.layers(k)))
            for scale in CONTINUATION:
                st, theta = self._loop(lv, theta, scale, solved=False)
        self.last = lv
        self._summary(lv, st, theta)
        self.st, self.theta = st, theta
        return lv.PI, lv.H0, theta

    def layers(self, k: int) -> int:
        """Layers across the film on level ``k``: ``nz`` on the isothermal solve's level and above, halved per level
        below, so that the thermal levels up to the isothermal one refine the film across and along together and
        their Richardson estimate covers both (the cross-film error is as large as the one along it: at 60 m/s,
        0.8 GPa, h_c moves 4 % from 8 to 32 layers, 0.7 % from 16 to 32).  A level beyond the isothermal one keeps
        ``nz`` layers (doubling them would double the dense solids' share of the energy system: 4.4 s to factorise
        1024 x 32 cells of a slow, heavy contact), so the cross-film error of 16 layers is not in the estimate of such
        a level: a path sequence whose estimate the layers hold above the tolerance doubles ``nz`` instead
        (:func:`femgear.physics.tehl.solver._finer`)."""
        return max(4, int(round(self.nz * 2.0 ** min(k - self.iso[0], 0))))

    def _loop(self, lv: _Level, theta, scale: float, solved: bool):
        L = self.loop
        st, theta, it, n_its = thermal_loop(
            self.energy(lv, scale), lambda th: lv.resolve(th, self.case), theta, tol=L["thermal_tol"],
            relax=L["relax"], max_step=L["max_step"], max_rise=L["max_rise"], max_iter=L["max_iter"],
            case=self.case, solved=solved, growth=1.1, history=self.history["temperature_change"], bulk=self.c.T_bulk)
        self.its, self.newton_its = self.its + it, self.newton_its + n_its
        return st, theta

    def _summary(self, lv: _Level, st: EnergyState, theta) -> None:
        c = self.c
        P, H = lv.fields()
        i0 = int(np.argmin(np.abs(lv.lv.X)))
        dx = np.diff(lv.xf)
        self.summaries.append({"nodes": lv.lv.n, "Hc": float(H[i0] * c.hs), "Hmin": float(H.min() * c.hs),
                               "mu": float(abs(st.tau_couette @ dx) / c.w),
                               **film_peaks(theta, st.surface1, st.surface2, lv.xc), "iterations": self.its})

    def result(self, iso, t0: float, t_iso: float, est, t_est: float | None = None) -> TEHLResult:
        c, lv, st, theta = self.c, self.last, self.st, self.theta
        P, H = lv.fields()
        X = lv.lv.X
        xf = lv.xf
        dx = np.diff(xf)
        mu_c = float(st.tau_couette @ dx / c.w)
        mu_p = float(st.tau_poiseuille @ dx / c.w)
        i0 = int(np.argmin(np.abs(X)))
        hs = c.hs
        peaks = film_peaks(theta, st.surface1, st.surface2, lv.xc)
        out = TEHLResult(
            hc=float(H[i0] * hs), hmin=float(H.min() * hs), pmax=float(P.max() * c.ph), hc_isothermal=float(iso.Hc_hertz * hs),
            dT_max=peaks["dT_max"], dT_surface=peaks["dT_surface"],
            mu=abs(mu_c), mu_couette=mu_c, mu_poiseuille=mu_p, heat=st.heat, iterations=self.its,
            newton_iterations=self.newton_its, seconds=time.perf_counter() - t0, seconds_isothermal=t_iso, b=c.b,
            ph=c.ph, x=X * c.b, p=P * c.ph, h=H * hs, x_cells=lv.xc, T_film=c.T_bulk + theta,
            T_surface1=c.T_bulk + st.surface1, T_surface2=c.T_bulk + st.surface2, tau=st.tau_couette,
            hmin_isothermal=float(iso.Hmin_hertz * hs), error_estimate={"hc": est["Hc"], "hmin": est["Hmin"]},
            levels=tuple(self.summaries), M=c.M, L=c.L, nodes=lv.lv.n, layers=theta.shape[1],
            isothermal_estimate=max((e for e in iso.error_estimate.values() if e is not None), default=None),
            temperature_estimate=t_est,
            history={**self.history, **({"spike": iso.history["spike"]} if "spike" in iso.history else {})})
        scalars = [out.hc, out.hmin, out.pmax, out.dT_max, out.mu, out.mu_poiseuille]
        if not all(math.isfinite(s) for s in scalars) or not np.all(np.isfinite(out.T_film)):
            raise ConvergenceError("tehl line", "non-finite result", self.history)
        return out
