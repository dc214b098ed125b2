"""Galerkin (Q1 / P1) Reynolds equation with isotropic artificial diffusion (scikit-fem).

Hertzian dimensionless steady Reynolds equation (Venner & Lubrecht 2000, eq. 2.36):

    div(eps grad P) - d(rho H)/dX = 0,   eps = rho H^3 / (eta lam_bar),   P = 0 on the boundary.

Weak form, for every interior test function v (R = 0 at the solution):

    R(v) = int (eps + eps_art) grad P . grad v  -  int Q dv/dX,     Q = rho H (nodal, interpolated).

Stabilisation (Habchi 2008, isotropic artificial diffusion): where eps -> 0 the equation
becomes the transport equation dQ/dX = 0 and plain Galerkin is ill-conditioned (the
Newton corrections of P blow up, because d/dX K annihilates P-modes that vary in Y
only). Seen as transport of P, the wedge term has the local "velocity"
beta = rho dH/dP|_self = rho K_00 / h (K_00 the self-influence coefficient of a node's
cell; 0.714 for the point kernel). The optimal 1D artificial diffusion for the cell
Peclet number Pe = beta h / (2 eps) is

    eps_art = (beta h / 2) xi(Pe),   xi = coth(Pe) - 1/Pe   (Brooks & Hughes 1982).

Since beta = O(h), eps_art = O(h^2) and the consistency error vanishes at second order
under refinement; where Poiseuille flow dominates (the inlet, Pe << 1) eps_art ~ h^4/eps.
eps_art is a function of eps and is differentiated exactly (d eps_tot / d eps =
1 - Pe^2 xi'(Pe)), so Newton keeps its quadratic convergence. Coefficients are
evaluated at the quadrature points from the interpolated P and H; ``ad_factor``
scales eps_art (1 by default; the sensitivity of H_c to it is reported by the tests).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp
from skfem import Basis, BilinearForm, ElementLineP1, ElementQuad1, LinearForm, MeshLine, MeshQuad, asm
from skfem.helpers import dot, grad

from femgear.ehl.grid import Grid
from femgear.ehl.rheology import Rheology

BETA_SELF = 2.0 / np.pi**2 * 4.0 * np.log1p(np.sqrt(2.0))  # K_00 / h for the point kernel


@BilinearForm
def _diffusion(u, v, w):
    return w["c"] * dot(grad(u), grad(v))


@BilinearForm
def _coef_grad(u, v, w):
    # int u (a . grad v)
    return u * (w["ax"] * v.grad[0] + w["ay"] * v.grad[1])


@BilinearForm
def _streamline(u, v, w):
    return w["delta"] * u.grad[0] * v.grad[0]


@BilinearForm
def _wedge(u, v, w):
    return -u * v.grad[0]


@BilinearForm
def _coef_grad_1d(u, v, w):
    return u * w["ax"] * v.grad[0]


@LinearForm
def _unit(v, w):
    return v


def upwind_weight(Pe: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """xi(Pe) = coth(Pe) - 1/Pe and Pe^2 xi'(Pe), without overflow or cancellation."""
    Pe = np.minimum(np.abs(Pe), 1e12)
    small = Pe < 1e-2
    mid = (Pe >= 1e-2) & (Pe < 30.0)
    Ps = np.where(mid, Pe, 1.0)
    xi = np.where(small, Pe / 3.0 - Pe**3 / 45.0,
                  np.where(mid, 1.0 / np.tanh(Ps) - 1.0 / Ps, 1.0 - 1.0 / np.maximum(Pe, 30.0)))
    # Pe^2 xi' = 1 - Pe^2 / sinh^2(Pe)
    p2xi = np.where(small, Pe**2 / 3.0 - Pe**4 / 15.0,
                    np.where(mid, 1.0 - (Ps / np.sinh(Ps)) ** 2, 1.0))
    return xi, p2xi


@dataclass(frozen=True)
class Linearization:
    """Reynolds residual and its sparse partial derivatives at one state (grid order).

    ``R`` = A P + W Q (all nodes; rows of boundary nodes are ignored by the solver).
    ``JP`` = dR/dP|_H (local), ``JH`` = dR/dH|_P; the full Jacobian is JP + JH K.
    """

    R: np.ndarray
    JP: sp.csr_matrix
    JH: sp.csr_matrix
    eps_node_scale: np.ndarray  # |diag A| per node, for penalty scaling


class ReynoldsFE:
    """Q1 (point) or P1 (line) Reynolds operator on a uniform node grid.

    For point contacts ``grid`` is a :class:`Grid`; for line contacts pass ``x`` (1D
    uniform nodes) instead. Node numbering equals the grid's flat row-major order.
    """

    def __init__(self, rheology: Rheology, lam_bar: float, grid: Grid | None = None,
                 x: np.ndarray | None = None, beta: float = BETA_SELF,
                 ad_factor: float = 1.0, sd_factor: float = 0.0):
        self.rheology, self.lam_bar = rheology, lam_bar
        self.beta, self.ad_factor, self.sd_factor = beta, ad_factor, sd_factor
        if grid is not None:
            X, Y = grid.coords()
            ii, jj = np.meshgrid(np.arange(grid.nx - 1), np.arange(grid.ny - 1))
            n0 = (jj * grid.nx + ii).ravel()
            t = np.vstack([n0, n0 + 1, n0 + 1 + grid.nx, n0 + grid.nx])
            mesh = MeshQuad(np.vstack([X, Y]), t)
            self.basis = Basis(mesh, ElementQuad1(), intorder=2)
            self.h, self.dim = grid.h, 2
        else:
            mesh = MeshLine(np.asarray(x, dtype=float))
            self.basis = Basis(mesh, ElementLineP1(), intorder=2)
            self.h, self.dim = float(x[1] - x[0]), 1
        self.mass = asm(_unit, self.basis)  # int phi_i (= h^dim inside)
        self.W = asm(_wedge, self.basis).tocsr()  # (W Q)_i = -int Q dphi_i/dX

    def linearize(self, P: np.ndarray, H: np.ndarray) -> Linearization:
        b, rh = self.basis, self.rheology
        Pq, Hq = b.interpolate(P), b.interpolate(H)
        eps, deps_P, deps_H = rh.epsilon(np.asarray(Pq), np.asarray(Hq), self.lam_bar)
        rho_q, _ = rh.density(np.asarray(Pq))
        Pe = self.beta * rho_q * self.h**2 / (2.0 * np.maximum(eps, 1e-300))
        xi, p2xi = upwind_weight(Pe)
        eps_art = self.ad_factor * 0.5 * self.beta * rho_q * self.h**2 * xi
        g = 1.0 - self.ad_factor * p2xi  # d(eps + eps_art)/d eps
        A = asm(_diffusion, b, c=eps + eps_art)
        rho, drho = rh.density(P)
        Q = rho * H
        W = self.W
        # streamline diffusion of Q (optional): delta = sd (h/2) xi(Pe), differentiated
        # through eps: d delta/d eps = -sd Pe^2 xi'(Pe) / (beta rho h)
        sd = self.sd_factor
        if sd > 0.0 and self.beta > 0.0:
            delta = sd * 0.5 * self.h * xi
            ddelta = -sd * p2xi / (self.beta * rho_q * self.h)
            Qx = b.interpolate(Q).grad[0]
            W = W + asm(_streamline, b, delta=delta)
        else:
            ddelta, Qx = 0.0, 0.0
        gx = Pq.grad[0]
        if self.dim == 2:
            gy = Pq.grad[1]
            EP = asm(_coef_grad, b, ax=deps_P * (g * gx + ddelta * Qx), ay=deps_P * g * gy)
            EH = asm(_coef_grad, b, ax=deps_H * (g * gx + ddelta * Qx), ay=deps_H * g * gy)
        else:
            EP = asm(_coef_grad_1d, b, ax=deps_P * (g * gx + ddelta * Qx))
            EH = asm(_coef_grad_1d, b, ax=deps_H * (g * gx + ddelta * Qx))
        R = A @ P + W @ Q
        JP = (A + EP + W @ sp.diags(drho * H)).tocsr()
        JH = (EH + W @ sp.diags(rho)).tocsr()
        return Linearization(R, JP, JH, np.abs(A.diagonal()))
