"""The line deflection operator in hierarchical (HODLR) form: O(n log n) memory, build and product.

The deflection of the piecewise-linear pressure, D = K P with K_ij = -(1/pi) int phi_j(s) ln|X_i - s| ds
(:func:`femgear.physics.ehl.core.elastic.line_hat_kernel`, any non-uniform grid), has a smooth kernel away from
the diagonal: every off-diagonal block K[C1, C2] of two adjacent clusters of nodes has a numerical rank that grows
only like log(n) log(1/eps) (measured on the graded grid of (M, L) = (1000, 4.3), 2049 nodes: 10-20 singular values
above 1e-8 max|K| in every such block, 1023 x 1023 to 63 x 63).  The interior index range is bisected down to
leaves of at most :data:`LEAF` nodes (a *hierarchically off-diagonal low-rank* matrix, HODLR: Ambikasaran & Darve
2013, *J. Sci. Comput.* 57, 477); each off-diagonal block is compressed by adaptive cross approximation with
partial pivoting (Bebendorf 2000, *Numer. Math.* 86, 565), which reads O(r (|C1| + |C2|)) entries of the
kernel, and recompressed by a truncated SVD of its QR factors to the relative accuracy :data:`EPS`.

The blocks are kept over *widened* rows: the cluster's nodes and the nodes one to the left and two to the right of
it, which the four-point Reynolds stencil of each of its rows reads (:mod:`femgear.physics.ehl.fd.line_operator`:
offsets -2..+1 of the interior row are nodes i - 1 ... i + 2), so that the Jacobian's off-diagonal blocks B K are
formed from them without reading the kernel again (:mod:`femgear.physics.ehl.fd.line_fast`).  The product reads
only each block's own rows.  The two boundary rows (nodes 0 and n - 1) are kept dense.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from femgear.physics.ehl.core.elastic import half_hat_integral

LEAF = 128      #: the largest leaf (dense block) [nodes]
EPS = 1e-12     #: relative accuracy of each compressed block (Frobenius) [-]
FAR = 2.0       #: a half hat is far when its centre lies more than FAR of its lengths from the node [-]
FAR_GAUSS = 10.0  #: beyond this many lengths, 4 Gauss points suffice [-]
MAX_RANK = 96   #: the largest rank an off-diagonal block may take before the compression is refused [-]


@dataclass
class Cluster:
    """The interior index range [lo, hi) of a node of the tree, its widened node rows [r0, r1)
    (:func:`widened`), and either two children or (a leaf) its dense widened block ``near`` = K[r0:r1, lo:hi].
    ``up`` = (U, V) with K[rows of the left child, cols of the right] ~ U V^T (U over the left child's widened
    rows), ``low`` likewise for the right child's rows and the left child's columns."""

    lo: int
    hi: int
    r0: int
    r1: int
    kids: tuple = ()
    near: np.ndarray | None = None
    up: tuple = field(default=())
    low: tuple = field(default=())


def widened(lo: int, hi: int, n: int) -> tuple[int, int]:
    """Node rows [r0, r1) read by the interior rows lo..hi-1 (nodes lo+1..hi, stencil nodes lo-1 ... hi+1)."""
    return max(lo - 1, 0), min(hi + 2, n)


class HKernel:
    """K[:, interior] of a grid in HODLR form: ``K @ v`` for v on the interior nodes gives the deflection on all
    n nodes, to the relative accuracy :data:`EPS` of its blocks; ``row(i)`` one row, exact."""

    def __init__(self, X: np.ndarray, leaf: int = LEAF, eps: float = EPS):
        self.X = np.asarray(X, dtype=float)
        self.n = n = self.X.size
        self.m = n - 2
        self.cols = np.arange(1, n - 1)
        self.eps = eps
        self.edge = hat_kernel(self.X, np.array([0, n - 1]), self.cols)
        self.root = self._build(0, self.m, leaf)
        self.shape = (n, self.m)

    def block(self, rows: np.ndarray, lo: int, hi: int) -> np.ndarray:
        """K[rows][:, interior lo..hi-1] (node rows), to round-off (:func:`hat_kernel`)."""
        return hat_kernel(self.X, np.asarray(rows), self.cols[lo:hi])

    def row(self, i: int) -> np.ndarray:
        """Exact row of node ``i`` over the interior columns."""
        return self.block(np.array([i]), 0, self.m)[0]

    def _build(self, lo: int, hi: int, leaf: int) -> Cluster:
        r0, r1 = widened(lo, hi, self.n)
        c = Cluster(lo, hi, r0, r1)
        if hi - lo <= leaf:
            c.near = self.block(np.arange(r0, r1), lo, hi)
            return c
        mid = (lo + hi) // 2
        left, right = self._build(lo, mid, leaf), self._build(mid, hi, leaf)
        c.kids = (left, right)
        c.up = self._compress(np.arange(left.r0, left.r1), mid, hi)
        c.low = self._compress(np.arange(right.r0, right.r1), lo, mid)
        return c

    def _compress(self, rows: np.ndarray, lo: int, hi: int) -> tuple[np.ndarray, np.ndarray]:
        U, V = aca(lambda i: self.block(rows[i: i + 1], lo, hi)[0],
                   lambda j: self.block(rows, lo + j, lo + j + 1)[:, 0], rows.size, hi - lo, self.eps)
        return recompress(U, V, self.eps)

    def __matmul__(self, v: np.ndarray) -> np.ndarray:
        v = np.asarray(v, dtype=float)
        out = np.empty((self.n,) + v.shape[1:])
        out[0], out[-1] = self.edge @ v
        inner = out[1:-1]
        inner[...] = 0.0
        stack = [self.root]
        while stack:
            c = stack.pop()
            if c.near is not None:
                a = c.lo + 1 - c.r0            # the block's own rows inside its widened rows
                inner[c.lo:c.hi] += c.near[a: a + c.hi - c.lo] @ v[c.lo:c.hi]
                continue
            left, right = c.kids
            U, V = c.up
            a = left.lo + 1 - left.r0
            inner[left.lo:left.hi] += U[a: a + left.hi - left.lo] @ (V.T @ v[right.lo:right.hi])
            U, V = c.low
            a = right.lo + 1 - right.r0
            inner[right.lo:right.hi] += U[a: a + right.hi - right.lo] @ (V.T @ v[left.lo:left.hi])
            stack.extend(c.kids)
        return out

    def dense(self) -> np.ndarray:
        """The whole n x m matrix (for checks)."""
        return self @ np.eye(self.m)

    @property
    def ranks(self) -> list[int]:
        """The ranks of the off-diagonal blocks (for reports)."""
        out, stack = [], [self.root]
        while stack:
            c = stack.pop()
            if c.kids:
                out += [c.up[0].shape[1], c.low[0].shape[1]]
                stack.extend(c.kids)
        return out


def _gauss(q: int) -> tuple[np.ndarray, np.ndarray]:
    t, w = np.polynomial.legendre.leggauss(q)
    return 0.5 * (t + 1.0), 0.5 * w


#: (distance over length from which a rule applies, its nodes and weights on [0, 1])
_RULES = ((FAR_GAUSS, *_gauss(4)), (FAR, *_gauss(8)))


def hat_kernel(X: np.ndarray, rows: np.ndarray, cols: np.ndarray) -> np.ndarray:
    """K[rows][:, cols] as :func:`femgear.physics.ehl.core.elastic.line_hat_kernel`, with each half hat whose
    centre lies more than :data:`FAR` of its lengths from the node integrated by Gauss-Legendre: 8 points up to
    :data:`FAR_GAUSS` lengths, 4 beyond (the integrand is analytic in a Bernstein ellipse of parameter >= 7.9,
    resp. >= 40: errors below 1e-13 of the entry).  The closed form loses ~eps |X_i - s| / h to cancellation
    there (1e-10 of max|K| at 8193 nodes, which no low-rank form reproduces), the quadrature does not."""
    n = X.size
    x = np.broadcast_to(X[rows][:, None], (rows.size, cols.size))
    j = np.broadcast_to(cols[None, :], x.shape)
    out = np.zeros(x.shape)
    for side in (-1, 1):                      # the rising half on [X_(j-1), X_j], the falling one on [X_j, X_(j+1)]
        ok = (j + side >= 0) & (j + side <= n - 1)
        jj = np.where(ok, j + side, j)
        a, b = (X[jj], X[j]) if side < 0 else (X[j], X[jj])
        length = b - a
        ratio = np.where(ok, np.abs(x - 0.5 * (a + b)) / np.where(ok, length, 1.0), 0.0)
        done = ~ok
        for start, t, w in _RULES:
            sel = ~done & (ratio > start)
            done |= sel
            if sel.any():
                xs, a_s, ls = x[sel], a[sel], length[sel]
                shape = (t if side < 0 else 1.0 - t) * w
                out[sel] += ls * (np.log(np.abs(xs[:, None] - a_s[:, None] - ls[:, None] * t)) @ shape)
        sel = ~done
        if sel.any():
            out[sel] += half_hat_integral(x[sel], a[sel], b[sel], length[sel], side)
    return -out / np.pi


def aca(row, col, nr: int, nc: int, eps: float) -> tuple[np.ndarray, np.ndarray]:
    """A ~ U V^T of an nr x nc block from its rows ``row(i)`` and columns ``col(j)`` by adaptive cross
    approximation with partial pivoting (Bebendorf 2000): stops when two consecutive cross terms are below
    ``eps`` times the Frobenius norm of the approximation (the second one guards against a pivot row that
    happens to be well approximated already).  Raises ``ValueError`` past :data:`MAX_RANK`."""
    Us, Vs = [], []
    norm2, small, used = 0.0, 0, np.zeros(nr, bool)
    i = 0
    for _ in range(min(nr, nc, MAX_RANK + 2)):
        used[i] = True
        r = row(i) - (np.array([u[i] for u in Us]) @ np.array(Vs) if Us else 0.0)
        j = int(np.argmax(np.abs(r)))
        if r[j] == 0.0:
            free = np.nonzero(~used)[0]
            if free.size == 0:
                break
            i = int(free[0])
            small += 1
            if small >= 2:
                break
            continue
        v = r / r[j]
        u = col(j) - (np.array(Us).T @ np.array([w[j] for w in Vs]) if Us else 0.0)
        cross = float(np.linalg.norm(u) * np.linalg.norm(v))
        if Us:
            norm2 += 2.0 * float((np.array(Us) @ u) @ (np.array(Vs) @ v))
        norm2 += cross**2
        Us.append(u)
        Vs.append(v)
        small = small + 1 if cross <= eps * np.sqrt(max(norm2, 0.0)) else 0
        if small >= 2:
            break
        score = np.where(used, -1.0, np.abs(u))
        i = int(np.argmax(score))
        if score[i] < 0:
            break
    else:
        if len(Us) > MAX_RANK:
            raise ValueError(f"kernel block of {nr} x {nc} not compressible to rank {MAX_RANK}")
    if not Us:
        return np.zeros((nr, 0)), np.zeros((nc, 0))
    return np.array(Us).T, np.array(Vs).T


def recompress(U: np.ndarray, V: np.ndarray, eps: float) -> tuple[np.ndarray, np.ndarray]:
    """U V^T truncated to the singular values above ``eps`` times the largest (QR of both factors, SVD of
    the small core)."""
    if U.shape[1] == 0:
        return U, V
    Qu, Ru = np.linalg.qr(U)
    Qv, Rv = np.linalg.qr(V)
    W, sv, Zt = np.linalg.svd(Ru @ Rv.T)
    k = max(int(np.sum(sv > eps * sv[0])), 1) if sv[0] > 0 else 0
    return Qu @ (W[:, :k] * sv[:k]), Qv @ Zt[:k].T
