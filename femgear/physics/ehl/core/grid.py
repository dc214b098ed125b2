"""Structured node grids for the point- and line-contact problems.

The grid is uniform (spacing ``h``, square cells; or stretched, spacing ``h`` along X
and ``hy`` along Y, for slender elliptic contacts whose Y semi-axis is k = b/a times the
X one, so that the contact has as many nodes across it in Y as in X) so that the
DC-FFT deflection acts on the finite-element nodes directly. Levels double the number of intervals; level 0 has
``n0`` intervals along X. The skfem mesh (Q1 quads for point contact) and the
(ny, nx) array layout used by the FFT are linked by the permutation ``grid_of_dof``.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import scipy.sparse as sp


@dataclass(frozen=True)
class Domain:
    """Rectangular contact domain in Hertzian units (X = x/a, Y = y/a); ``aspect`` the cell
    aspect hy/hx of its grids (None: square cells)."""

    x0: float = -4.5
    x1: float = 1.5
    y0: float = -3.0
    y1: float = 3.0
    aspect: float | None = None

    def __post_init__(self) -> None:
        if not (self.x0 < 0.0 < self.x1 and self.y0 < 0.0 < self.y1):
            raise ValueError(f"domain must contain the origin: {self}")

    def scaled(self, s: float) -> Domain:
        return Domain(self.x0 * s, self.x1 * s, self.y0 * s, self.y1 * s, self.aspect)


@dataclass(frozen=True)
class Grid:
    """Uniform node grid x0 + i h (i = 0..nx-1), y0 + j hy (j = 0..ny-1); ``hy`` None:
    square cells (hy = h)."""

    x0: float
    y0: float
    h: float
    nx: int
    ny: int
    x: np.ndarray = field(repr=False, compare=False)
    y: np.ndarray = field(repr=False, compare=False)
    hy: float | None = None

    @property
    def dy(self) -> float:
        """The spacing along Y (h on square cells)."""
        return self.h if self.hy is None else self.hy

    @staticmethod
    def build(domain: Domain, level: int, n0: int = 16, aspect: float | None = None) -> Grid:
        """Level ``level`` grid: ``n0 * 2**level`` intervals on [x0, x1]; Y snapped to hy,
        hy = ``aspect`` h (None: square cells)."""
        if level < 0:
            raise ValueError("level must be >= 0")
        aspect = domain.aspect if aspect is None else aspect
        if aspect is not None and not (aspect > 0 and np.isfinite(aspect)):
            raise ValueError(f"aspect must be positive and finite, got {aspect!r}")
        nix = n0 * 2**level
        h0 = (domain.x1 - domain.x0) / n0
        h = h0 / 2**level
        hy0 = h0 if aspect is None else h0 * aspect
        hy = h if aspect is None else hy0 / 2**level
        # snap the Y bounds to multiples of the level-0 spacing about Y = 0, so that
        # Y = 0 is a grid line and the levels are nested
        j0 = int(np.floor(domain.y0 / hy0 + 1e-9)) * 2**level
        j1 = int(np.ceil(domain.y1 / hy0 - 1e-9)) * 2**level
        nx, ny = nix + 1, j1 - j0 + 1
        x = domain.x0 + h * np.arange(nx)
        y = j0 * hy + hy * np.arange(ny)
        return Grid(domain.x0, j0 * hy, h, nx, ny, x, y, None if aspect is None else hy)

    @property
    def n(self) -> int:
        return self.nx * self.ny

    def coords(self) -> tuple[np.ndarray, np.ndarray]:
        """Flattened (X, Y) of the grid nodes, row-major (j, i)."""
        X, Y = np.meshgrid(self.x, self.y)
        return X.ravel(), Y.ravel()

    def interior(self) -> np.ndarray:
        """Flat indices of the nodes not on the boundary."""
        j, i = np.divmod(np.arange(self.n), self.nx)
        return np.nonzero((i > 0) & (i < self.nx - 1) & (j > 0) & (j < self.ny - 1))[0]

    def mesh(self):
        """skfem MeshQuad and the permutation ``perm`` with mesh node k = grid node perm[k]."""
        from skfem import MeshQuad

        m = MeshQuad.init_tensor(self.x, self.y)
        i = np.rint((m.p[0] - self.x0) / self.h).astype(np.int64)
        j = np.rint((m.p[1] - self.y0) / self.dy).astype(np.int64)
        return m, j * self.nx + i


def prolongation_1d(nc: int) -> sp.csr_matrix:
    """Linear interpolation from nc nodes to 2 nc - 1 nodes."""
    nf = 2 * nc - 1
    rows, cols, vals = [], [], []
    for k in range(nf):
        if k % 2 == 0:
            rows.append(k), cols.append(k // 2), vals.append(1.0)
        else:
            rows += [k, k]
            cols += [k // 2, k // 2 + 1]
            vals += [0.5, 0.5]
    return sp.csr_matrix((vals, (rows, cols)), shape=(nf, nc))


def prolongation(coarse: Grid, fine: Grid) -> sp.csr_matrix:
    """Bilinear interpolation between nested grids (flat row-major node order)."""
    if fine.nx != 2 * coarse.nx - 1 or fine.ny != 2 * coarse.ny - 1:
        raise ValueError("grids are not nested by a factor 2")
    return sp.kron(prolongation_1d(coarse.ny), prolongation_1d(coarse.nx), format="csr")
