"""Thermal EHL of a line contact (per unit length of the contact line), SI in and out.

Thermal loop outside the EHL Newton (Habchi 2008, thesis INSA Lyon; Habchi 2018, *Finite
Element Modeling of Elastohydrodynamic Lubrication Problems*, Wiley, ch. 5):

1. isothermal FE line EHL at the bulk temperature (:func:`femgear.physics.ehl.fe.line.solve_line`);
2. energy equation of film and solids with the current pressure, film and viscosities
   (:func:`femgear.physics.tehl.energy.solve_energy`);
3. if the film temperatures moved less than ``tol`` [K]: done; else relax them, pass the
   film-mean temperature to the Reynolds viscosity and density
   (:class:`ThermalRheology`) and re-solve the EHL by Newton from the previous state.

Nested iteration (the coarse-to-fine idea of full multigrid, Brandt 1977, Math. Comp. 31
333, applied to the thermal fixed point): from level ``NESTED_MIN_LEVEL`` on, steps 2-3
first run on the next coarser EHL grid (the isothermal solution injected there) with half
the thermal cells and Newton to ``coarse_newton_tol``, to ``coarse_tol`` = 2 K only (the
coarse and fine temperatures differ by 3-6 K anyway in the cells of the pressure spike,
where compression heating peaks, on the baseline contact at SRR 0-1); the fine loop then
starts from those temperatures (interpolated) and from the prolonged coarse pressure or
the isothermal fine pressure plus the prolonged coarse correction, whichever has the
smaller Reynolds residual, and it stops only on a fine state re-solved at its
temperatures, with the same ``tol`` as a loop on the fine grid alone: the converged
answers agree with that loop's to the thermal tolerance (tested).  The Newton LU factors
of the isothermal start are kept for the re-solves (``reuse=`` of
:func:`femgear.physics.ehl.fe.line.solve_line`).  If the coarse stage fails, the loop is run on the fine
grid alone.

Hot contacts (``hot_stage``): when the first energy solve on the grid two levels down (the
isothermal film, a quarter of the thermal cells) raises the film by more than
``max_step``, the nested iteration starts there (three stages), and the isothermal Newton
LU factors are dropped (with the viscosities 2-3x lower they precondition GMRES so poorly
that the first step of each stage failed after DENSE_REUSE_KRYLOV iterations and
refactorised anyway).  Measured on the baseline contact at level 5: at SRR 1 the
level-4 stage then needs one EHL re-solve (4 Newton steps) instead of three (19 steps,
the first of 11 damped ones); at SRR 0 and 0.3 (rise 1-8 K) nothing changes but the
probe's energy solve on 48 cells.  Inside each stage the thermal loop does not take a
secant (Anderson) pair from the energy solve on the predicted, not re-solved, fine state
(:func:`femgear.physics.tehl.loop.thermal_loop`), and it drops its history only when the change
grows by more than 10 % (``growth``); measured: SRR 0.3 needs two fine re-solves instead
of three, SRR 1 stays at three (its second change, 0.50 -> 0.51 K, had halved the damping).

Reduced form (documented): the Reynolds equation uses the viscosity at the cross-film
mean temperature (no Yang & Wen 1990 cross-film integrals F0, F1 — J. Tribol. 112:631);
the traction uses the cross-film harmonic-mean viscosity of the layer temperatures.
With ``heat=False`` the sources vanish, step 2 returns T ≡ T_b and the isothermal solution
is returned unchanged (exact recovery, tested).
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, field, replace

import numpy as np

from femgear.errors import ConvergenceError
from femgear.physics.ehl.core import params as pr
from femgear.physics.ehl.core.rheology import ROELANDS_P0
from femgear.physics.ehl.dimensional import EHLOil, solve_line_dimensional
from femgear.physics.ehl.fe.level import Level
from femgear.physics.ehl.fe.newton import newton_dense
from femgear.physics.lubrication.oil import OilLaw
from femgear.physics.tehl.energy import EnergyState, ThermalProps, jaeger_matrix, solve_energy
from femgear.physics.tehl.loop import thermal_loop
from femgear.physics.tehl.rheology import ThermalRheology

X0, X1 = -4.5, 1.5  # domain in units of the Hertz half-width (as femgear.physics.ehl.fe.line.solve_line)
# the thermal loop starts on the next coarser grid from this level on (measured: at level 4 the
# coarse stage on 129 nodes costs more than it saves, at levels 5 and 6 it halves the cost)
NESTED_MIN_LEVEL = 5


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
    iterations: int           #: thermal iterations (energy solves), the coarse stage included
    newton_iterations: int    #: Newton steps of the thermal re-solves, both grids
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
                    max_step: float = 25.0, newton_tol: float = 1e-8, x0: float = X0, coarse: bool = True,
                    coarse_newton_tol: float = 1e-5, coarse_cells: int = 2, fine_relax: float = 1.0,
                    coarse_tol: float = 2.0, hot_stage: bool = True, growth: float = 1.1) -> TEHLResult:
    """Thermal EHL line contact: load per length ``w`` [N/m], reduced radius ``R`` [m],
    entrainment speed ``ue`` = (v1 + v2)/2 [m/s], ``srr`` = (v1 − v2)/ue, bulk temperature [K].

    Numerics: ``level`` of the EHL grid (16·2^level cells on [``x0`` b, 1.5 b], x0 = −4.5 by
    default; a longer inlet, e.g. −8, avoids the inlet starvation of fast contacts), ``cells`` x
    ``nz`` thermal finite volumes on the same band, thermal loop to ``tol`` [K] (Anderson
    acceleration with damping ``relax``, :mod:`femgear.physics.tehl.loop`, history dropped when the
    change grows by more than ``growth`` x) with at most ``max_step`` [K] per iteration, Newton
    tolerance ``newton_tol`` per EHL re-solve.  ``heat=False`` switches all heat sources off.
    ``coarse`` (default on from level ``NESTED_MIN_LEVEL``): nested iteration from the next
    coarser grid (``cells // coarse_cells`` thermal cells, Newton to ``coarse_newton_tol``,
    temperatures to ``coarse_tol`` [K], the fine loop started with damping ``fine_relax``;
    ``hot_stage``: a third stage two grids down for hot contacts), see the module text.
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
    reuse: dict = {}  # LU factors (Reynolds per level, energy) kept from the isothermal start on
    iso = solve_line_dimensional(w, R, ue, E_red, ehl_oil, level=level, x0=x0, reuse=reuse)
    t_iso = time.perf_counter() - t0
    res = iso.result
    b, ph = iso.a, iso.ph
    hs = b * b / R
    rheo = _thermal_rheology(res, ehl_oil, oil, ph, compressible, T_bulk)
    lengths = (X1 - x0) * b

    def cells_of(nt):  # thermal finite-volume band: faces, centres, Jaeger operators
        xf = np.linspace(x0, X1, nt + 1) * b
        return xf, 0.5 * (xf[:-1] + xf[1:]), jaeger_matrix(nt, lengths, props.B1, v1), jaeger_matrix(
            nt, lengths, props.B2, v2)

    first: dict = {}  # a stage's first energy solve (θ = 0) done already, to decide on the stages
    def energy(film, grid):
        xf, xc, J1, J2 = grid

        def run(theta):
            if film in first and not np.any(theta):
                return first.pop(film)
            st = solve_energy(xf, np.interp(xf, film.X * b, film.P * ph), np.interp(xc, film.X * b, film.H * hs), v1,
                              v2, T_bulk, theta, oil, props, J1, J2, model=model, tau0=tau0,
                              limiting_shear=limiting_shear, heat=heat)
            return st, st.theta
        return run

    def resolve(film, xc, tol_n):
        return lambda theta: film.resolve(T_bulk + np.interp(film.X * b, xc, theta.mean(axis=1)), tol_n, reuse, case)

    def run_stages(stages):
        theta, its, newton_its = np.zeros((stages[0][1][1].size, nz)), 0, 0
        for k, (film, grid) in enumerate(stages):
            cold = not np.any(theta)  # heat off: the fine isothermal start is the answer, untouched
            if k > 0 and not cold:
                xc0 = stages[k - 1][1][1]
                theta = np.stack([np.interp(grid[1], xc0, col) for col in theta.T], axis=1)
                film.correct(stages[k - 1][0], T_bulk + np.interp(film.X * b, grid[1], theta.mean(axis=1)))
            elif k > 0:
                theta = np.zeros((grid[1].size, nz))
            fine = k == len(stages) - 1
            st, theta, it, n_its = thermal_loop(
                energy(film, grid), resolve(film, grid[1], newton_tol if fine else coarse_newton_tol), theta,
                tol=tol if fine else max(tol, coarse_tol),
                relax=relax if k == 0 else fine_relax, max_step=max_step, max_rise=max_rise, max_iter=max_iter,
                case=case, solved=k == 0 or cold, growth=growth)
            its, newton_its = its + it, newton_its + n_its
        return st, theta, its, newton_its

    stages = [(level - 1, max(cells // coarse_cells, 8))] if coarse and level >= NESTED_MIN_LEVEL else []
    stages = [(_Film(rheo, res, level, k, x0), cells_of(nt)) for k, nt in stages + [(level, cells)]]
    if hot_stage and len(stages) > 1 and heat:  # a hot contact: a third, coarser stage first
        probe = (_Film(rheo, res, level, level - 2, x0), cells_of(max(cells // coarse_cells**2, 8)))
        first[probe[0]] = energy(*probe)(np.zeros((probe[1][1].size, nz)))
        if float(np.max(np.abs(first[probe[0]][1]))) > max_step:
            stages.insert(0, probe)
            reuse.clear()  # the isothermal LU factors: no preconditioner for a film this hot

    try:
        st, theta, its, newton_its = run_stages(stages)
    except ConvergenceError:
        if len(stages) == 1:
            raise
        stages = [(_Film(rheo, res, level, level, x0), stages[-1][1])]
        st, theta, its, newton_its = run_stages(stages)
    xf, xc = stages[-1][1][:2]
    film = stages[-1][0]
    return _result(st, theta, iso, film.X, film.P, film.H, b, ph, hs, xf, xc, w, T_bulk, its, newton_its, t0, t_iso)


def _thermal_rheology(res, ehl_oil: EHLOil, oil: OilLaw, ph: float, compressible: bool, T_bulk: float):
    """The Reynolds rheology of the isothermal solve ``res`` with the temperature hook."""
    return ThermalRheology(pr.line_alpha_bar(res.M, res.L), viscosity=ehl_oil.viscosity, ph=ph,
                           z=ehl_oil.roelands_z() if ehl_oil.viscosity == "roelands" else 0.68,
                           compressible=compressible, T_bulk=T_bulk, s0=oil.s0 if oil.model == "roelands" else 0.0,
                           beta_t=oil.beta_t, expansion=oil.expansion, T_ref=oil.T0)


class _Film:
    """One EHL grid of the thermal loop: its Level with a :class:`ThermalRheology` of its
    own, and the current (P, H) there, started from the isothermal solution ``res``
    (injected onto a coarser grid)."""

    def __init__(self, rheo: ThermalRheology, res, level: int, k: int, x0: float):
        self.rheo = replace(rheo, state={})
        self.X = np.linspace(x0, X1, 16 * 2**k + 1)
        self.lv = Level(self.rheo, pr.line_lam_bar(res.M), pr.LINE_LOAD, x=self.X, ad_factor=1.0, sd_factor=1.0)
        self.start = res.P[:: 2 ** (level - k)], res.H0
        self.PI, self.H0 = self.start[0][self.lv.interior].copy(), res.H0
        self.P, self.H = (res.P, res.H) if k == level else self.lv.film(self.PI, self.H0)

    def correct(self, coarse: _Film, T_nodes: np.ndarray) -> None:
        """Start from the better (smaller Reynolds residual at the coarse temperatures
        ``T_nodes`` [K]) of the isothermal solution plus the prolonged thermal correction of
        the ``coarse`` grid (the nested iteration's coarse-grid correction: the fine-minus-
        coarse difference is about the same hot and cold) and the prolonged coarse thermal
        solution itself (better where the heating moves the pressure spike by cells)."""
        self.temperature(T_nodes)
        H0 = self.start[1] + (coarse.H0 - coarse.start[1])
        best = None
        for P in (self.start[0] + np.interp(self.X, coarse.X, coarse.P - coarse.start[0]),
                  np.interp(self.X, coarse.X, coarse.P)):
            PI = np.maximum(P, 0.0)[self.lv.interior]
            norm = self.residual(PI, H0)
            if best is None or norm < best[0]:
                best = (norm, PI)
        self.PI, self.H0 = best[1], H0
        self.P, self.H = self.lv.film(self.PI, self.H0)

    def residual(self, PI: np.ndarray, H0: float) -> float:
        """The Reynolds residual norm (load row scaled by the load) at the current temperatures; inf if not finite."""
        F = self.lv.evaluate(PI, H0)[0]
        norm = float(np.hypot(np.linalg.norm(F[:-1]), F[-1] / self.lv.load))
        return norm if np.isfinite(norm) else math.inf

    def temperature(self, T_nodes: np.ndarray) -> None:
        """The film-mean temperatures [K] on the nodes, seen by the Reynolds viscosity and density."""
        self.rheo.state["node"] = T_nodes
        self.rheo.state["quad"] = self.lv.reynolds.basis.interpolate(T_nodes)

    def resolve(self, T_nodes: np.ndarray, tol: float, reuse: dict, case: str) -> int:
        """Newton on this grid with the film-mean temperatures ``T_nodes`` [K]; its iterations."""
        self.temperature(T_nodes)
        self.PI, self.H0, hist = newton_dense(self.lv, self.PI, self.H0, tol=tol, case=case, reuse=reuse)
        self.P, self.H = self.lv.film(self.PI, self.H0)
        return len(hist.residual)




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
