"""Q1 / P1 element tables on a uniform grid, and assembly by array arithmetic.

On a uniform grid of square or equal rectangular cells (or equal 1-D intervals) every element is the same
affine image of the reference element, so the basis values ``phi[q, a]``, physical
gradients ``grad[d][q, a]`` and weights ``w[q]`` at the quadrature points are one set of
constants.  An element matrix with a coefficient c(e, q) at the points is then the
product of the (elements x points) array c with a constant (points x 4 x 4) table, and the
global matrix is that array summed into a CSR pattern computed once.

Layout (the same as scikit-fem's ``MeshQuad``/``ElementQuad1`` and ``MeshLine``/
``ElementLineP1`` with ``intorder=2``, so quadrature-point arrays are interchangeable):
elements row-major (e = j (nx-1) + i), element nodes (i, j), (i+1, j), (i+1, j+1),
(i, j+1); 2 x 2 Gauss points (xi, eta) = (g1, g1), (g1, g2), (g2, g1), (g2, g2),
g = (1 -/+ 1/sqrt 3)/2, weight h hy/4 each (gradients d/dY scaled by 1/hy); in 1-D the two points g1, g2, weight h/2.
Element matrices are indexed [e, test, trial].
"""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp

_G = (0.5 - 0.5 / np.sqrt(3.0), 0.5 + 0.5 / np.sqrt(3.0))


class UniformElements:
    """Connectivity ``T`` (ne, npe), tables ``phi``, ``grad``, ``w`` and the CSR pattern."""

    def __init__(self, T: np.ndarray, n: int, phi: np.ndarray, grad: tuple, w: np.ndarray):
        self.T, self.n, self.phi, self.grad, self.w = T, n, phi, grad, w
        self.ne, self.npe = T.shape
        rows = np.repeat(T, self.npe, axis=1).ravel()
        cols = np.tile(T, (1, self.npe)).ravel()
        keys, self._inv = np.unique(rows.astype(np.int64) * n + cols, return_inverse=True)
        self._indices = (keys % n).astype(np.int32)
        self._indptr = np.concatenate([[0], np.cumsum(np.bincount(keys // n, minlength=n))]).astype(np.int32)
        # constant tables [q, test, trial]
        self.stiffness = np.einsum("q,dqi,dqj->qij", w, np.array(grad), np.array(grad))
        # per direction (stretched cells: the artificial diffusion is scaled per direction)
        self.stiffness_d = [np.einsum("q,qi,qj->qij", w, g, g) for g in grad]
        self.streamline = np.einsum("q,qi,qj->qij", w, grad[0], grad[0])
        self._coef = [np.einsum("q,qi,qj->qij", w, g, phi) for g in grad]

    @classmethod
    def quad(cls, nx: int, ny: int, h: float, hy: float | None = None) -> UniformElements:
        """Q1 on nx x ny nodes, cells h x hy (hy None: square, h x h)."""
        ii, jj = np.meshgrid(np.arange(nx - 1), np.arange(ny - 1))
        n0 = (jj * nx + ii).ravel()
        T = np.stack([n0, n0 + 1, n0 + 1 + nx, n0 + nx], axis=1)
        xi = np.array([_G[0], _G[0], _G[1], _G[1]])
        eta = np.array([_G[0], _G[1], _G[0], _G[1]])
        phi = np.stack([(1 - xi) * (1 - eta), xi * (1 - eta), xi * eta, (1 - xi) * eta], axis=1)
        gx = np.stack([-(1 - eta), 1 - eta, eta, -eta], axis=1) / h
        gy = np.stack([-(1 - xi), -xi, xi, 1 - xi], axis=1) / (h if hy is None else hy)
        return cls(T, nx * ny, phi, (gx, gy), np.full(4, h * (h if hy is None else hy) / 4.0))

    @classmethod
    def line(cls, n: int, h: float) -> UniformElements:
        i = np.arange(n - 1)
        T = np.stack([i, i + 1], axis=1)
        xi = np.array(_G)
        phi = np.stack([1 - xi, xi], axis=1)
        gx = np.stack([-np.ones(2), np.ones(2)], axis=1) / h
        return cls(T, n, phi, (gx,), np.full(2, h / 2.0))

    # -- values at the quadrature points (elements x points) ------------------------------
    def at_points(self, Ue: np.ndarray) -> np.ndarray:
        return Ue @ self.phi.T

    def grad_at_points(self, Ue: np.ndarray, d: int) -> np.ndarray:
        return Ue @ self.grad[d].T

    def interpolate(self, u: np.ndarray) -> np.ndarray:
        """Nodal values ``u`` at the quadrature points (scikit-fem's Basis.interpolate)."""
        return self.at_points(np.asarray(u)[self.T])

    # -- element matrices [e, test, trial] ------------------------------------------------
    def products(self, trial: np.ndarray, test: np.ndarray) -> np.ndarray:
        """Constant element matrix int trial_j test_i from tables (points x npe)."""
        return np.einsum("q,qj,qi->ij", self.w, trial, test)

    def weighted(self, c: np.ndarray, table: np.ndarray) -> np.ndarray:
        """sum_q c[e, q] table[q, i, j]."""
        nq = table.shape[0]
        return (c @ table.reshape(nq, -1)).reshape(self.ne, self.npe, self.npe)

    def coef_grad(self, ax: np.ndarray, ay: np.ndarray | None = None) -> np.ndarray:
        """int phi_trial (a . grad phi_test) with a = (ax, ay) at the points."""
        out = self.weighted(ax, self._coef[0])
        if ay is not None:
            out += self.weighted(ay, self._coef[1])
        return out

    # -- global assembly ------------------------------------------------------------------
    def matrix(self, Ee: np.ndarray) -> sp.csr_matrix:
        data = np.bincount(self._inv, weights=np.ascontiguousarray(Ee).ravel(),
                           minlength=self._indices.size)
        A = sp.csr_matrix((data, self._indices, self._indptr), shape=(self.n, self.n))
        A.has_sorted_indices = True
        return A

    def scatter(self, Ve: np.ndarray) -> np.ndarray:
        return np.bincount(self.T.ravel(), weights=np.ascontiguousarray(Ve).ravel(), minlength=self.n)

    def load(self) -> np.ndarray:
        """int phi_i (lumped mass)."""
        return self.scatter(np.broadcast_to(self.w @ self.phi, (self.ne, self.npe)))
