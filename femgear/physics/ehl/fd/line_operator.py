"""Finite-difference line-contact EHL operator on one (graded) grid: residual and Jacobian.

Venner & Lubrecht's (2000, *Multilevel Methods in Lubrication*, Tribology Series 37, ch. 5)
discretisation of the steady line contact in Hertzian units (X = x/b, P = p/p_h,
H = h R/b^2), written for the non-uniform nodes X_i of :mod:`femgear.physics.ehl.fd.line_grid`
(P = 0 at both ends), at each interior node i:

    L_i = [eps_(i+1/2) (P_(i+1) - P_i) / h_(i+1/2) - eps_(i-1/2) (P_i - P_(i-1)) / h_(i-1/2)] / d_i
          - D_X(rho H)_i,

eps = rho H^3 / (eta lam_bar) at the nodes, face values the mean of the two nodes,
h_(i+1/2) = X_(i+1) - X_i, d_i = (h_(i-1/2) + h_(i+1/2))/2, D_X the second-order upstream
difference through X_(i-2), X_(i-1), X_i (the three-point Lagrange derivative; (3 Q_i -
4 Q_(i-1) + Q_(i-2)) / (2 h) on a uniform grid; first order next to the inlet boundary),
H = H0 + X^2/2 - R_s + D[P] with D the log-kernel deflection of the piecewise-linear P
(:func:`femgear.physics.ehl.core.elastic.line_hat_kernel`), load sum d_i P_i = pi/2 (the
trapezoidal rule, the integral of that P).  No artificial diffusion: the upstream wedge is
the only stabilisation, and its truncation error is set by the derivatives of the film,
which are small in the Hertzian zone.  (The Galerkin scheme's O(h^2) diffusion acts on P
instead and dominates at heavy loads: at (M, L) = (1000, 4.3) its Hc moves 17 % from 1025
to 4097 uniform nodes, and halving the diffusion moves it 13 % at 1025.)

Residual as in :mod:`femgear.physics.ehl.fe.level` (the complementarity P >= 0, R >= 0,
P R = 0 with R = -L, in the NCP form min(P, s R), s a row scaling frozen per solve), so
that the damped semi-smooth Newton of :mod:`femgear.physics.ehl.fe.newton` drives it.  The
Jacobian is J = T + B K: T = dR/dP|_H and B = dR/dH|_P are banded (offsets -2..+1), K the
dense kernel.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from femgear.physics.ehl.core.elastic import line_hat_kernel
from femgear.physics.ehl.core.rheology import Rheology

OFFSETS = (-2, -1, 0, 1)  # the band of T and B: column node i + o of interior row i


@dataclass(frozen=True)
class LineJacobian:
    """Row-scaled Jacobian parts of the interior equations at one state.

    ``T[o]``, ``B[o]`` (o in :data:`OFFSETS`): coefficient of P / H at node i + o in the row
    of interior node i (arrays over the m = n - 2 interior rows, i = 1..n-2; entries that
    would leave the grid are 0), multiplied by the row scaling and zeroed on the active
    (cavitated) rows; ``active`` those rows (identity rows of J); ``colH`` the H0 column
    (the sum of B)."""

    T: dict
    B: dict
    active: np.ndarray
    colH: np.ndarray


class FDLine:
    """Grid, film and FD Reynolds operator of one line-contact level: the interface of
    :class:`femgear.physics.ehl.fe.level.Level` that the Newton driver uses (``evaluate``,
    ``film``, ``full``, ``load``, ``m``, ``interior``, ``X``, ``Y``, ``n``, ``alpha_bar``).

    ``kernel``: K[:, interior] (all nodes x interior nodes) when the caller has it (the
    levels of a nested solve share it by grid): a dense array, or any operator with ``K @ v``
    (the HODLR :class:`femgear.physics.ehl.fd.line_hodlr.HKernel` of fine grids, whose
    Newton steps do not use :meth:`dense`); built here (dense) otherwise."""

    dim = 1

    def __init__(self, x: np.ndarray, rheology: Rheology, lam_bar: float, load: float,
                 surface: np.ndarray | None = None, kernel: np.ndarray | None = None):
        self.X = np.asarray(x, dtype=float)
        self.n = self.X.size
        if self.n < 5 or not np.all(np.diff(self.X) > 0):
            raise ValueError("a line level needs at least 5 increasing nodes")
        self.Y = np.zeros(self.n)
        self.rheology, self.lam_bar, self.load = rheology, lam_bar, load
        self.geometry = 0.5 * self.X**2 - (0.0 if surface is None else np.asarray(surface, dtype=float))
        self.interior = np.arange(1, self.n - 1)
        self.K = line_hat_kernel(self.X, cols=self.interior) if kernel is None else kernel
        hh = np.diff(self.X)
        self.h = float(hh.min())
        self.dual = 0.5 * (hh[:-1] + hh[1:])
        self.m = self.dual
        self._gw, self._ge = 0.5 / (hh[:-1] * self.dual), 0.5 / (hh[1:] * self.dual)
        h1, h2 = hh[1:-1], hh[:-2]                 # X_i - X_(i-1), X_(i-1) - X_(i-2) for i = 2..n-2
        self._c = {0: np.r_[1.0 / hh[0], (2 * h1 + h2) / (h1 * (h1 + h2))],
                   -1: np.r_[-1.0 / hh[0], -(h1 + h2) / (h1 * h2)],
                   -2: np.r_[0.0, h1 / (h2 * (h1 + h2))]}

    @property
    def alpha_bar(self) -> float:
        """alpha p_h of the rheology (the Newton step cap)."""
        return self.rheology.alpha_bar

    # -- state ---------------------------------------------------------------------------
    def full(self, PI: np.ndarray) -> np.ndarray:
        P = np.zeros(self.n)
        P[1:-1] = PI
        return P

    def deflection(self, P: np.ndarray) -> np.ndarray:
        return self.K @ P[1:-1]

    def film(self, PI: np.ndarray, H0: float) -> tuple[np.ndarray, np.ndarray]:
        return self.full(PI), H0 + self.geometry + self.K @ PI

    # -- operator ------------------------------------------------------------------------
    def wedge(self, Q: np.ndarray) -> np.ndarray:
        """Upstream D_X Q at the interior nodes."""
        c = self._c
        out = c[0] * Q[1:-1] + c[-1] * Q[:-2]
        out[1:] += c[-2][1:] * Q[:-3]
        return out

    def faces(self, eps: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The Poiseuille coefficients (a_w, a_e) of the interior rows."""
        return self._gw * (eps[:-2] + eps[1:-1]), self._ge * (eps[2:] + eps[1:-1])

    def reynolds(self, P: np.ndarray, H: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """R = -L at the interior nodes (R >= 0 where P = 0 at a solution) and a_w + a_e."""
        eps = self.rheology.epsilon(P, H, self.lam_bar)[0]
        rho = self.rheology.density(P)[0]
        aw, ae = self.faces(eps)
        Pc = P[1:-1]
        return self.wedge(rho * H) - (aw * (P[:-2] - Pc) + ae * (P[2:] - Pc)), aw + ae

    def evaluate(self, PI: np.ndarray, H0: float, s: np.ndarray | None = None):
        """Residual F (n_I + 1), the state (P, H) for the Jacobian, film H, scaling s and
        the active (cavitated) set.  s = d / (d (a_w + a_e) + 1): the FE row scaling of
        :class:`femgear.physics.ehl.fe.level.Level` for FD rows (d times smaller)."""
        P, H = self.film(PI, H0)
        R, diag = self.reynolds(P, H)
        if s is None:
            s = self.dual / (self.dual * diag + 1.0)
        sR = s * R
        active = PI <= sR
        F = np.empty(self.n - 1)
        F[:-1] = np.where(active, PI, sR)
        F[-1] = self.dual @ PI - self.load
        return F, (P, H), H, s, active

    def jacobian(self, state: tuple, s: np.ndarray, active: np.ndarray) -> LineJacobian:
        """The banded parts of the row-scaled Jacobian at ``state`` = (P, H)."""
        P, H = state
        rh = self.rheology
        eps, deps_P, deps_H = rh.epsilon(P, H, self.lam_bar)
        rho, drho = rh.density(P)
        gw, ge = self._gw, self._ge
        Pc = P[1:-1]
        dW, dE = gw * (P[:-2] - Pc), ge * (P[2:] - Pc)
        aw, ae = self.faces(eps)
        # R_i = wedge_i - [a_w (P_(i-1) - P_i) + a_e (P_(i+1) - P_i)]
        T = {-2: np.zeros(self.n - 2), -1: -aw - dW * deps_P[:-2], 0: aw + ae - (dW + dE) * deps_P[1:-1],
             1: -ae - dE * deps_P[2:]}
        B = {-2: np.zeros(self.n - 2), -1: -dW * deps_H[:-2], 0: -(dW + dE) * deps_H[1:-1], 1: -dE * deps_H[2:]}
        i = np.arange(1, self.n - 1)
        for o, c in self._c.items():
            j = np.maximum(i + o, 0)
            T[o] = T[o] + c * drho[j] * H[j]
            B[o] = B[o] + c * rho[j]
        keep = np.where(active, 0.0, s)
        T = {o: v * keep for o, v in T.items()}
        B = {o: v * keep for o, v in B.items()}
        return LineJacobian(T=T, B=B, active=active, colH=sum(B.values()))

    def band_rows(self, jac: LineJacobian, M: np.ndarray) -> np.ndarray:
        """sum_o B[o] M[i + o] over the interior rows i: B applied to a matrix (or vector)
        ``M`` given on all nodes."""
        n = self.n
        out = np.zeros((n - 2,) + M.shape[1:])
        for o, b in jac.B.items():
            lo = 1 + o
            if lo < 0:      # o = -2 at i = 1 reads node -1: its coefficient is 0
                out[1:] += _col(b[1:], M) * M[: n - 3]
            else:
                out += _col(b, M) * M[lo: lo + n - 2]
        return out

    def matvec(self, jac: LineJacobian, v: np.ndarray) -> np.ndarray:
        """J v for v = (dP_I, dH0): the bordered system with the load row."""
        vP = v[:-1]
        full = self.full(vP)
        r = self.band_rows(jac, self.K @ vP) + jac.colH * v[-1]
        n = self.n
        for o, t in jac.T.items():
            lo = 1 + o
            if lo < 0:
                r[1:] += t[1:] * full[: n - 3]
            else:
                r += t * full[lo: lo + n - 2]
        r[jac.active] = vP[jac.active]
        return np.r_[r, self.dual @ vP]

    def dense(self, jac: LineJacobian) -> np.ndarray:
        """The bordered Jacobian as a dense (m + 1)^2 matrix."""
        m = self.n - 2
        J = np.empty((m + 1, m + 1))
        J[:m, :m] = self.band_rows(jac, self.K)
        r = np.arange(m)
        for o, t in jac.T.items():
            c = r + o                       # interior column index of node i + o
            ok = (c >= 0) & (c < m)
            J[r[ok], c[ok]] += t[ok]
        J[:m, m] = jac.colH
        ia = np.nonzero(jac.active)[0]
        J[ia, :] = 0.0
        J[ia, ia] = 1.0
        J[m, :m] = self.dual
        J[m, m] = 0.0
        return J


def _col(b: np.ndarray, M: np.ndarray) -> np.ndarray:
    return b if M.ndim == 1 else b[:, None]
