"""Dense semi-smooth Newton for the FD EHL equations of one (coarse) grid, with FAS
right-hand sides: the exact coarsest-grid solver of the multigrid cycle (:mod:`fas`).

Unknowns x = (P at the interior nodes, H0); equations

    F = ( min(P_i, c_i (f_i - L_i(P, H0))),   (hx hy sum P - g) / g )

(the NCP form of the cavitation condition, as in :mod:`femgear.physics.ehl.fe.level`; c_i a row
scaling frozen at the start). The Jacobian is exact: the 5-point Poiseuille stencil with
the derivatives of eps = rho H^3 / (eta lam_bar) through P and H, the upwinded wedge, and
the film's dependence on P through the dense influence matrix. The load row fixes H0
(the exact load balance on the coarsest grid replaces Venner & Lubrecht's H0 relaxation,
which needs tens of cycles to reach 1e-6). Damped by backtracking on |F| with a cap on
|dP| and a positive film.
"""

from __future__ import annotations

import numpy as np
import scipy.linalg as sla
import scipy.sparse as sp

from femgear.errors import ConvergenceError
from femgear.physics.ehl.fd.operator import FDLevel

MAX_DP = 1.0
MAX_LOG_ETA = 4.0


def _stencil(lv: FDLevel, entries: dict[tuple[int, int], np.ndarray]) -> sp.csr_matrix:
    """Matrix (interior nodes x all nodes) from {(dy, dx): coefficient (ny-2, nx-2)}."""
    ny, nx = lv.ny, lv.nx
    jj, ii = np.meshgrid(np.arange(1, ny - 1), np.arange(1, nx - 1), indexing="ij")
    row = np.arange(jj.size).reshape(jj.shape)
    rows, cols, vals = [], [], []
    for (dy, dx), c in entries.items():
        jc, ic = jj + dy, np.clip(ii + dx, 0, nx - 1)
        rows.append(row.ravel()), cols.append((jc * nx + ic).ravel()), vals.append(c.ravel())
    return sp.csr_matrix((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))),
                         shape=(jj.size, nx * ny))


def jacobian_blocks(lv: FDLevel, P: np.ndarray, H: np.ndarray):
    """Local dL/dP|_H and dL/dH|_P (interior x all nodes) at the state (P, H)."""
    rh = lv.rheology
    eps, deps_P, deps_H = rh.epsilon(P, H, lv.lam_bar)
    rho, drho = rh.density(P)
    w, e, s, n = lv.faces(eps)
    Pc = P[1:-1, 1:-1]
    gx, gy = 1.0 / (2 * lv.hx**2), 1.0 / (2 * lv.hy**2)
    dW, dE = gx * (P[1:-1, :-2] - Pc), gx * (P[1:-1, 2:] - Pc)
    dS, dN = gy * (P[:-2, 1:-1] - Pc), gy * (P[2:, 1:-1] - Pc)
    nb = {(0, 0): dW + dE + dS + dN, (0, -1): dW, (0, 1): dE, (-1, 0): dS, (1, 0): dN}
    pois = {(0, 0): -(w + e + s + n), (0, -1): w, (0, 1): e, (-1, 0): s, (1, 0): n}

    def at(a, dy, dx):
        return a[1 + dy: lv.ny - 1 + dy, 1 + dx: lv.nx - 1 + dx]

    eP, eH = {}, {}
    for (dy, dx), dl in nb.items():
        eP[(dy, dx)] = pois[(dy, dx)] + dl * at(deps_P, dy, dx)
        eH[(dy, dx)] = dl * at(deps_H, dy, dx)
    for o, wt in lv.wedge_weights():
        src = np.clip(np.arange(1, lv.nx - 1) + o, 0, lv.nx - 1)
        eP[(0, o)] = eP.get((0, o), 0.0) - wt * (drho * H)[1:-1][:, src]
        eH[(0, o)] = eH.get((0, o), 0.0) - wt * rho[1:-1][:, src]
    return _stencil(lv, eP), _stencil(lv, eH)


class CoarseNewton:
    """Exact solver of one small FD level: ``solve(P, H0, f, g)`` -> (P, H0, iterations)."""

    def __init__(self, lv: FDLevel, max_iter: int = 40, tol: float = 1e-10):
        self.lv, self.max_iter, self.tol = lv, max_iter, tol
        nx, ny = lv.nx, lv.ny
        jj, ii = np.meshgrid(np.arange(1, ny - 1), np.arange(1, nx - 1), indexing="ij")
        self.I = (jj * nx + ii).ravel()
        self.Kd = (np.zeros((lv.nx * lv.ny, self.I.size)) if lv.rigid
                   else lv.defl.dense(np.arange(lv.nx * lv.ny), self.I))
        self._lu, self._c = None, None

    def merit(self, P, H0, f, g, c):
        """F, the film and the active (cavitated: min picks P) set."""
        lv = self.lv
        r, H, _, _ = lv.residual(P, H0, f)
        F = np.empty(self.I.size + 1)
        PI, cr = P[1:-1, 1:-1].ravel(), c * r.ravel()
        F[:-1] = np.minimum(PI, cr)
        F[-1] = 0.0 if g is None else (lv.load_of(P) - g) / g
        return F, H, PI <= cr

    def jacobian(self, P, H, c, act, g) -> np.ndarray:
        lv, I = self.lv, self.I
        JP, JH = jacobian_blocks(lv, P, H)
        J = np.empty((I.size + 1, I.size + 1))
        J[:-1, :-1] = JP[:, I].toarray()
        if not lv.rigid:
            J[:-1, :-1] += JH @ self.Kd
        J[:-1, -1] = np.asarray(JH.sum(axis=1)).ravel()
        J[:-1] *= -c[:, None]
        ia = np.nonzero(act)[0]
        J[ia] = 0.0
        J[ia, ia] = 1.0
        if g is None:  # H0 given (no load equation)
            J[-1], J[-1, -1] = 0.0, 1.0
        else:
            J[-1, :-1], J[-1, -1] = lv.cell / g, 0.0
        return J

    def solve(self, P: np.ndarray, H0: float, f: np.ndarray, g: float, case: str = "ehl fas coarse",
              strict: bool = True, max_iter: int | None = None, chord: bool = False):
        """Newton from (P, H0) -> (P, H0, iterations) (``g`` None: H0 fixed, no load
        equation); raises on failure, or
        (``strict=False``: inside a cycle, where the coarse grid only approximates the
        fine one) returns the iterate of smallest residual, after at most ``max_iter``
        steps (default: the solver's). ``chord``: keep the last LU factors while they
        halve the residual each step (the coarse problems of successive cycles differ
        little; a factorisation costs ~10 residuals)."""
        max_iter = self.max_iter if max_iter is None else max_iter
        lv, I = self.lv, self.I
        P = np.maximum(P, 0.0)
        if chord and self._c is not None:  # the row scaling of the kept factors
            c = self._c
        else:
            JP, _ = jacobian_blocks(lv, P, lv.film(P, H0))
            c = 1.0 / np.maximum(np.abs(JP[np.arange(I.size), I].A1), 1e-12)
        self._c = c
        F, H, act = self.merit(P, H0, f, g, c)
        hist: list[float] = []
        best = (np.inf, P, H0)
        cap = min(MAX_DP, MAX_LOG_ETA / max(lv.rheology.alpha_bar, 1e-12))
        try:
            for it in range(max_iter + 1):
                hist.append(float(np.linalg.norm(F)))
                if hist[-1] < best[0]:
                    best = (hist[-1], P, H0)
                if hist[-1] < self.tol:
                    return P, H0, it
                if it == max_iter:
                    break
                lu = self._lu if chord else None
                if lu is None:
                    try:
                        lu = sla.lu_factor(self.jacobian(P, H, c, act, g), check_finite=False)
                    except (sla.LinAlgError, ValueError) as exc:
                        raise ConvergenceError(case, f"singular coarse Jacobian ({exc})",
                                               {"residual": hist}) from exc
                    self._lu = lu
                dx = sla.lu_solve(lu, -F, check_finite=False)
                P, H0, F, H, act = self._search(P, H0, dx, F, f, g, c, cap, case, hist)
                if np.linalg.norm(F) > 0.5 * hist[-1]:
                    self._lu = None  # a slow (chord) step: refactorise next time
            raise ConvergenceError(case, f"no convergence in {max_iter} coarse Newton "
                                   "iterations", {"residual": hist})
        except ConvergenceError:
            if strict or not np.isfinite(best[0]):
                raise
            return best[1], best[2], max_iter

    def _search(self, P, H0, dx, F, f, g, c, cap, case, hist):
        big = float(np.max(np.abs(dx[:-1]))) if dx.size > 1 else 0.0
        alpha = min(1.0, cap / big) if big > 0 else 1.0
        norm0, best = float(np.linalg.norm(F)), None
        for _ in range(12):
            Pt = P.copy()
            Pt[1:-1, 1:-1] += alpha * dx[:-1].reshape(self.lv.ny - 2, self.lv.nx - 2)
            np.maximum(Pt, 0.0, out=Pt)
            H0t = H0 + alpha * dx[-1]
            Ft, Ht, at = self.merit(Pt, H0t, f, g, c)
            if np.all(np.isfinite(Ft)) and Ht.min() > 0.0:
                nt = float(np.linalg.norm(Ft))
                if nt <= (1 - 1e-4 * alpha) * norm0:
                    return Pt, H0t, Ft, Ht, at
                if best is None or nt < best[0]:
                    best = (nt, (Pt, H0t, Ft, Ht, at))
            alpha *= 0.5
        if best is None:
            raise ConvergenceError(case, "coarse line search found no admissible step",
                                   {"residual": hist})
        return best[1]
