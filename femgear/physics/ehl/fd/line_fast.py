"""Newton steps of the FD line operator in O(n log^2 n): a HODLR factorisation of the Jacobian, GMRES on the exact one.

The row-scaled Jacobian of :mod:`femgear.physics.ehl.fd.line_operator` is J = T + B K (T, B banded, offsets
-2..+1; K the dense deflection kernel) bordered by the H0 column and the load row.  With K in the HODLR form of
:class:`femgear.physics.ehl.fd.line_hodlr.HKernel`, J inherits it: every off-diagonal block of two sibling
clusters is B[C1] K[widened C1, C2] + (the corner entries of T), i.e. (B U) V^T plus a rank-1 (upper) or rank-2
(lower) term, formed from the kernel's factors in O(|C| r) without reading the kernel; the leaves are dense
(T + B K on the leaf, the active rows identity).  That matrix is factorised by the recursive Sherman-Morrison-
Woodbury formula (Ambikasaran & Darve 2013, *J. Sci. Comput.* 57, 477, sec. 3: per node the children's solves
of the low-rank factors and an LU of the small capacitance matrix), O(n r^2 log^2 n), and solved in
O(n r log n); the border by one more solve (block elimination of H0).  The factorisation is as exact as the
kernel's compression (1e-12), so it serves as the preconditioner of right-preconditioned GMRES
(:func:`femgear.physics.ehl.fe.krylov.gmres_right`) on the exact J (its product in O(n r log n) through the
HKernel): a fresh factorisation converges in one or two iterations, and one kept from an earlier Newton step
(or an earlier solve of a sequence, ``reuse``) serves while GMRES needs at most :data:`REUSE_KRYLOV` iterations,
as the dense LU does in :func:`femgear.physics.ehl.fd.line.direction`.  The Newton iterates, and hence the
answer, are set by the residual alone, whose only difference from the dense path is the kernel's compression.
"""

from __future__ import annotations

import numpy as np
import scipy.linalg as sla

from femgear.errors import ConvergenceError
from femgear.physics.ehl.fd.line_hodlr import Cluster, HKernel
from femgear.physics.ehl.fd.line_operator import OFFSETS, LineJacobian
from femgear.physics.ehl.fe.krylov import gmres_right

REUSE_KRYLOV = 12    #: GMRES iterations allowed on kept factors before refactorising
FRESH_KRYLOV = 40    #: GMRES iterations allowed on fresh factors (one or two are needed)


def band_apply(jac: LineJacobian, W: np.ndarray, lo: int, hi: int, r0: int) -> np.ndarray:
    """sum_o B[o]_i W[node i + 1 + o - r0] for the interior rows i in [lo, hi): B applied to a block ``W``
    given on the node rows from ``r0`` (the widened rows of :func:`femgear.physics.ehl.fd.line_hodlr.widened`)."""
    i = np.arange(lo, hi)
    out = np.zeros((hi - lo, W.shape[1]))
    for o in OFFSETS:
        loc = i + 1 + o - r0
        ok = loc >= 0                       # node -1 (o = -2 at i = 0) has a zero coefficient
        out[ok] += jac.B[o][lo:hi][ok, None] * W[loc[ok]]
    return out


class _Leaf:
    def __init__(self, c: Cluster, jac: LineJacobian):
        J = band_apply(jac, c.near, c.lo, c.hi, c.r0)
        r = np.arange(c.hi - c.lo)
        for o in OFFSETS:
            col = r + o
            ok = (col >= 0) & (col < r.size)
            J[r[ok], col[ok]] += jac.T[o][c.lo:c.hi][ok]
        act = np.nonzero(jac.active[c.lo:c.hi])[0]
        J[act] = 0.0
        J[act, act] = 1.0
        self.lu = sla.lu_factor(J, check_finite=False)
        self.getrs = sla.get_lapack_funcs("getrs", (self.lu[0],))

    def solve(self, b: np.ndarray) -> np.ndarray:
        return self.getrs(self.lu[0], self.lu[1], b)[0]


class _Node:
    """A^-1 for A = diag(A1, A2) + [[0, U1 V1^T], [U2 V2^T, 0]] by Sherman-Morrison-Woodbury."""

    def __init__(self, c: Cluster, jac: LineJacobian):
        left, right = c.kids
        self.mid, self.lo = left.hi, c.lo
        self.kids = (_factor(left, jac), _factor(right, jac))
        U1, V1 = _upper(c, jac)
        U2, V2 = _lower(c, jac)
        self.V1, self.V2 = V1, V2
        self.Y1, self.Y2 = self.kids[0].solve(U1), self.kids[1].solve(U2)
        r1, r2 = U1.shape[1], U2.shape[1]
        C = np.eye(r1 + r2)
        C[:r1, r1:] = V1.T @ self.Y2
        C[r1:, :r1] = V2.T @ self.Y1
        self.r1 = r1
        self.cap = sla.lu_factor(C, check_finite=False)
        self.getrs = sla.get_lapack_funcs("getrs", (self.cap[0],))

    def solve(self, b: np.ndarray) -> np.ndarray:
        k = self.mid - self.lo
        y1, y2 = self.kids[0].solve(b[:k]), self.kids[1].solve(b[k:])
        t = self.getrs(self.cap[0], self.cap[1], np.concatenate([self.V1.T @ y2, self.V2.T @ y1]))[0]
        return np.concatenate([y1 - self.Y1 @ t[: self.r1], y2 - self.Y2 @ t[self.r1:]])


def _factor(c: Cluster, jac: LineJacobian):
    return _Leaf(c, jac) if c.near is not None else _Node(c, jac)


def _upper(c: Cluster, jac: LineJacobian) -> tuple[np.ndarray, np.ndarray]:
    """J[left rows, right cols] = (B U) V^T + T[+1] at (mid - 1, mid)."""
    left, right = c.kids
    U, V = c.up
    BU = band_apply(jac, U, left.lo, left.hi, left.r0)
    u = np.zeros((left.hi - left.lo, 1))
    u[-1, 0] = jac.T[1][left.hi - 1]
    v = np.zeros((right.hi - right.lo, 1))
    v[0, 0] = 1.0
    return np.hstack([BU, u]), np.hstack([V, v])


def _lower(c: Cluster, jac: LineJacobian) -> tuple[np.ndarray, np.ndarray]:
    """J[right rows, left cols] = (B U) V^T + T[-1], T[-2] at (mid, mid - 1), (mid, mid - 2), (mid + 1, mid - 1)."""
    left, right = c.kids
    U, V = c.low
    mid = right.lo
    BU = band_apply(jac, U, right.lo, right.hi, right.r0)
    u = np.zeros((right.hi - right.lo, 2))
    u[0, 0], u[1, 0] = jac.T[-1][mid], jac.T[-2][mid + 1]
    u[0, 1] = jac.T[-2][mid]
    v = np.zeros((left.hi - left.lo, 2))
    v[-1, 0], v[-2, 1] = 1.0, 1.0
    return np.hstack([BU, u]), np.hstack([V, v])


class JacobianSolver:
    """The bordered Jacobian [[A, colH], [dual^T, 0]] of one state, factorised (module docstring)."""

    def __init__(self, K: HKernel, jac: LineJacobian, dual: np.ndarray):
        self.root = _factor(K.root, jac)
        self.dual = dual
        self.z = self.root.solve(jac.colH[:, None])[:, 0]
        self.dz = float(dual @ self.z)

    def solve(self, r: np.ndarray) -> np.ndarray:
        w = self.root.solve(r[:-1, None])[:, 0]
        mu = (self.dual @ w - r[-1]) / self.dz if self.dz != 0.0 else 0.0
        return np.r_[w - mu * self.z, mu]


def fast_direction(lv, reuse: dict | None, forcing):
    """The Newton direction of a level whose kernel is an :class:`HKernel`: GMRES on the exact Jacobian
    preconditioned by the kept factorisation, refactorised at the current state when that needs more than
    :data:`REUSE_KRYLOV` iterations.  ``forcing(F)`` is GMRES's relative tolerance."""
    key = ("fd line hodlr", lv.n)
    kept = {} if reuse is None else reuse

    def solve(PI, H0, F, state, s, act):
        jac = lv.jacobian(state, s, act)
        matvec = lambda v: lv.matvec(jac, v)  # noqa: E731
        old = kept.get(key)
        if old is not None:
            dx, its, ok = gmres_right(matvec, old.solve, -F, forcing(F), REUSE_KRYLOV)
            if ok:
                dx[:-1][act] = -F[:-1][act]
                return dx, its
        fac = JacobianSolver(lv.K, jac, lv.dual)
        kept[key] = fac
        dx, its, ok = gmres_right(matvec, fac.solve, -F, forcing(F), FRESH_KRYLOV)
        if not np.all(np.isfinite(dx)):
            raise ConvergenceError("ehl line", "singular Newton system (HODLR factorisation)")
        dx[:-1][act] = -F[:-1][act]
        return dx, its

    return solve
