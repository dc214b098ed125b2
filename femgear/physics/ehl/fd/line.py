"""Line-contact EHL on graded grids, converged to a tolerance: the nested Newton driver.

Each level of :mod:`femgear.physics.ehl.fd.line_grid` is solved by the damped semi-smooth
Newton of :mod:`femgear.physics.ehl.fe.newton` on the FD operator of
:mod:`femgear.physics.ehl.fd.line_operator`, from the solution of the level below
(linear interpolation); the levels go up until the Richardson estimates of Hc and Hmin of
:mod:`femgear.physics.ehl.core.accuracy` are within ``tol`` (default 1 %) and at least
``min_level`` is reached: the grid is chosen by the solver, not by the caller.

Newton steps, by the size of the level (:data:`DENSE_NODES`): on coarse levels the bordered dense Jacobian (the
FD band times the dense kernel) is factorised by LAPACK (LU), O(n^3); on finer ones the kernel is an
:class:`femgear.physics.ehl.fd.line_hodlr.HKernel` (HODLR, O(n log n) to apply) and the Jacobian is factorised
in the same hierarchical form (:mod:`femgear.physics.ehl.fd.line_fast`, O(n log^2 n)), the direction found by
GMRES on the exact Jacobian; both give the same films to the Newton tolerance (measured 1e-11 at (1000, 4.3)).
With ``reuse`` (a dict the caller keeps across a sequence of solves) the last factors of a level size
precondition right-preconditioned GMRES on the exact Jacobian (:mod:`femgear.physics.ehl.fe.krylov`) and are
refactorised only when it needs more than :data:`REUSE_KRYLOV` iterations.  Measured at (1000, 4.3), one solve
nested up to 1025 / 2049 / 4097 / 8193 / 16385 nodes: dense LU on every level 0.27 / 1.2 / 7.6 s (x2.6, x4.4,
x6.4 per doubling), the default (HODLR above 513 nodes) 0.083 / 0.16 / 0.32 / 0.73 / 1.7 s (x1.6-2.4;
``python studies/benchmarks/line_scaling.py``).

Cold start (the coarsest level): the dry Hertz pressure with Moes's central film; when
Newton fails from it (heavy loads: the steps are capped at 4/alpha_bar and the line search
stalls at the contact edges; light ones: the pressure is far from Hertzian), continuation in the load from
M = :data:`M_EASY` up or down to M, the ratio doubled after each converged step and its root taken after a failed
one (Allgower & Georg
1990, *Numerical Continuation Methods*, ch. 2: step-size adaptation), each start the
previous solution in Hertzian units with H0 shifted by the change of Moes's film; when that
fails too, the next finer level is tried (:data:`COLD_LEVELS` in all).  Warm start (``start``, a neighbouring line
solution: the previous position of a path, the previous point of a map): the levels of
``start`` are solved from it (interpolated to the new grid, H0 shifted likewise), falling
back to the cold start.
"""

from __future__ import annotations

import time
from functools import lru_cache

import numpy as np
import scipy.linalg as sla

from femgear.errors import ConvergenceError, SceneError
from femgear.physics.ehl.core import accuracy as acc
from femgear.physics.ehl.core import params as pr
from femgear.physics.ehl.core.assemble import assemble
from femgear.physics.ehl.core.elastic import line_hat_kernel
from femgear.physics.ehl.core.history import History
from femgear.physics.ehl.core.results import EHLResult
from femgear.physics.ehl.core.rheology import Rheology
from femgear.physics.ehl.fd.line_fast import fast_direction
from femgear.physics.ehl.fd.line_grid import (
    SPIKE_DENSITY,
    SPIKE_WIDTH,
    LineDomain,
    expected_film,
    hertz_start,
    line_domain,
)
from femgear.physics.ehl.fd.line_hodlr import HKernel
from femgear.physics.ehl.fd.line_operator import FDLine
from femgear.physics.ehl.fe.krylov import gmres_right
from femgear.physics.ehl.fe.newton import _dense_forcing, _newton

DEFAULT_TOL = 0.01   #: the accuracy a line solve is converged to by default (Hc and Hmin) [-]
COARSE_LEVEL = 2     #: the cold start's level (65 intervals)
ESTIMATE_LEVELS = 3  #: the levels a result's Richardson estimate is taken from (their observed order)
MIN_LEVEL = 4        #: the coarsest level a result may end on (257 intervals)
MAX_LEVEL = 7        #: the finest level a solve may reach (2049 intervals)
REUSE_KRYLOV = 12    #: GMRES iterations allowed on reused factors before refactorising
M_EASY = 10.0        #: where the load continuation of a cold start begins (up or down to M)
COLD_LEVELS = 3      #: the levels a cold start is tried on, from COARSE_LEVEL up
NEWTON_TOL = 1e-8    #: Newton's step tolerance (relative |dP|, |dH0|)
#: the largest grid solved with the dense kernel and LU; finer ones take the HODLR kernel and factorisation of
#: :mod:`femgear.physics.ehl.fd.line_fast` (O(n log^2 n); the crossover measured by
#: ``studies/benchmarks/line_scaling.py``)
DENSE_NODES = 513
#: the bumped solves of ``spike=True``: the bump moved to the spike they find while it moves by more than
#: SPIKE_SETTLED of its width.  On the baseline's path (513 nodes) the plain grids put the spike 0.031 b (0.6 w_s)
#: upstream of the resolved one, 0.063 b at the tehl level's probe (whose tolerance-driven plain solve ended on 257
#: nodes), the first bumped solve within 0.001 b.  A bump 0.6 w_s off lowers the isothermal peak pressure by 0.6 %,
#: the thermal one by 4 % and the film's peak temperature by 16 %; 1.3 w_s off the isothermal peak by 4 %: the
#: probe's step was the 10.7 % (p_max) and 17.5 % (film ΔT) second differences of the tehl level's path
SPIKE_PASSES = 3
SPIKE_SETTLED = 0.1


@lru_cache(maxsize=16)
def _kernel(dom: LineDomain, level: int, fast: bool | None = None) -> np.ndarray | HKernel:
    """K[:, interior] of the grid: dense up to :data:`DENSE_NODES` nodes, an :class:`HKernel` above (or as
    ``fast`` says); cached: the levels of a nested solve, the thermal loop and the positions of a path whose
    contacts share a domain build it once."""
    X = dom.nodes(level)
    if X.size > DENSE_NODES if fast is None else fast:
        return HKernel(X)
    K = line_hat_kernel(X, cols=np.arange(1, X.size - 1))
    K.setflags(write=False)
    return K


class LineProblem:
    """The levels of one line contact (M, L) on a domain, with the oil's rheology."""

    def __init__(self, M: float, L: float, dom: LineDomain, rheology: dict, surface=None,
                 rheology_factory=None, rigid: bool = False, fast: bool | None = None):
        self.M, self.L, self.dom, self.rigid, self.fast = M, L, dom, rigid, fast
        self.rheology, self.surface = rheology, surface
        self.factory = rheology_factory or (lambda M_, frac: Rheology(pr.line_alpha_bar(M_, L) * frac, **rheology))
        self.fac = pr.line_h_moes_factor(M)

    def level(self, k: int, M_: float | None = None, frac: float = 1.0) -> FDLine:
        M_ = self.M if M_ is None else M_
        X = self.dom.nodes(k)
        R = None if self.surface is None else self.surface(X)
        K = np.zeros((X.size, X.size - 2)) if self.rigid else _kernel(self.dom, k, self.fast)
        return FDLine(X, self.factory(M_, frac), pr.line_lam_bar(M_), pr.LINE_LOAD, surface=R, kernel=K)

    def summary(self, lv: FDLine, PI, H0, its: int, t0: float) -> dict:
        P, H = lv.film(PI, H0)
        i0 = int(np.argmin(np.abs(lv.X)))
        return {"nodes": lv.n, "h": lv.h, "Hc": float(H[i0] * self.fac), "Hmin": float(H.min() * self.fac),
                "Pmax": float(P.max()), "iterations": its, "seconds": time.perf_counter() - t0}


def direction(lv: FDLine, reuse: dict | None):
    """The Newton direction of level ``lv``: dense LU, or GMRES on the exact Jacobian preconditioned by the
    factors kept in ``reuse``; on a level with an :class:`HKernel`, the HODLR factorisation of
    :func:`femgear.physics.ehl.fd.line_fast.fast_direction` instead."""
    if isinstance(lv.K, HKernel):
        return fast_direction(lv, reuse, _dense_forcing)
    key = ("fd line", lv.n)

    def solve(PI, H0, F, state, s, act):
        jac = lv.jacobian(state, s, act)
        old = None if reuse is None else reuse.get(key)
        if old is not None:
            dx, its, ok = gmres_right(lambda v: lv.matvec(jac, v), old, -F, _dense_forcing(F), REUSE_KRYLOV)
            if ok:
                dx[:-1][act] = -F[:-1][act]
                return dx, its
        lu = sla.lu_factor(lv.dense(jac), check_finite=False)
        getrs = sla.get_lapack_funcs("getrs", (lu[0],))
        psolve = lambda r: getrs(lu[0], lu[1], r)[0]  # noqa: E731
        if reuse is not None:
            reuse[key] = psolve
        dx = psolve(-F)
        if not np.all(np.isfinite(dx)):
            raise ConvergenceError("ehl line", "singular Newton system")
        return dx, 0

    return solve


class NestedLine:
    """One nested solve of a :class:`LineProblem` (its history, level summaries, timing)."""

    def __init__(self, prob: LineProblem, reuse: dict | None, case: str, newton_tol: float, max_iter: int):
        self.prob, self.reuse, self.case = prob, reuse, case
        self.newton_tol, self.max_iter = newton_tol, max_iter
        self.hist = History()
        self.t0 = time.perf_counter()
        self.per_level: list[dict] = []

    def newton(self, lv: FDLine, PI, H0, max_iter: int | None = None):
        """(PI, H0) by Newton on ``lv`` (history recorded), or None."""
        try:
            PI, H0, h = _newton(lv, PI, H0, direction(lv, self.reuse), max_iter or self.max_iter,
                                self.newton_tol, self.case)
        except ConvergenceError as exc:
            self.hist.extend(History(**exc.history))
            return None
        self.hist.extend(h)
        return PI, H0

    def record(self, lv: FDLine, PI, H0, n0: int) -> None:
        self.per_level.append(self.prob.summary(lv, PI, H0, len(self.hist.residual) - n0, self.t0))

    def hertz(self, lv: FDLine, M_: float):
        PI = hertz_start(lv.X)[1:-1]
        PI *= lv.load / (lv.dual @ PI)
        i0 = int(np.argmin(np.abs(lv.X)))
        return PI, expected_film(M_, self.prob.L) - float(lv.deflection(lv.full(PI))[i0])

    def cold(self, k: int):
        """(level, PI, H0) on level ``k`` from Hertz, by load continuation when needed."""
        M = self.prob.M
        lv = self.prob.level(k)
        got = self.newton(lv, *self.hertz(lv, M))
        if got:
            return lv, *got
        Mc = M_EASY if M < M_EASY else min(M_EASY, M / 2.0)
        lvc = self.prob.level(k, Mc)
        got = self.newton(lvc, *self.hertz(lvc, Mc))
        ratio = 2.0
        up = M > Mc
        while got and Mc != M:
            Mn = min(M, Mc * ratio) if up else max(M, Mc / ratio)
            H0 = got[1] + expected_film(Mn, self.prob.L) - expected_film(Mc, self.prob.L)
            nxt = self.newton(self.prob.level(k, Mn), got[0], H0)
            if nxt:
                got, Mc, ratio = nxt, Mn, min(2.0 * ratio, 8.0)
            elif ratio > 1.1:
                ratio = ratio**0.5
            else:
                got = None
        if not got:
            return None
        return self.prob.level(k), *got

    def refine(self, lv: FDLine, PI, H0, k: int):
        fine = self.prob.level(k)
        P = np.interp(fine.X, lv.X, lv.full(PI))[1:-1]
        got = self.newton(fine, P, H0)
        return None if got is None else (fine, *got)

    def warm(self, start: EHLResult, k: int):
        lv = self.prob.level(k)
        PI = np.maximum(np.interp(lv.X, start.x, start.P), 0.0)[1:-1]
        PI *= lv.load / max(lv.dual @ PI, 1e-300)
        H0 = start.H0 + expected_film(self.prob.M, self.prob.L) - expected_film(start.M, start.L)
        got = self.newton(lv, PI, H0)
        return None if got is None else (lv, *got)


def solve_line_fd(M: float, L: float, *, tol: float | None = DEFAULT_TOL, level: int | None = None,
                  min_level: int = MIN_LEVEL, max_level: int = MAX_LEVEL, x0: float | None = None,
                  x1: float | None = None, viscosity: str = "barus", compressible: bool = False,
                  ph: float | None = None, z: float = 0.68, newton_tol: float = NEWTON_TOL,
                  max_iter: int = 60, start: EHLResult | None = None, reuse: dict | None = None,
                  surface=None, graded: bool = True, rheology_factory=None, rigid: bool = False,
                  fast: bool | None = None, spike: bool = False, spike_at: float | None = None,
                  spike_density: float = SPIKE_DENSITY) -> EHLResult:
    """Isothermal line-contact EHL in Moes line groups (M, L), converged to ``tol``.

    ``tol``: relative accuracy of Hc and Hmin by the two-level Richardson estimate (None:
    solve exactly ``level``); the levels go from ``min_level`` up to ``max_level`` (a result
    whose estimate still exceeds ``tol`` there is flagged).  ``level``: solve up to exactly
    that level instead.  ``x0``, ``x1``: the domain (default: the inlet at 1.25 m*, the
    fully flooded distance of the expected film, :mod:`femgear.physics.ehl.fd.line_grid`; an
    explicit inlet inside m* is solved and flagged).  Rheology as :class:`Rheology`;
    ``surface``: stationary roughness R(X) (a callable, Hertzian units); ``start``/``reuse``:
    warm starts along a sequence (module docstring).  ``graded=False``: uniform grids (for
    convergence studies); ``rigid``: no elastic deflection (the rigid limits' checks); ``fast``: the HODLR
    kernel and factorisation on every level (True), the dense ones (False), or by size (None: above
    :data:`DENSE_NODES`; the answers agree to the Newton tolerance).  ``spike``: the grids resolve the outlet
    pressure spike (the path solvers: its peak is then smooth along a path), by a bump of the node density at the
    spike (:func:`spike_index`, the outlet-most local maximum) that a first solve on the plain grids locates
    (``spike_at``: there, :meth:`LineDomain.with_spike`, of amplitude ``spike_density``), moved
    to where the bumped solve puts the spike and solved again while it moves by more than :data:`SPIKE_SETTLED` w_s
    (at most :data:`SPIKE_PASSES` bumped solves: the plain grids, whose cells are wider than the spike, place it
    up to 0.06 b upstream of the resolved one on the baseline's path).  Raises
    :class:`ConvergenceError` with the history when no level converges."""
    if not (M > 0 and L >= 0 and np.isfinite(M) and np.isfinite(L)):
        raise ValueError("need finite M > 0 and L >= 0")
    if tol is not None and not 0.0 < tol < 1.0:
        raise SceneError("tol", f"relative tolerance must lie in (0, 1), got {tol!r}")
    if surface is not None and not callable(surface):
        raise ValueError("surface must be a callable R(X) for the FD line solver")
    if spike and spike_at is None:
        args = dict(tol=tol, level=level, min_level=min_level, max_level=max_level, x0=x0, x1=x1, viscosity=viscosity,
                    compressible=compressible, ph=ph, z=z, newton_tol=newton_tol, max_iter=max_iter, surface=surface,
                    graded=graded, rheology_factory=rheology_factory, rigid=rigid, fast=fast,
                    spike_density=spike_density)
        best = solve_line_fd(M, L, start=start, **args)
        at = spike_peak(best.x, best.P)
        for _ in range(SPIKE_PASSES):
            try:
                got = solve_line_fd(M, L, start=best, reuse=reuse, spike_at=at, **args)
            except ConvergenceError as exc:   # the bumped grid's coarse levels too poor: the last answer, said so
                best.history["spike"] = f"not resolved (the spike grid failed: {str(exc)[:120]})"
                return best
            best, moved = got, spike_peak(got.x, got.P)
            if abs(moved - at) <= SPIKE_SETTLED * SPIKE_WIDTH:
                break
            at = moved
        return best
    H_exp = expected_film(M, L)
    dom = line_domain(H_exp, x0, x1, graded=graded)
    if spike_at is not None:
        dom = dom.with_spike(spike_at, spike_density)
    inlet = acc.inlet_problem(dom.x0, H_exp) if x0 is not None else None
    top = max_level if level is None else level
    prob = LineProblem(M, L, dom, dict(viscosity=viscosity, ph=ph, z=z, compressible=compressible), surface,
                       rheology_factory, rigid, fast)
    run = NestedLine(prob, reuse, f"ehl line M={M:g} L={L:g}", newton_tol, max_iter)
    got, k = None, min(COARSE_LEVEL, top)
    if start is not None:
        if start.kind != "line":
            raise ValueError("start must be a line-contact EHLResult")
        k = min(max(_level_of(start) - ESTIMATE_LEVELS + 1, COARSE_LEVEL), top)
        n0 = len(run.hist.residual)
        got = run.warm(start, k)
        if got:
            run.record(*got, n0)
    while got is None and k <= min(top, COARSE_LEVEL + COLD_LEVELS - 1):
        n0 = len(run.hist.residual)
        got = run.cold(k)
        if got:
            run.record(*got, n0)
        else:
            k += 1
    if got is None:
        raise ConvergenceError(run.case, "no convergence from a Hertzian start on any level", run.hist.as_dict())
    lv, PI, H0 = got
    while k < top:
        est = estimate(run.per_level)
        if tol is not None and level is None and k >= min_level and len(run.per_level) >= ESTIMATE_LEVELS and all(
                e is not None and e <= tol for e in est.values()):
            break
        k += 1
        n0 = len(run.hist.residual)
        nxt = run.refine(lv, PI, H0, k) or run.cold(k)   # a coarse solution too poor to start from: afresh
        if nxt is None:
            raise ConvergenceError(run.case, f"Newton failed on level {k} ({16 * 2**k + 1} nodes)",
                                   run.hist.as_dict())
        lv, PI, H0 = nxt
        run.record(lv, PI, H0, n0)
    load_error = abs(lv.dual @ PI - lv.load) / lv.load
    P, H = lv.film(PI, H0)
    hist = {**run.hist.as_dict(), "method": "fd", "domain": dom.as_list()}
    return assemble("line", M, L, lv.X, np.zeros(0), P, H, H0=H0, load_error=load_error, fac=prob.fac,
                    history=hist, iterations=len(run.hist.residual), per_level=run.per_level,
                    seconds=time.perf_counter() - run.t0, tol=DEFAULT_TOL if tol is None else tol,
                    extra_flags=(f"domain: {inlet}",) if inlet else (), estimate=estimate(run.per_level))


def spike_index(P: np.ndarray) -> int:
    """Index of the outlet pressure spike of ``P``: the local maximum nearest the outlet above a fifth of the
    largest pressure (the largest nodal value where there is no interior one).  Not the largest pressure: on a heavy
    contact the plain grid's spike is lower than the Hertzian dome, and a bump put at the dome never resolves it
    (the marine zoo pair, M 16, L 11.7: the spike 0.65-0.75 GPa on the plain 1025-node grid, 0.92-1.06 GPa
    resolved; the film's peak temperature on it up to 2 times low)."""
    inner = np.flatnonzero((P[1:-1] > P[:-2]) & (P[1:-1] >= P[2:]) & (P[1:-1] > 0.2 * P.max())) + 1
    return int(inner[-1]) if inner.size else int(np.argmax(P))


def spike_peak(X: np.ndarray, P: np.ndarray) -> float:
    """X of the outlet pressure spike (:func:`spike_index`): the vertex of the parabola through its nodal value and
    its neighbours (within them), so that the spike bump follows the spike smoothly rather than from node to node."""
    i = spike_index(P)
    if 0 < i < P.size - 1:
        a, b, _ = np.polyfit(X[i - 1:i + 2] - X[i], P[i - 1:i + 2], 2)
        if a < 0:
            return float(X[i] + np.clip(-b / (2.0 * a), X[i - 1] - X[i], X[i + 1] - X[i]))
    return float(X[i])


#: the nodes across the spike width w_s (:data:`~femgear.physics.ehl.fd.line_grid.SPIKE_WIDTH`) that resolve the
#: outlet spike (:func:`spike_resolved`): the bump gives about 100 (nodes 0.0005 b apart at 1025 nodes), the plain
#: graded grids 5 at 1025 nodes and 10 at 2049
SPIKE_NODES = 20


def spike_resolved(X: np.ndarray, P: np.ndarray) -> bool:
    """Whether the grid ``X`` resolves the outlet pressure spike of ``P`` (Hertzian units): at least
    :data:`SPIKE_NODES` nodes across the spike width at the spike (:func:`spike_index`), where there is one
    (:func:`is_spike`).  Not so where a path
    contact's bumped solve failed and the plain grid stands in: its peak pressure and film peak temperature are then
    the unresolved spike's, low by an amount no estimate of the solver measures (its Richardson estimate is of the
    films)."""
    i = spike_index(P)
    if not 0 < i < P.size - 1 or not is_spike(X, P, i):
        return True
    return bool(SPIKE_WIDTH / (0.5 * (X[i + 1] - X[i - 1])) >= SPIKE_NODES)


#: a local maximum is a spike when the pressure falls below SPIKE_DROP of it within SPIKE_REACH spike widths
#: downstream (:func:`is_spike`)
SPIKE_DROP, SPIKE_REACH = 0.9, 4.0


def is_spike(X: np.ndarray, P: np.ndarray, i: int) -> bool:
    """Whether the local maximum ``i`` of ``P`` is a spike, not a dome: the pressure falls below :data:`SPIKE_DROP`
    of it within :data:`SPIKE_REACH` spike widths downstream (0.2 b).  A Hertzian dome takes 0.44 b to fall by 10 %;
    an outlet spike falls to the outlet pressure within about one width.  A fast contact whose inlet heating has
    flattened the spike away (the turbo zoo pairs, M 5.4, L 15: the maximum 0.97 p_h at X 0.03) has none to
    resolve: flagging its dome as an unresolved spike was a false alarm at every path position."""
    down = (X > X[i]) & (X <= X[i] + SPIKE_REACH * SPIKE_WIDTH)
    return bool(np.any(P[down] < SPIKE_DROP * P[i]))


def estimate(per_level: list[dict]) -> dict:
    """The Richardson estimates of Hc and Hmin from the last :data:`ESTIMATE_LEVELS` levels with their observed
    order (:func:`femgear.physics.ehl.core.accuracy.error_estimate`, clamped to 1..2): Hc converges at second order
    on the graded grids (changes 0.053 / 0.013 / 0.0034 at (300, 4) from 257 to 2049 nodes), but Hmin, set at the
    outlet constriction beside the free cavitation boundary, can converge at first order (Roelands and
    Dowson-Higginson at (23, 13.9): changes 0.045 / 0.022 / 0.008 from 513 to 2049 nodes), which a two-level
    estimate of assumed order 2 would read up to three times too small."""
    return acc.error_estimate(per_level[-ESTIMATE_LEVELS:])


def _level_of(res: EHLResult) -> int:
    """The grid level of a line result (16 * 2**k intervals)."""
    return max(int(round(np.log2(max(res.nodes - 1, 16) / 16))), 0)
