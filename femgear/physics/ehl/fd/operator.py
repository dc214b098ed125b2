"""Finite-difference point-contact EHL operator on one grid (the multigrid discretisation).

The discretisation of Venner & Lubrecht (2000, "Multilevel Methods in Lubrication",
Tribology Series 37, ch. 5 and 7) in Hertzian units (X = x/a, P = p/p_h, H = h R/a^2):

    L_ij = [eps_(i-1/2,j)(P_(i-1,j) - P_ij) + eps_(i+1/2,j)(P_(i+1,j) - P_ij)] / hx^2
         + [eps_(i,j-1/2)(P_(i,j-1) - P_ij) + eps_(i,j+1/2)(P_(i,j+1) - P_ij)] / hy^2
         - D_X(rho H)_ij = f_ij,

eps = rho H^3 / (eta lam_bar) at the nodes, face values the mean of the two nodes, and the
wedge term D_X upwinded (first order, (Q_ij - Q_(i-1,j)) / hx, Venner & Lubrecht's
standard scheme; ``wedge='second'`` takes the second-order upstream difference
(3 Q_ij - 4 Q_(i-1,j) + Q_(i-2,j)) / (2 hx) used with defect correction in their ch. 8).
H = H0 + X^2/2 + lambda Y^2/2 + sum K P (piecewise-constant cell influence coefficients,
the DC-FFT of :mod:`femgear.physics.ehl.core.elastic`), load hx hy sum P = 2 pi / 3. Cavitation is
the complementarity P >= 0, f - L >= 0, P (f - L) = 0. ``f`` and the load target are the
FAS right-hand sides (0 and the load on the finest grid).

Arrays are (ny, nx) with the boundary rows and columns at P = 0; operators return the
interior (ny - 2, nx - 2) block. The spacings hx, hy enter every stencil separately; the
deflection kernel is that of hx x hy cells (:mod:`femgear.physics.ehl.core.elastic`).
"""

from __future__ import annotations

import numpy as np

from femgear.physics.ehl.core.elastic import point_deflection
from femgear.physics.ehl.core.grid import Grid
from femgear.physics.ehl.core.rheology import Rheology


class FDLevel:
    """Grid, film and FD Reynolds operator of one multigrid level."""

    def __init__(self, grid: Grid, rheology: Rheology, lam_bar: float, load: float, *,
                 ratio: float = 1.0, rigid: bool = False, wedge: str = "first"):
        if wedge not in ("first", "second"):
            raise ValueError(f"wedge must be 'first' or 'second', not {wedge!r}")
        self.grid, self.rheology, self.lam_bar, self.load = grid, rheology, lam_bar, load
        self.rigid, self.wedge = rigid, wedge
        self.nx, self.ny = grid.nx, grid.ny
        self.hx, self.hy = grid.h, grid.dy
        self.X, self.Y = np.meshgrid(grid.x, grid.y)
        self.geometry = 0.5 * self.X**2 + 0.5 * ratio * self.Y**2
        self.defl = point_deflection(grid.nx, grid.ny, grid.h, grid.dy)
        self.K = np.zeros_like(self.defl.K) if rigid else self.defl.K  # [dy, dx] offsets >= 0
        self.cell = self.hx * self.hy

    # -- state ----------------------------------------------------------------------------
    def film(self, P: np.ndarray, H0: float) -> np.ndarray:
        if self.rigid:
            return H0 + self.geometry
        return H0 + self.geometry + self.defl.apply(P)

    def coefficients(self, P: np.ndarray, H: np.ndarray):
        """eps and rho at the nodes."""
        eps = self.rheology.epsilon(P, H, self.lam_bar)[0]
        return eps, self.rheology.density(P)[0]

    def load_of(self, P: np.ndarray) -> float:
        return float(self.cell * P.sum())

    # -- operator -------------------------------------------------------------------------
    def faces(self, eps: np.ndarray, rows: np.ndarray | None = None):
        """Face coefficients (west, east, south, north) / h^2 of the interior nodes (of the
        interior rows ``rows`` only, when given)."""
        j = slice(1, -1) if rows is None else rows + 1
        jm = slice(None, -2) if rows is None else rows
        jp = slice(2, None) if rows is None else rows + 2
        c = eps[j, 1:-1]
        return ((eps[j, :-2] + c) / (2 * self.hx**2), (eps[j, 2:] + c) / (2 * self.hx**2),
                (eps[jm, 1:-1] + c) / (2 * self.hy**2), (eps[jp, 1:-1] + c) / (2 * self.hy**2))

    def wedge_term(self, Q: np.ndarray) -> np.ndarray:
        """Upwind D_X Q at the interior nodes of the rows of ``Q`` (full rows)."""
        first = (Q[:, 1:-1] - Q[:, :-2]) / self.hx
        if self.wedge == "first":
            return first
        out = first.copy()
        out[:, 1:] = (3 * Q[:, 2:-1] - 4 * Q[:, 1:-2] + Q[:, :-3]) / (2 * self.hx)
        return out

    def operator(self, P: np.ndarray, H: np.ndarray, eps: np.ndarray, rho: np.ndarray,
                 rows: np.ndarray | None = None, faces=None) -> np.ndarray:
        """L at the interior nodes (of the interior rows ``rows`` only, when given)."""
        w, e, s, n = self.faces(eps, rows) if faces is None else faces
        j = slice(1, -1) if rows is None else rows + 1
        jm = slice(None, -2) if rows is None else rows
        jp = slice(2, None) if rows is None else rows + 2
        Pc = P[j, 1:-1]
        lap = (w * (P[j, :-2] - Pc) + e * (P[j, 2:] - Pc)
               + s * (P[jm, 1:-1] - Pc) + n * (P[jp, 1:-1] - Pc))
        return lap - self.wedge_term(rho[j] * H[j])

    def residual(self, P: np.ndarray, H0: float, f: np.ndarray):
        """(f - L) on the interior, the film H and (eps, rho)."""
        H = self.film(P, H0)
        eps, rho = self.coefficients(P, H)
        return f - self.operator(P, H, eps, rho), H, eps, rho

    def complementarity(self, P: np.ndarray, r: np.ndarray) -> np.ndarray:
        """The residual with the cavitated nodes (P = 0 and f - L >= 0) set to 0."""
        return np.where((P[1:-1, 1:-1] <= 0.0) & (r >= 0.0), 0.0, r)

    def wedge_weights(self) -> tuple[tuple[int, float], ...]:
        """The upwind difference as (offset, weight / hx) pairs: D_X Q_i = sum w Q_(i+o)."""
        if self.wedge == "first":
            return ((0, 1.0 / self.hx), (-1, -1.0 / self.hx))
        return ((0, 1.5 / self.hx), (-1, -2.0 / self.hx), (-2, 0.5 / self.hx))


def restrict_full_weighting(r: np.ndarray) -> np.ndarray:
    """Full weighting of an interior field (fine interior (2m-1, 2n-1) -> coarse (m-1, n-1)).

    The fine residual is padded with its zero boundary; coarse node (J, I) gathers
    (4 centre + 2 edge neighbours + 1 corner neighbours) / 16 (Brandt 1977; Trottenberg,
    Oosterlee & Schueller 2001, sec. 2.3)."""
    f = np.pad(r, 1)
    c = f[2:-2:2, 2:-2:2]
    edge = f[1:-3:2, 2:-2:2] + f[3:-1:2, 2:-2:2] + f[2:-2:2, 1:-3:2] + f[2:-2:2, 3:-1:2]
    corner = f[1:-3:2, 1:-3:2] + f[1:-3:2, 3:-1:2] + f[3:-1:2, 1:-3:2] + f[3:-1:2, 3:-1:2]
    return (4 * c + 2 * edge + corner) / 16.0


def inject(P: np.ndarray) -> np.ndarray:
    """Fine node field (2m-1, 2n-1) -> coarse (m, n) by injection."""
    return P[::2, ::2].copy()


def prolong_bilinear(u: np.ndarray) -> np.ndarray:
    """Coarse node field (m, n) -> fine (2m-1, 2n-1), bilinear interpolation."""
    m, n = u.shape
    out = np.empty((2 * m - 1, 2 * n - 1))
    out[::2, ::2] = u
    out[::2, 1::2] = 0.5 * (u[:, :-1] + u[:, 1:])
    out[1::2, :] = 0.5 * (out[:-2:2, :] + out[2::2, :])
    return out


def prolong_cubic(u: np.ndarray) -> np.ndarray:
    """Coarse node field -> fine, tensor cubic (4-point Lagrange, (-1, 9, 9, -1)/16) inside,
    linear next to the boundary: the FMG interpolation (Venner & Lubrecht 2000, ch. 3)."""

    def along(v: np.ndarray) -> np.ndarray:  # last axis
        n = v.shape[-1]
        out = np.empty(v.shape[:-1] + (2 * n - 1,))
        out[..., ::2] = v
        mid = 0.5 * (v[..., :-1] + v[..., 1:])
        if n >= 4:
            mid[..., 1:-1] = (-v[..., :-3] + 9 * v[..., 1:-2] + 9 * v[..., 2:-1] - v[..., 3:]) / 16
        out[..., 1::2] = mid
        return out

    return along(along(u).swapaxes(0, 1)).swapaxes(0, 1)
