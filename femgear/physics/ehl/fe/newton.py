"""Damped Newton iterations on x = (P_I, H0) for one :class:`Level`.

* :func:`newton_dense` - exact Jacobian JP + JH K with the dense influence matrix
  (Habchi 2008's full-system Newton, with the elastic block condensed onto P), LU
  solve. Used on coarse grids (up to ~65^2 nodes) and for all line contacts.
* :func:`newton_krylov` - fine grids: GMRES on exact Jacobian-vector products (the
  deflection applied by DC-FFT), preconditioned by a two-grid cycle: a local
  factorisation (elastic kernel truncated to a few cells) smooths, and the coarse
  level's dense Jacobian (LU) corrects the nonlocal elastic coupling that a local
  preconditioner misses (the cause of the stalled JFNK prototype in the project notes).

Globalisation: |dP|_inf <= 1 step cap, positive film, and a non-monotone Armijo
backtracking (Grippo, Lampariello & Lucidi 1986: the reference is the largest of the
last 5 merits) on a residual norm whose row scaling is frozen at the start of the solve;
the min-NCP residual is not monotone along good Newton steps, a monotone search stalls. Both functions return the
history and raise :class:`femgear.errors.ConvergenceError` on failure; no NaN returns.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np
import scipy.linalg as sla
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from femgear.errors import ConvergenceError
from femgear.physics.ehl.core.grid import prolongation
from femgear.physics.ehl.core.history import History
from femgear.physics.ehl.fe.krylov import gmres_right
from femgear.physics.ehl.fe.level import Level

MAX_DP = 1.0
RESIDUAL_TOL = 1e-10  # scaled residual norm accepted as converged after a full step
MAX_LOG_ETA = 4.0
WATCHDOG = 4
ILU_DROP, ILU_FILL = 1e-3, 3.0
LOCAL_RADIUS = 2  # elastic kernel kept in the local (smoother) Jacobian
# rebuild the preconditioner when GMRES needed more than REBUILD_KRYLOV iterations, or more
# than REBUILD_MIN and REBUILD_GROWTH x the iterations of the first solve with it (a stale
# active set makes the next, tighter solve stagnate).  Counted in iterations, not timed, so
# that a solve does not depend on the machine's load (it did: results varied by ~1e-10 and a
# thermal loop once failed on one run and passed on the next).
REBUILD_KRYLOV, REBUILD_MIN, REBUILD_GROWTH = 30, 8, 2.0


def _line_search(level: Level, PI, H0, F, dP, dH0, s, scale, hist: History, case: str, watchdog: int):
    """Backtracking on ||scale F||; returns the accepted (PI, H0, F, lin, H, act, alpha) and the count of watchdog
    steps in a row up to this one (``watchdog`` before it; 0 after a step that decreased the merit).

    When no trial decreases the (non-monotone) merit, the best admissible trial (finite,
    positive film) is accepted anyway up to ``WATCHDOG`` times in a row (a watchdog
    step: the min-NCP merit is not smooth where the cavitation set changes)."""
    merit0 = max([np.linalg.norm(scale * F)] + hist.residual[-5:])
    big = np.max(np.abs(dP)) if dP.size else 0.0
    cap = _step_cap(level)
    alpha = min(1.0, cap / big) if big > 0 else 1.0
    best = None
    for _ in range(10):
        Pt, H0t = PI + alpha * dP, H0 + alpha * dH0
        Ft, lin, H, _, act = level.evaluate(Pt, H0t, s)
        if np.all(np.isfinite(Ft)) and H.min() > 0.0:
            merit = np.linalg.norm(scale * Ft)
            if merit <= (1.0 - 1e-4 * alpha) * merit0:
                return (Pt, H0t, Ft, lin, H, act, alpha), 0
            if best is None or merit < best[0]:
                best = (merit, (Pt, H0t, Ft, lin, H, act, alpha))
        alpha *= 0.5
    watchdog += 1
    if best is not None and watchdog <= WATCHDOG:
        return best[1], watchdog
    raise ConvergenceError(case, "line search failed (residual does not decrease)"
                           + _stall_reason(hist, _step_cap(level)), hist.as_dict())


def _step_cap(level: Level) -> float:
    """The cap on |dP| of a step: the viscosity changes by at most e^MAX_LOG_ETA anywhere."""
    return min(MAX_DP, MAX_LOG_ETA / max(level.alpha_bar, 1e-12))


STALL_STEP = 0.25  # median damping below which a failed solve is reported as step-limited


def _stall_reason(hist: History, cap: float, last: int = 10) -> str:
    """Why a failed Newton solve did not converge, from its last ``last`` iterations:
    when the accepted steps were damped to a median below STALL_STEP, the largest Newton
    component |dP| and its node (the linear model fails there, e.g. at the outlet pressure
    spike of a strongly piezoviscous contact); '' otherwise."""
    steps, big = hist.step[-last:], hist.max_dp[-last:]
    if not steps or not big or float(np.median(steps)) >= STALL_STEP:
        return ""
    k = int(np.argmax(big))
    x, y = hist.max_dp_at[-last:][k]
    return (f"; steps damped to a median of {np.median(steps):.2g} over the last {len(steps)} "
            f"iterations: the Newton direction's largest |dP| reached {big[k]:.3g} (cap {cap:.2g}) "
            f"at (X, Y) = ({x:.3f}, {y:.3f})")


def _converged(level: Level, PI, H0, dP, dH0, F, alpha, tol, merit: float,
               residual_tol: float = RESIDUAL_TOL) -> bool:
    """A full step that was small (|dP| <= tol max P, |dH0| <= tol (|H0| + 1)), or a full
    step onto a scaled residual below ``RESIDUAL_TOL`` (the step test lags one quadratic
    iteration behind); both with the load balanced to 1e-6."""
    Hc_scale = max(abs(H0) + 1.0, 1e-3)
    load_err = abs(F[-1]) / level.load
    if alpha != 1.0 or load_err >= 1e-6:
        return False
    small_step = np.max(np.abs(dP)) <= tol * max(1.0, np.max(PI)) and abs(dH0) <= tol * Hc_scale
    return bool(small_step or merit < residual_tol)


def _record(hist: History, level: Level, F, scale, alpha, kry):
    hist.residual.append(float(np.linalg.norm(scale * F)))
    hist.load_error.append(float(abs(F[-1]) / level.load))
    hist.step.append(float(alpha))
    hist.krylov.append(int(kry))
    hist.level.append(int(level.n))


def _record_direction(hist: History, level: Level, dP: np.ndarray) -> None:
    """The largest |dP| of the undamped Newton direction and its node [X, Y]."""
    i = int(np.argmax(np.abs(dP))) if dP.size else 0
    node = int(level.interior[i]) if dP.size else 0
    hist.max_dp.append(float(abs(dP[i])) if dP.size else 0.0)
    hist.max_dp_at.append([float(level.X[node]), float(level.Y[node])])


def _newton(level: Level, PI, H0, direction: Callable, max_iter: int, tol: float,
            case: str, residual_tol: float = RESIDUAL_TOL) -> tuple[np.ndarray, float, History]:
    """Generic damped Newton loop; ``direction(PI, H0, F, lin, s, act)`` -> (dx, krylov its)."""
    hist = History()
    F, lin, H, s, act = level.evaluate(PI, H0)
    if not np.all(np.isfinite(F)):
        raise ConvergenceError(case, "non-finite residual at the initial state", hist.as_dict())
    scale = np.ones_like(F)
    scale[-1] = 1.0 / level.load
    watchdog = 0      # watchdog steps in a row (:func:`_line_search`)
    for _ in range(max_iter):
        dx, its = direction(PI, H0, F, lin, s, act)
        if not np.all(np.isfinite(dx)):
            raise ConvergenceError(case, "non-finite Newton direction", hist.as_dict())
        dP, dH0 = dx[:-1], float(dx[-1])
        _record_direction(hist, level, dP)
        (PI, H0, F, lin, H, act, alpha), watchdog = _line_search(level, PI, H0, F, dP, dH0, s, scale, hist, case,
                                                                 watchdog)
        _record(hist, level, F, scale, alpha, its)
        if _converged(level, PI, H0, alpha * dP, alpha * dH0, F, alpha, tol, hist.residual[-1],
                      residual_tol):
            return PI, H0, hist
    raise ConvergenceError(case, f"no convergence in {max_iter} Newton iterations"
                           + _stall_reason(hist, _step_cap(level)), hist.as_dict())


def newton_dense(level: Level, PI: np.ndarray, H0: float, *, max_iter: int = 60,
                 tol: float = 1e-7, case: str = "ehl", residual_tol: float = RESIDUAL_TOL,
                 reuse: dict | None = None) -> tuple[np.ndarray, float, History]:
    """Newton with the exact dense Jacobian (coarse grids, line contacts).

    With ``reuse`` (a dict kept by the caller across the solves of a sequence), the LU
    factors of the last Jacobian of the same size are kept and the Newton system is
    solved by right-preconditioned GMRES (:mod:`femgear.physics.ehl.fe.krylov`) on the exact
    Jacobian preconditioned by them; the Jacobian is
    factorised again only when GMRES needs more than :data:`DENSE_REUSE_KRYLOV`
    iterations. A Newton step then costs O(n^2) instead of O(n^3)."""
    Kd = level.dense_kernel()

    def factor(lin, s, act):
        J = level.dense_jacobian(lin, s, act, Kd)
        try:
            lu = sla.lu_factor(J, check_finite=True)
        except (sla.LinAlgError, ValueError) as exc:
            raise ConvergenceError(case, f"singular Jacobian ({exc})") from exc
        if reuse is not None:
            reuse[("dense", level.n)] = lu
        return lu

    def direction(PI, H0, F, lin, s, act):
        lu = None if reuse is None else reuse.get(("dense", level.n))
        if lu is not None:
            dx, its = _reused_lu_direction(level, lin, s, act, Kd, lu, F)
            if dx is not None:
                return dx, its
        return sla.lu_solve(factor(lin, s, act), -F, check_finite=False), 0

    return _newton(level, PI, H0, direction, max_iter, tol, case, residual_tol)


DENSE_REUSE_KRYLOV = 12


def _dense_forcing(F: np.ndarray) -> float:
    """GMRES relative tolerance of a reused-LU Newton step: eta = min(1e-3, 0.1 |F|), at
    least 1e-10. A forcing term O(|F|) keeps Newton's quadratic rate (Dembo, Eisenstat &
    Steihaug 1982, Inexact Newton methods, SIAM J. Numer. Anal. 19, thm 3.3) and the
    converged answer is set by the residual test alone; loose steps far from the
    solution let the stale factors serve longer."""
    return float(min(1e-3, max(1e-10, 0.1 * np.linalg.norm(F))))


def _reused_lu_direction(level: Level, lin, s, act, Kd, lu, F):
    """Right-preconditioned GMRES (:func:`femgear.physics.ehl.fe.krylov.gmres_right`) on the exact
    (row-scaled) dense-level Jacobian with ``lu`` as preconditioner; (dx, iterations) or
    (None, iterations) when it needs more than DENSE_REUSE_KRYLOV. The Jacobian is applied
    on full-length vectors (the boundary rows are dropped after the product): no sparse
    slicing per Newton step."""
    I = level.interior
    JP, JH = lin.JP, lin.JH
    colH = (JH @ np.ones(level.n))[I]
    full = np.zeros(level.n)

    def matvec(v):
        vP = v[:-1]
        out = np.empty_like(v)
        full[I] = vP
        r = s * ((JP @ full + JH @ (Kd @ vP))[I] + colH * v[-1])
        r[act] = vP[act]
        out[:-1] = r
        out[-1] = level.m @ vP
        return out

    getrs = sla.get_lapack_funcs("getrs", (lu[0],))  # lu_solve without its checks

    def psolve(r):
        return getrs(lu[0], lu[1], r)[0]

    dx, its, ok = gmres_right(matvec, psolve, -F, _dense_forcing(F), DENSE_REUSE_KRYLOV)
    if not ok:
        return None, its
    dx[:-1][act] = -F[:-1][act]
    return dx, its


class _PrecLevel:
    """Unscaled Jacobian of one level at a given state: matrix-free product (DC-FFT),
    a local factorisation (kernel truncated to ``radius`` cells) or, on the coarsest
    level, a dense LU."""

    def __init__(self, level: Level, PI: np.ndarray, H0: float, dense: bool, radius: int,
                 lin=None, act=None, factor: bool = True):
        self.level = level
        if lin is None:
            _, lin, _, _, act = level.evaluate(PI, H0)
        I = level.interior
        self.act = act
        self.JP = lin.JP[I][:, I].tocsr()
        self.JH = lin.JH[I].tocsr()
        self.colH = np.asarray(self.JH.sum(axis=1)).ravel()
        self.colH[act] = 0.0
        self.lu = self.ilu = None
        if not factor:
            return
        if dense:
            J = level.dense_jacobian(lin, np.ones(PI.size), act, level.dense_kernel())
            self.lu = sla.lu_factor(J, check_finite=False)
        else:
            Jl = (self.JP + self.JH @ level.local_kernel(radius)).tocsr()
            keep = sp.diags((~act).astype(float))
            Jl = (keep @ Jl + sp.diags(act.astype(float))).tocsc()
            try:  # natural (flow-wise) ordering is the most effective when it works
                self.ilu = spla.spilu(Jl, drop_tol=ILU_DROP, fill_factor=ILU_FILL,
                                      permc_spec="NATURAL")
            except RuntimeError:  # zero pivot: let SuperLU pivot and reorder, then exact LU
                try:
                    self.ilu = spla.spilu(Jl, drop_tol=ILU_DROP * 0.1,
                                          fill_factor=2 * ILU_FILL, permc_spec="COLAMD",
                                          diag_pivot_thresh=1.0)
                except RuntimeError:
                    try:
                        self.ilu = spla.splu(Jl)
                    except RuntimeError as exc:
                        raise ConvergenceError(
                            "ehl preconditioner", f"singular local Jacobian ({exc})") from exc

    def matvec(self, v: np.ndarray) -> np.ndarray:
        lv = self.level
        vP, vH = v[:-1], v[-1]
        out = np.empty_like(v)
        r = self.JP @ vP + self.JH @ lv.deflection(lv.full(vP)) + self.colH * vH
        r[self.act] = vP[self.act]
        out[:-1] = r
        out[-1] = lv.m @ vP
        return out

    def smooth(self, r: np.ndarray) -> np.ndarray:
        z = np.zeros_like(r)
        z[:-1] = self.ilu.solve(r[:-1])
        return z


def _transfer(coarse: Level, fine: Level) -> sp.csr_matrix:
    Pm = prolongation(coarse.grid, fine.grid)
    return Pm[fine.interior][:, coarse.interior].tocsr()


def _inject(coarse: Level, fine: Level, PI: np.ndarray) -> np.ndarray:
    j, i = np.divmod(coarse.interior, coarse.grid.nx)
    return fine.full(PI)[(2 * j) * fine.grid.nx + 2 * i]


class MultilevelPreconditioner:
    """V-cycle over ``levels`` (coarsest first): ILU smoothing of the local Jacobian on
    each level, dense LU of the full Jacobian on the coarsest; bilinear prolongation,
    its transpose as restriction. Applied to unscaled residuals.

    ``reuse`` maps a Level to a factorised :class:`_PrecLevel` kept from an earlier solve
    (the nested iteration's coarser levels, factorised at their own solutions): those are
    taken as they are, the others are built at the injected state and stored there, and
    the finest level's is always rebuilt at the current state and stored."""

    def __init__(self, levels: list[Level], transfers: list[sp.csr_matrix], PI, H0,
                 lin, act, radius: int | None = None, reuse: dict | None = None):
        self.transfers = transfers
        radius = LOCAL_RADIUS if radius is None else radius
        reuse = {} if reuse is None else reuse
        nl = len(levels)
        states = [PI]
        for k in range(nl - 1, 0, -1):
            states.insert(0, _inject(levels[k - 1], levels[k], states[0]))
        self.lv = []
        for k in range(nl):
            lv = levels[k]
            if k < nl - 1 and lv in reuse:
                self.lv.append(reuse[lv])
                continue
            fine = k == nl - 1
            reuse[lv] = _PrecLevel(lv, states[k], H0, dense=(k == 0), radius=radius,
                                   lin=lin if fine else None, act=act if fine else None)
            self.lv.append(reuse[lv])

    def vcycle(self, k: int, r: np.ndarray) -> np.ndarray:
        L = self.lv[k]
        if k == 0:
            return sla.lu_solve(L.lu, r, check_finite=False)
        T = self.transfers[k - 1]
        z = L.smooth(r)
        res = r - L.matvec(z)
        res[:-1][L.act] = 0.0
        rc = np.concatenate([T.T @ res[:-1], res[-1:]])
        zc = self.vcycle(k - 1, rc)
        z[:-1] += T @ zc[:-1]
        z[-1] += zc[-1]
        res = r - L.matvec(z)
        z += L.smooth(res)
        return z


@dataclass
class KeptPreconditioner:
    """The multilevel preconditioner of :func:`newton_krylov`, kept across its Newton steps (and, passed as its
    ``keep``, across a sequence of solves), with the GMRES iterations that decide its rebuild
    (:data:`REBUILD_KRYLOV`, :data:`REBUILD_MIN`, :data:`REBUILD_GROWTH`)."""

    prec: Any = None             #: the :class:`MultilevelPreconditioner` (None: not built yet)
    its: int = 0                 #: GMRES iterations of the latest solve with it (10**6: GMRES did not converge)
    its0: int | None = None      #: GMRES iterations of the first solve with it (None: none yet)

    def stale(self) -> bool:
        """Whether to rebuild it before the next solve: none yet, or GMRES slowed down with it."""
        first = self.its if self.its0 is None else self.its0
        return self.prec is None or self.its > REBUILD_KRYLOV or self.its > max(REBUILD_MIN, REBUILD_GROWTH * first)


@dataclass
class Forcing:
    """The Eisenstat & Walker (1996, choice 2: gamma 0.9, alpha 2) forcing term of one Newton solve, with its
    safeguard: the previous step's residual norm and term."""

    norm_f: float | None = None  #: |F| of the previous Newton step
    eta: float | None = None     #: its forcing term

    def next(self, norm_f: float, floor: float) -> float:
        """The GMRES relative tolerance of the step at residual norm ``norm_f``, in [``floor``, 0.1]."""
        if self.norm_f is None:
            eta = 0.1
        else:
            eta = 0.9 * (norm_f / self.norm_f) ** 2
            if 0.9 * self.eta**2 > 0.1:
                eta = max(eta, 0.9 * self.eta**2)
        eta = min(0.1, max(floor, eta))
        self.norm_f, self.eta = norm_f, eta
        return eta


def newton_krylov(levels: list[Level], PI: np.ndarray, H0: float, *, max_iter: int = 30,
                  tol: float = 1e-7, krylov_rtol: float = 1e-4, restart: int = 60,
                  maxiter_krylov: int = 300, case: str = "ehl", reuse: dict | None = None,
                  residual_tol: float = RESIDUAL_TOL, keep: KeptPreconditioner | None = None):
    """Newton on the finest of ``levels`` with GMRES + :class:`MultilevelPreconditioner`.

    The preconditioner is factorised once and kept across Newton steps until GMRES
    slows down (see :data:`REBUILD_KRYLOV`); ``reuse`` (see the preconditioner) carries
    factorised levels between the solves of a nested iteration or a sequence.
    GMRES is stopped at the Eisenstat & Walker (1996, choice 2) forcing term
    eta_k = 0.9 (|F_k|/|F_(k-1)|)^2, safeguarded, within [``krylov_rtol``, 0.1]: loose far
    from the solution, tight near it, so that Newton keeps its quadratic rate.

    ``keep``: a :class:`KeptPreconditioner` kept by the caller across a sequence of solves of one problem whose
    coefficients move (the thermal loop's re-solves at new film temperatures): the last
    preconditioner starts the next solve and is rebuilt by the same rule when GMRES slows
    down.  The operator is always the current Jacobian, so the converged answer is set by
    the residual test alone, as with any preconditioner."""
    fine = levels[-1]
    transfers = [_transfer(levels[k], levels[k + 1]) for k in range(len(levels) - 1)]

    kept = KeptPreconditioner() if keep is None else keep
    forcing = Forcing()

    def direction(PI, H0, F, lin, s, act):
        if kept.stale():
            kept.prec = MultilevelPreconditioner(levels, transfers, PI, H0, lin, act, reuse=reuse)
            kept.its0 = None
            Jf = kept.prec.lv[-1]
        else:
            Jf = _PrecLevel(fine, PI, H0, dense=False, radius=0, lin=lin, act=act, factor=False)
        prec = kept.prec
        # unscaled Newton system: rows of inactive nodes divided by s
        rhs = -F.copy()
        rhs[:-1] = np.where(act, rhs[:-1], rhs[:-1] / s)
        n = F.size
        A = spla.LinearOperator((n, n), matvec=Jf.matvec, dtype=float)
        M = spla.LinearOperator((n, n), matvec=lambda r: prec.vcycle(len(levels) - 1, r),
                                dtype=float)
        count = [0]

        def cb(_):
            count[0] += 1

        eta = forcing.next(float(np.linalg.norm(F)), krylov_rtol)
        dx, info = spla.gmres(A, rhs, M=M, rtol=eta, restart=restart,
                              maxiter=maxiter_krylov, callback=cb, callback_type="pr_norm")
        if info < 0:
            raise ConvergenceError(case, "GMRES breakdown")
        # the active (cavitated) rows of the Jacobian are identity rows: their components
        # are exact, whatever the GMRES tolerance (P = 0 there after a full step)
        dx[:-1][act] = rhs[:-1][act]
        kept.its = count[0] if info == 0 else 10**6
        if kept.its0 is None:
            kept.its0 = count[0]
        return dx, count[0]

    return _newton(fine, PI, H0, direction, max_iter, tol, case, residual_tol)

