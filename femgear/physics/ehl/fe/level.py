"""One discretisation level: grid, Reynolds operator, deflection, film and load.

The unknowns are x = (P at the interior nodes, H0). The residual is

    F = ( min(P_I, s_I R_I(P, H)),   sum_I m_i P_i - load )

with H = H0 + G(X, Y) + D[P] (G = X^2/2 + lambda Y^2/2 for point contacts, X^2/2 for
line contacts). Cavitation is the complementarity problem P >= 0, R >= 0, P R = 0
(the Reynolds residual R = A P - W Q is the multiplier of the constraint, as in an
obstacle problem), written with the NCP function min(a, b) and solved by semi-smooth
Newton, i.e. a primal-dual active set (Hintermueller, Ito & Kunisch 2002); it is the
limit of Wu's (1986) penalty xi min(P, 0) as xi -> infinity, without its ill-conditioning.
s_I = 1 / (|A_ii| + h^(d-1)) is a row scaling frozen at the start of a solve.
"""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp

from femgear.physics.ehl.core.elastic import line_kernel, line_kernel_interior, point_deflection
from femgear.physics.ehl.core.grid import Grid
from femgear.physics.ehl.core.rheology import Rheology
from femgear.physics.ehl.fe.reynolds import Linearization, ReynoldsFE


class Level:
    """Discrete EHL problem on one grid (point: ``grid``; line: 1D nodes ``x``)."""

    def __init__(self, rheology: Rheology, lam_bar: float, load: float, *,
                 grid: Grid | None = None, x: np.ndarray | None = None,
                 ratio: float = 1.0, rigid: bool = False, ad_factor: float = 1.0,
                 sd_factor: float = 0.0):
        self.grid, self.load, self.rigid = grid, load, rigid
        self._dense = None
        self._local: dict[int, sp.csr_matrix] = {}
        if grid is not None:
            X, Y = grid.coords()
            self.X, self.Y = X, Y
            self.geometry = 0.5 * X**2 + 0.5 * ratio * Y**2
            self.interior = grid.interior()
            self.defl = point_deflection(grid.nx, grid.ny, grid.h, grid.hy)
            self.shape = (grid.ny, grid.nx)
            self.h, self.hy, self.dim = grid.h, grid.dy, 2
        else:
            self.X = np.asarray(x, dtype=float)
            self.Y = np.zeros_like(self.X)
            self.geometry = 0.5 * self.X**2
            self.interior = np.arange(1, self.X.size - 1)
            self.h, self.dim = float(x[1] - x[0]), 1
            self.hy = self.h
            self._K = line_kernel(self.X, self.h)
            self.shape = (self.X.size,)
        # the artificial diffusion models the elastic transport of P (reynolds.py): none
        # for rigid surfaces
        beta = 0.0 if rigid else (self.defl.K[0, 0] if self.dim == 2 else self._K[0, 0]) / self.h
        self.reynolds = ReynoldsFE(rheology, lam_bar, grid=grid, x=x, beta=beta,
                                   ad_factor=ad_factor, sd_factor=sd_factor)
        self.n = self.X.size
        self.m = self.reynolds.mass[self.interior]

    @property
    def alpha_bar(self) -> float:
        """alpha p_h of the level's rheology (the Newton step cap)."""
        return self.reynolds.rheology.alpha_bar

    # -- state -------------------------------------------------------------------------
    def full(self, PI: np.ndarray) -> np.ndarray:
        P = np.zeros(self.n)
        P[self.interior] = PI
        return P

    def deflection(self, P: np.ndarray) -> np.ndarray:
        if self.rigid:
            return np.zeros(self.n)
        if self.dim == 2:
            return self.defl.apply(P.reshape(self.shape)).ravel()
        return self._K @ P

    def film(self, PI: np.ndarray, H0: float) -> tuple[np.ndarray, np.ndarray]:
        P = self.full(PI)
        return P, H0 + self.geometry + self.deflection(P)

    def dense_kernel(self) -> np.ndarray:
        """K[:, interior] as a dense array (all nodes x interior nodes), cached."""
        if self._dense is None:
            self._dense = self._dense_kernel()
        return self._dense

    def _dense_kernel(self) -> np.ndarray:
        I = self.interior
        if self.rigid:
            return np.zeros((self.n, I.size))
        if self.dim == 2:
            return self.defl.dense(np.arange(self.n), I)
        return line_kernel_interior(self.X, self.h)  # interior = 1..n-2 on a line

    def local_kernel(self, r: int) -> sp.csr_matrix:
        """K[:, interior] truncated to offsets <= r (sparse), for preconditioners; cached."""
        if r not in self._local:
            self._local[r] = self._local_kernel(r)
        return self._local[r]

    def _local_kernel(self, r: int) -> sp.csr_matrix:
        if self.rigid:
            return sp.csr_matrix((self.n, self.interior.size))
        if self.dim == 2:
            full = self.defl.local(np.arange(self.n), r)
            return full[:, self.interior].tocsr()
        K = self._K[:, self.interior]
        band = np.abs(np.arange(self.n)[:, None] - self.interior[None, :]) <= r
        return sp.csr_matrix(np.where(band, K, 0.0))

    # -- residual ----------------------------------------------------------------------
    def reynolds_residual(self, PI: np.ndarray, H0: float) -> np.ndarray:
        """Film (with the deflection) and Reynolds residual at all nodes, no Jacobian: one
        work unit of the solver benchmarks."""
        P, H = self.film(PI, H0)
        return self.reynolds.residual(P, H)

    def evaluate(self, PI: np.ndarray, H0: float, s: np.ndarray | None = None):
        """Residual F (length n_I + 1), linearization, film H (all nodes), scaling s and
        the active (cavitated) set. ``s`` is computed here when not given."""
        P, H = self.film(PI, H0)
        lin = self.reynolds.linearize(P, H)
        I = self.interior
        if s is None:
            s = 1.0 / (lin.eps_node_scale[I] + self.h ** (self.dim - 1))
        sR = s * lin.R[I]
        active = PI <= sR
        F = np.empty(I.size + 1)
        F[:-1] = np.where(active, PI, sR)
        F[-1] = self.m @ PI - self.load
        return F, lin, H, s, active

    def dense_jacobian(self, lin: Linearization, s: np.ndarray, active: np.ndarray,
                       Kd: np.ndarray) -> np.ndarray:
        I = self.interior
        nI = I.size
        JH_I = lin.JH[I]
        J = np.empty((nI + 1, nI + 1))
        J[:nI, :nI] = JH_I @ Kd if not self.rigid else 0.0
        J[:nI, :nI] += lin.JP[I][:, I].toarray()
        J[:nI, nI] = np.asarray(JH_I.sum(axis=1)).ravel()
        J[:nI] *= s[:, None]
        J[:nI][active] = 0.0
        ia = np.nonzero(active)[0]
        J[ia, ia] = 1.0
        J[nI, :nI] = self.m
        J[nI, nI] = 0.0
        return J
