"""Line contact EHL (1D): P1 Reynolds (scikit-fem), log-kernel deflection, dense Newton.

Hertzian line scaling (Venner & Lubrecht 2000, sec. 2.2): X = x/b, P = p/p_h,
H = h R/b^2, H(X) = H0 + X^2/2 - (1/pi) int ln|X - X'| P dX', load int P = pi/2,
lam_bar = 3 pi^2/(8 M^2), alpha_bar = L sqrt(M/(2 pi)) (Moes line groups, :mod:`params`).
Nested iteration over levels (``16 * 2**level`` intervals); each level is solved by dense
Newton (cheap for n <= ~4000), with continuation in alpha_bar when a direct start fails.
"""

from __future__ import annotations

import time

import numpy as np

from femgear.errors import ConvergenceError, SceneError
from femgear.physics.contact.film import moes_line_central
from femgear.physics.ehl.core import accuracy as acc
from femgear.physics.ehl.core import params as pr
from femgear.physics.ehl.core.grid import prolongation_1d
from femgear.physics.ehl.core.history import History
from femgear.physics.ehl.core.results import EHLResult
from femgear.physics.ehl.core.rheology import Rheology
from femgear.physics.ehl.core.surface import apply_surface, evaluate
from femgear.physics.ehl.fe.level import Level
from femgear.physics.ehl.fe.newton import RESIDUAL_TOL, newton_dense
from femgear.physics.ehl.fe.point import CONTINUATION, _result

X0_DEFAULT = -4.5
DEFAULT_LEVEL = 6  # 1025 nodes
MAX_LEVEL = 8  # 4097 nodes: the finest grid a tol-driven solve may reach (dense Newton)
LIMIT = 3.0  # predictor increments capped at LIMIT x their rms (see _PathHistory)
# warm-started solves of a sequence stop at this scaled residual: on the 41-position
# benchmark path (studies/benchmarks/ehl.py) the answers then equal the cold ones (residual
# 1e-10) to 1.3e-9 (Hc), 8e-8 (Hmin), 8e-7 (Pmax, the outlet spike) relative, and it saves
# about one finest-level Newton iteration per position against 1e-8
WARM_RESIDUAL_TOL = 1e-6
# the coarser level of a warm solve only feeds the two-level error estimate and the fine
# start: at 1e-4 the estimates move by 1.3 % (Hc) and 0.7 % (Hmin) of themselves on that
# path (an estimate, not a bound; 1e-3 moved them by 5 % and 18 %) and it saves more than
# half a Newton iteration per solve against 1e-6
COARSE_WARM_RESIDUAL_TOL = 1e-4
# a finest-level Newton from the predicted start that has not converged in this many
# iterations restarts from the prolonged coarse solution: converging warm solves take 2-6;
# on coarser paths (9-21 positions for the benchmark's mesh cycle) some predictions led
# Newton into damped steps (alpha 0.03-0.05, residual stuck at 4e-2) for the full
# max_iter = 60 iterations before the restart (fine iterations on the 21-position path:
# 431 -> 120)
WARM_MAX_ITER = 8


def solve_line(M: float, L: float, *, level: int | None = None, coarse_level: int = 4,
               x0: float | None = None, x1: float = 1.5, viscosity: str = "barus",
               compressible: bool = False, ph: float | None = None, z: float = 0.68,
               ad_factor: float = 1.0, sd_factor: float = 1.0, tol: float | None = None,
               newton_tol: float = 1e-8, max_level: int = MAX_LEVEL, max_iter: int = 60,
               start: EHLResult | None = None, reuse: dict | None = None,
               surface=None):
    """Isothermal line-contact EHL in Moes line groups (M, L); returns EHLResult.

    Domain X in [x0, x1] (x0 default -4.5, checked against the fully flooded inlet
    distance like the point contact's default domain); level ``k`` has ``16 * 2**k``
    intervals. ``tol``, ``newton_tol`` and the flags as in
    :func:`femgear.physics.ehl.point.solve_point` (default level 6, tol-driven cap ``max_level``).

    ``start``: a line solution of a neighbouring case (the previous position of a path,
    the previous point of a friction map) to warm-start from: the nested iteration then
    begins one level below the finest from that solution instead of from Hertz on the
    coarse levels (so the result still carries a two-level error estimate); when Newton
    fails from it, the cold start is used. ``reuse``: a dict the caller keeps across a
    sequence of solves; the LU factors of each level's Jacobian are kept there and
    reused as GMRES preconditioners (:func:`femgear.physics.ehl.fe.newton.newton_dense`), and the
    last two solutions on each level: when they end at ``start``, the warm start is the
    secant prediction of :class:`_PathHistory` (fewer Newton iterations); a finest-level
    Newton that fails from the prediction is restarted from the prolonged coarse level.
    A warm solve stops at the scaled residuals :data:`WARM_RESIDUAL_TOL` (finest level)
    and :data:`COARSE_WARM_RESIDUAL_TOL` (the level below, which feeds the error estimate).

    ``surface``: stationary roughness R(X) in Hertzian units (:mod:`femgear.physics.ehl.core.surface`),
    a callable f(X) or nodal values on the finest grid; the film is H0 + X^2/2 + D - R.
    None (default) leaves the smooth solve untouched.
    """
    if M <= 0 or L < 0:
        raise ValueError("need M > 0 and L >= 0")
    if tol is not None and not 0.0 < tol < 1.0:
        raise SceneError("tol", f"relative tolerance must lie in (0, 1), got {tol!r}")
    given_x0, x0 = x0 is not None, X0_DEFAULT if x0 is None else x0
    if not x0 < -1.0 < 1.0 < x1:
        raise ValueError("the domain must contain the Hertzian contact [-1, 1]")
    level = (DEFAULT_LEVEL if tol is None else max_level) if level is None else level
    t0 = time.perf_counter()
    case = f"ehl line M={M:g} L={L:g} level={level}"
    fac = pr.line_h_moes_factor(M)
    inlet = acc.inlet_problem(x0, float(moes_line_central(M, L)) / fac)
    if inlet and not given_x0:
        raise SceneError("M", f"line (M, L) = ({M:g}, {L:g}): {inlet}; pass x0= to solve it "
                         "anyway (the result is then flagged)")

    def make(frac: float, lev: int) -> Level:
        lv = line_level(M, L, np.linspace(x0, x1, 16 * 2**lev + 1), frac,
                        rheology=dict(viscosity=viscosity, ph=ph, z=z, compressible=compressible),
                        ad_factor=ad_factor, sd_factor=sd_factor)
        apply_surface(lv, evaluate(surface, lv.X, fine_x=np.linspace(x0, x1, 16 * 2**level + 1)))
        return lv

    hist = History()

    def newton(lv: Level, P, H0, residual_tol: float = RESIDUAL_TOL, iterations: int = max_iter):
        P, H0, h = newton_dense(lv, P, H0, max_iter=min(iterations, max_iter), tol=newton_tol,
                                case=case, residual_tol=residual_tol, reuse=reuse)
        hist.extend(h)
        return P, H0

    path = _PathHistory.of(reuse, x0, x1)
    got = _warm(start, make, max(level - 1, 0), M, L, fac, hist, newton, path)
    if got:
        lv, P, H0 = got
        coarse_level = max(level - 1, 0)
    else:
        lv, P, H0, coarse_level = _cold(make, min(coarse_level, level), level, M, L, fac, hist,
                                        newton, case)
    solved = {coarse_level: (lv.full(P), H0)}
    per_level = [_line_summary(lv, P, H0, fac, len(hist.residual), t0)]
    for k in range(coarse_level + 1, level + 1):
        if tol is not None and all(e is not None and e <= tol
                                   for e in acc.error_estimate(per_level).values()):
            break
        fine = make(1.0, k)
        n0 = len(hist.residual)
        if got:  # the predicted fine solution is closer than the prolonged coarse one
            P, H0 = _fine_warm(fine, path.fine_start(fine, start, M, L, k, solved[k - 1]),
                               solved[k - 1], hist, newton)
        else:
            P, H0 = newton(fine, (prolongation_1d(lv.n) @ lv.full(P))[fine.interior], H0)
        lv = fine
        solved[k] = (lv.full(P), H0)
        per_level.append(_line_summary(lv, P, H0, fac, len(hist.residual) - n0, t0))
    path.record(M, L, solved)
    return _result("line", M, L, lv, P, H0, fac, hist, per_level, time.perf_counter() - t0,
                   tol=acc.DEFAULT_TOL if tol is None else tol,
                   extra_flags=(f"domain: {inlet}",) if inlet else ())


def line_level(M: float, L: float, x: np.ndarray, frac: float = 1.0, *, rheology: dict,
               ad_factor: float = 1.0, sd_factor: float = 1.0) -> Level:
    """The smooth line-contact Level on nodes ``x`` (Hertzian X) for Moes (M, L), with
    alpha_bar scaled by ``frac`` (continuation); ``rheology`` as Rheology's keywords."""
    rheo = Rheology(pr.line_alpha_bar(M, L) * frac, **rheology)
    return Level(rheo, pr.line_lam_bar(M), pr.LINE_LOAD, x=x, ad_factor=ad_factor,
                 sd_factor=sd_factor)


def _cold(make, first: int, level: int, M, L, fac, hist: History, newton, case):
    """(level, P_I, H0, its index) from a Hertzian start on the first level that converges
    from ``first`` up (a coarse grid cannot carry a very thin film: high M)."""
    for lev in range(first, level + 1):
        try:
            return (*_direct(make, lev, M, L, fac, hist, newton), lev)
        except ConvergenceError as exc:
            hist.extend(History(**exc.history))
            if lev == level:
                raise ConvergenceError(case, "no convergence from a Hertzian start on any "
                                       "level", hist.as_dict()) from exc
    raise ValueError("level must be >= 0")


def _direct(make, lev: int, M, L, fac, hist: History, newton):
    """Level ``lev`` from the Hertz pressure and the Moes film, directly or with
    continuation in alpha_bar."""
    lv = make(1.0, lev)
    P = np.sqrt(np.maximum(1.0 - lv.X**2, 0.0))[lv.interior]
    P *= lv.load / (lv.m @ P)
    i0 = int(np.argmin(np.abs(lv.X)))
    H0 = float(moes_line_central(M, L)) / fac - float(lv.deflection(lv.full(P))[i0])
    try:
        return (lv, *newton(lv, P.copy(), H0))
    except ConvergenceError as exc:
        hist.extend(History(**exc.history))
    for frac in CONTINUATION:  # continuation in alpha_bar
        P, H0 = newton(lv if frac == 1.0 else make(frac, lev), P, H0)
    return lv, P, H0


def _warm(start: EHLResult | None, make, lev: int, M, L, fac, hist: History, newton,
          path: _PathHistory):
    """(level, P_I, H0) solved on level ``lev`` from a neighbouring line solution
    ``start``, or None when there is none or Newton fails there. The start is the
    secant prediction of :class:`_PathHistory` when the history kept in ``reuse`` ends at
    ``start``; otherwise ``start`` itself (Hertzian units: P(X) interpolated and scaled to
    the load, H0 shifted by the change of the Moes central film)."""
    if start is None:
        return None
    if start.kind != "line":
        raise ValueError("start must be a line-contact EHLResult")
    lv = make(1.0, lev)
    pred = path.predict(start, M, L, lev)
    if pred is not None:
        P, H0 = _on_level(lv, pred[0]), pred[1]
    else:
        P = _scaled_start(lv, start)
        H0 = start.H0 + (float(moes_line_central(M, L)) / fac - float(
            moes_line_central(start.M, start.L)) / pr.line_h_moes_factor(start.M))
    try:
        P, H0 = newton(lv, P, H0, COARSE_WARM_RESIDUAL_TOL)
    except ConvergenceError as exc:
        hist.extend(History(**exc.history))
        return None
    return lv, P, H0


def _fine_warm(fine: Level, predicted: tuple, coarse: tuple, hist: History, newton):
    """(P_I, H0) on the finest level of a warm solve from the ``predicted`` start; when
    Newton fails from it, from the ``coarse`` solution (nodal P, H0) prolonged (as a cold
    solve)."""
    try:
        return newton(fine, *predicted, WARM_RESIDUAL_TOL, WARM_MAX_ITER)
    except ConvergenceError as exc:
        hist.extend(History(**exc.history))
    P = (prolongation_1d(coarse[0].size) @ coarse[0])[fine.interior]
    return newton(fine, P, coarse[1], WARM_RESIDUAL_TOL)


def _scaled_start(level: Level, start: EHLResult) -> np.ndarray:
    """The pressure of ``start`` (Hertzian X) on the interior nodes of ``level``, scaled
    to the load."""
    return _on_level(level, np.interp(level.X, start.x, start.P))


def _on_level(level: Level, P: np.ndarray) -> np.ndarray:
    """Nodal pressure ``P`` on ``level``: clipped at 0, interior nodes, scaled to the load."""
    PI = np.maximum(P, 0.0)[level.interior]
    return PI * (level.load / (level.m @ PI))


class _PathHistory:
    """The last two solutions of a sequence of line solves (kept in the caller's
    ``reuse`` dict, per domain), level by level, for the warm-start predictor.

    Predictor (a secant continuation step in the parameter, Allgower & Georg 1990,
    Numerical Continuation Methods, ch. 2): with s = (ln M, ln L), the new solution is
    extrapolated linearly from the last two, x_pred = x_1 + t (x_1 - x_0), with
    t = (s - s_1).(s_1 - s_0) / |s_1 - s_0|^2 clipped to [0, 2] (t = 0, the last
    solution itself, with one entry). On the finest level the coarse-grid correction of
    the nested iteration is added: the coarse level is solved first, and its correction
    to its own prediction, prolonged, corrects the fine prediction (the fine-minus-coarse
    discretisation difference varies slowly along the path). The increment is limited
    to LIMIT x its rms value node by node: the pressure spike moves by about a cell per
    position, and extrapolating it at fixed nodes gives a start Newton does not recover
    from, while the limited step keeps the previous spike there."""

    KEY = "line path"

    def __init__(self, entries: list):
        self.entries = entries

    @classmethod
    def of(cls, reuse: dict | None, x0: float, x1: float) -> _PathHistory:
        return cls([] if reuse is None else reuse.setdefault((cls.KEY, x0, x1), []))

    def record(self, M: float, L: float, solved: dict) -> None:
        self.entries.append((M, L, solved))
        del self.entries[:-2]

    def _t(self, M: float, L: float) -> float:
        if len(self.entries) < 2:
            return 0.0
        (M0, L0, _), (M1, L1, _) = self.entries
        d0 = np.log([M1 / M0, max(L1, 1e-300) / max(L0, 1e-300)])
        d1 = np.log([M / M1, max(L, 1e-300) / max(L1, 1e-300)])
        nn = float(d0 @ d0)
        return 0.0 if nn == 0.0 else float(np.clip((d1 @ d0) / nn, 0.0, 2.0))

    def predict(self, start: EHLResult, M: float, L: float, lev: int):
        """(P on the nodes of level ``lev``, H0) predicted for (M, L), or None when the
        history does not end at ``start`` or lacks the level."""
        if not self.entries:
            return None
        M1, L1, last = self.entries[-1]
        if (M1, L1) != (start.M, start.L) or lev not in last:
            return None
        t = self._t(M, L)
        P1, H1 = last[lev]
        if t == 0.0 or lev not in self.entries[0][2]:
            return P1, H1
        P0, H0 = self.entries[0][2][lev]
        dP = t * (P1 - P0)
        cap = LIMIT * np.sqrt(np.mean(dP**2))  # a moving pressure spike is not extrapolated
        return P1 + np.clip(dP, -cap, cap), H1 + t * (H1 - H0)

    def fine_start(self, fine: Level, start: EHLResult, M: float, L: float, lev: int,
                   coarse: tuple):
        """(P_I, H0) to start level ``lev`` from: the fine prediction plus the prolonged
        coarse correction (``coarse`` = the solved coarse (P nodal, H0)), or ``start``
        interpolated with the coarse H0 when the history lacks the levels."""
        pf, pc = self.predict(start, M, L, lev), self.predict(start, M, L, lev - 1)
        if pf is None or pc is None or pc[0].size != coarse[0].size:
            return _scaled_start(fine, start), coarse[1]
        dP = np.interp(fine.X, fine.X[::2], coarse[0] - pc[0])  # linear prolongation
        dH0 = coarse[1] - pc[1]
        return _on_level(fine, pf[0] + dP), pf[1] + dH0


def _line_summary(level: Level, PI, H0, fac, its, t0) -> dict:
    P, H = level.film(PI, H0)
    i0 = int(np.argmin(np.abs(level.X)))
    return {"nodes": level.n, "h": level.h, "Hc": float(H[i0] * fac),
            "Hmin": float(H.min() * fac), "Pmax": float(P.max()), "iterations": its,
            "seconds": time.perf_counter() - t0}
