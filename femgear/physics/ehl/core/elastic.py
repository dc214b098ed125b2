"""Elastic deflection of the equivalent half-space in Hertzian dimensionless form.

Point contact (Venner & Lubrecht 2000, eq. 2.37): with X = x/a, P = p/p_h,
H = h R/a^2 the deflection is

    D(X, Y) = (2/pi^2) iint P(X', Y') / sqrt((X-X')^2 + (Y-Y')^2) dX' dY'.

P is taken piecewise constant on the cell h x h centred at each node (or hx x hy on a
stretched grid for slender elliptic contacts); the cell integral of 1/r over a rectangle
has a closed form (Love 1929; Johnson, Contact Mechanics, 1985, 3.25): with the corner
offsets a, b = dx +/- hx/2 and c, d = dy +/- hy/2 it is F(a,c) - F(a,d) - F(b,c) + F(b,d),
F the antiderivative below (tested against brute-force quadrature, tests/ehl/test_elliptic.py).
The discrete convolution over the node grid is evaluated with DC-FFT (Liu, Wang & Liu,
Wear 243 (2000) 101): the kernel for offsets -(n-1)..(n-1) is wrapped into a 2n
array, P is zero-padded to 2n, and the circular convolution then equals the linear
one exactly. Cost O(n log n).

Line contact (Venner & Lubrecht 2000, eq. 2.14): X = x/b,
D(X) = -(1/pi) int ln|X - X'| P(X') dX', with piecewise-constant P per node cell.
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np
import scipy.fft as sfft
import scipy.sparse as sp


def _F(x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """Antiderivative of 1/r: d^2F/dxdy = 1/sqrt(x^2+y^2) (F = x asinh(y/|x|) + y asinh(x/|y|))."""
    with np.errstate(divide="ignore", invalid="ignore"):
        t1 = np.where(x != 0.0, x * np.arcsinh(y / np.abs(np.where(x != 0.0, x, 1.0))), 0.0)
        t2 = np.where(y != 0.0, y * np.arcsinh(x / np.abs(np.where(y != 0.0, y, 1.0))), 0.0)
    return t1 + t2


def cell_influence(dx: np.ndarray, dy: np.ndarray, h: float, hy: float | None = None) -> np.ndarray:
    """(2/pi^2) * integral of 1/r over the h x hy cell (hy = h: square) centred at offset (dx, dy)."""
    hy = h if hy is None else hy
    a, b = dx + h / 2, dx - h / 2
    c, d = dy + hy / 2, dy - hy / 2
    val = _F(a, c) - _F(a, d) - _F(b, c) + _F(b, d)
    return (2.0 / np.pi**2) * val


class PointDeflection:
    """DC-FFT deflection operator on an (ny, nx) node grid with spacing h (along x) and
    hy along y (None: square cells, hy = h).

    ``apply(P2d)`` returns D on the same grid. ``dense(rows, cols)`` returns the matrix
    between flattened nodes (for the coarse-grid direct solves),
    ``local(r)`` the kernel truncated to offsets |i|,|j| <= r as a sparse matrix.
    """

    def __init__(self, nx: int, ny: int, h: float, hy: float | None = None):
        self.nx, self.ny, self.h = nx, ny, h
        self.hy = h if hy is None else hy
        ix = np.arange(nx) * h
        iy = np.arange(ny) * self.hy
        self.K = cell_influence(ix[None, :], iy[:, None], h, hy)  # (ny, nx), offsets >= 0
        # any period N >= 2n - 1 keeps the circular convolution linear on the grid; the
        # next 5-smooth length avoids 2 (16 2^k + 1) = 2 x prime sizes (514 = 2 x 257:
        # 82 ms per transform pair against 12 ms at 540)
        Ny, Nx = (sfft.next_fast_len(2 * m - 1, real=True) for m in (ny, nx))
        kw = np.zeros((Ny, Nx))
        kw[:ny, :nx] = self.K
        kw[Ny - ny + 1 :, :nx] = self.K[:0:-1, :]
        kw[:ny, Nx - nx + 1 :] = self.K[:, :0:-1]
        kw[Ny - ny + 1 :, Nx - nx + 1 :] = self.K[:0:-1, :0:-1]
        self._N = (Ny, Nx)
        self._khat = sfft.rfft2(kw)

    def apply(self, P2d: np.ndarray) -> np.ndarray:
        """D = K * P; the transforms skip the zero padding where they can (the x pass of
        the forward transform and of the inverse on the first ny rows only)."""
        ny, nx = self.ny, self.nx
        Ny, Nx = self._N
        f = sfft.fft(sfft.rfft(P2d, n=Nx, axis=1), n=Ny, axis=0)
        return sfft.irfft(sfft.ifft(f * self._khat, axis=0)[:ny], n=Nx, axis=1)[:, :nx]

    def dense(self, rows: np.ndarray, cols: np.ndarray | None = None) -> np.ndarray:
        """Dense influence matrix from the flattened grid nodes ``cols`` (default ``rows``)
        to the nodes ``rows``."""
        cols = rows if cols is None else cols
        j, i = np.divmod(rows, self.nx)
        jc, ic = np.divmod(cols, self.nx)
        return self.K[np.abs(j[:, None] - jc[None, :]), np.abs(i[:, None] - ic[None, :])]

    def local(self, flat_index: np.ndarray, r: int) -> sp.csr_matrix:
        """Influence matrix truncated to |di|, |dj| <= r between nodes ``flat_index``."""
        n = self.nx * self.ny
        pos = -np.ones(n, dtype=np.int64)
        pos[flat_index] = np.arange(flat_index.size)
        j, i = np.divmod(flat_index, self.nx)
        rows, cols, vals = [], [], []
        for dj in range(-r, r + 1):
            for di in range(-r, r + 1):
                jj, ii = j + dj, i + di
                ok = (jj >= 0) & (jj < self.ny) & (ii >= 0) & (ii < self.nx)
                tgt = pos[np.where(ok, jj * self.nx + ii, 0)]
                ok &= tgt >= 0
                rows.append(np.nonzero(ok)[0])
                cols.append(tgt[ok])
                vals.append(np.full(ok.sum(), self.K[abs(dj), abs(di)]))
        m = flat_index.size
        return sp.csr_matrix(
            (np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))), shape=(m, m)
        )


def line_influence(x: np.ndarray, h: float) -> np.ndarray:
    """Dense line-contact matrix: D_i = sum_j K_ij P_j, K_ij = -(1/pi) int_cell_j ln|x_i - s| ds."""

    def G(t: np.ndarray) -> np.ndarray:  # antiderivative of ln|t|
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.where(t != 0.0, t * np.log(np.abs(np.where(t != 0.0, t, 1.0))) - t, 0.0)

    d = x[:, None] - x[None, :]
    return -(G(d + h / 2) - G(d - h / 2)) / np.pi


def line_kernel_interior(x: np.ndarray, h: float) -> np.ndarray:
    """K[:, 1:-1] of :func:`line_kernel` (the columns of the interior nodes, where P is
    unknown) as a C-contiguous array, cached (read-only) like the kernel: the dense line
    Jacobian and its Newton-Krylov products use it at every step of a sequence."""
    if x.size > 2049:
        return np.ascontiguousarray(line_influence(x, h)[:, 1:-1])
    return _line_kernel_interior(int(x.size), float(h))


@lru_cache(maxsize=4)
def _line_kernel_interior(n: int, h: float) -> np.ndarray:
    K = np.ascontiguousarray(_line_kernel(n, h)[:, 1:-1])
    K.setflags(write=False)
    return K


@lru_cache(maxsize=4)
def _line_kernel(n: int, h: float) -> np.ndarray:
    K = line_influence(h * np.arange(n), h)  # depends on offsets only
    K.setflags(write=False)
    return K


def line_kernel(x: np.ndarray, h: float) -> np.ndarray:
    """:func:`line_influence` on uniform nodes, cached (read-only) for grids up to 2049
    nodes: a sequence of solves (a path, a map, a thermal loop) builds it once."""
    if x.size > 2049:
        return line_influence(x, h)
    return _line_kernel(int(x.size), float(h))


@lru_cache(maxsize=8)
def point_deflection(nx: int, ny: int, h: float, hy: float | None = None) -> PointDeflection:
    """Cached :class:`PointDeflection` (its kernel transform is built once per grid)."""
    return PointDeflection(nx, ny, h, hy)


def _log_integrals(t0: np.ndarray, t1: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """int_t0^t1 ln|u| du and int_t0^t1 u ln|u| du (closed forms, 0 ln 0 = 0)."""

    def F1(t):
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.where(t != 0.0, t * np.log(np.abs(np.where(t != 0.0, t, 1.0))) - t, 0.0)

    def F2(t):
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.where(t != 0.0, t * t * (0.5 * np.log(np.abs(np.where(t != 0.0, t, 1.0))) - 0.25), 0.0)

    return F1(t1) - F1(t0), F2(t1) - F2(t0)


def line_hat_kernel(X: np.ndarray, rows: np.ndarray | None = None, cols: np.ndarray | None = None) -> np.ndarray:
    """K[rows][:, cols] of the line deflection D_i = sum_j K_ij P_j on the (non-uniform,
    increasing) nodes X for piecewise-linear P (hat functions phi_j):
    K_ij = -(1/pi) int phi_j(s) ln|X_i - s| ds (Venner & Lubrecht 2000, eq. 2.14, with the
    linear interpolation of P; second order on any grid), in closed form: on an interval
    [a, b] the rising half of a hat gives (I1 + (x - a) I0)/(b - a) with I0, I1 the integrals
    of ln|u| and u ln|u| over [a - x, b - x].  Default: all nodes."""
    n = X.size
    rows = np.arange(n) if rows is None else np.asarray(rows)
    cols = np.arange(n) if cols is None else np.asarray(cols)
    x = X[rows][:, None]
    out = np.zeros((rows.size, cols.size))
    j = cols[None, :]
    for side in (-1, 1):                      # the interval left (rising) / right (falling) of node j
        ok = (j + side >= 0) & (j + side <= n - 1)
        jj = np.where(ok, j + side, j)
        a = np.where(side < 0, X[jj], X[j])   # [a, b] = [X_(j-1), X_j] or [X_j, X_(j+1)]
        b = np.where(side < 0, X[j], X[jj])
        length = np.where(ok, b - a, 1.0)
        out += np.where(ok, half_hat_integral(x, a, b, length, side), 0.0)
    return -out / np.pi


def half_hat_integral(x, a, b, length, side: int):
    """int phi ln|x - s| ds over [a, b] (closed form) for the rising (``side`` -1: (s - a)/length) or the falling
    (+1: (b - s)/length) half of a hat function."""
    I0, I1 = _log_integrals(a - x, b - x)
    rise = (I1 + (x - a) * I0) / length
    return rise if side < 0 else I0 - rise
