"""Galerkin (Q1 / P1) Reynolds equation with isotropic artificial diffusion.

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

Stretched cells (h along X, hy = k h along Y, slender elliptic contacts): Pe and eps_art
are built on h (the transport runs along X) and the diffusion along Y is k eps_art
(beta rho h hy xi / 2, the geometric mean of the two cell sizes). Measured at (M, L) =
(100, 10), 129^2 nodes: with 1 eps_art along Y (isotropic) the Y-only modes of the
high-pressure zone are weakly damped and Newton takes 11 steps (lambda = 0.1); with
k^2 eps_art (isotropic in cell-scaled coordinates) also 11 steps and Hc 0.6 % low against
square cells (lambda = 0.2); with k eps_art 6 steps and Hc within 0.1 % of square cells.
The consistency error stays O(h hy), second order under refinement.

Assembly.  The grid is uniform, so every element has the same reference tables (basis
values and gradients at the 2 x 2 (Q1) or 2 (P1) Gauss points, scikit-fem's intorder-2
rule and node/point order): the element matrices are einsum products of the
quadrature-point coefficients with constant tables, summed into a CSR pattern fixed at
construction (:class:`femgear.physics.ehl.fe.stencil.UniformElements`); the same Q1/P1 Galerkin
matrices as scikit-fem's assembly (tested to round-off), about ten times faster, which
matters because the operator is rebuilt at every Newton trial.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp

from femgear.physics.ehl.core.grid import Grid
from femgear.physics.ehl.core.rheology import Rheology
from femgear.physics.ehl.fe.stencil import UniformElements

BETA_SELF = 2.0 / np.pi**2 * 4.0 * np.log1p(np.sqrt(2.0))  # K_00 / h for the point kernel


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
    ``basis.interpolate(u)`` gives nodal values at the quadrature points (elements x
    points), the layout the rheology receives there.
    """

    def __init__(self, rheology: Rheology, lam_bar: float, grid: Grid | None = None,
                 x: np.ndarray | None = None, beta: float = BETA_SELF,
                 ad_factor: float = 1.0, sd_factor: float = 0.0):
        self.rheology, self.lam_bar = rheology, lam_bar
        self.beta, self.ad_factor, self.sd_factor = beta, ad_factor, sd_factor
        if grid is not None:
            self.basis = UniformElements.quad(grid.nx, grid.ny, grid.h, grid.hy)
            self.h, self.dim = grid.h, 2
            # stretched cells hy = k h: the diffusion along Y is scaled by k (module docstring)
            self.ad_y = None if grid.hy is None else grid.hy / grid.h
        else:
            x = np.asarray(x, dtype=float)
            self.basis = UniformElements.line(x.size, float(x[1] - x[0]))
            self.h, self.dim = float(x[1] - x[0]), 1
            self.ad_y = None
        e = self.basis
        self.mass = e.load()  # int phi_i (= h^dim inside)
        self._wedge = -e.products(e.phi, e.grad[0])  # (W Q)_i = -int Q dphi_i/dX
        self.W = e.matrix(np.broadcast_to(self._wedge, (e.ne,) + self._wedge.shape))

    def residual(self, P: np.ndarray, H: np.ndarray) -> np.ndarray:
        """R = A P + W Q alone (no Jacobian): the operator's cheapest evaluation, the
        work unit of the benchmarks; equals ``linearize(P, H).R``."""
        e, rh = self.basis, self.rheology
        Pe, He = P[e.T], H[e.T]
        Pq = e.at_points(Pe)
        eps, _, _ = rh.epsilon(Pq, e.at_points(He), self.lam_bar)
        rho_q, _ = rh.density(Pq)
        xi, _ = upwind_weight(self.beta * rho_q * self.h**2 / (2.0 * np.maximum(eps, 1e-300)))
        art = self.ad_factor * 0.5 * self.beta * rho_q * self.h**2 * xi
        if self.ad_y is None:
            c = (eps + art) * e.w
            flux = sum((c * e.grad_at_points(Pe, d)) @ e.grad[d] for d in range(self.dim))
        else:
            flux = sum(((eps + art * s) * e.w * e.grad_at_points(Pe, d)) @ e.grad[d]
                       for d, s in enumerate((1.0, self.ad_y)))
        Q = rh.density(P)[0] * H
        R = e.scatter(flux) + self.W @ Q
        if self.sd_factor > 0.0 and self.beta > 0.0:
            delta = self.sd_factor * 0.5 * self.h * xi * e.w
            R += e.scatter((delta * e.grad_at_points(Q[e.T], 0)) @ e.grad[0])
        return R

    def linearize(self, P: np.ndarray, H: np.ndarray) -> Linearization:
        e, rh = self.basis, self.rheology
        Pe, He = P[e.T], H[e.T]  # (ne, npe)
        Pq, Hq = e.at_points(Pe), e.at_points(He)
        eps, deps_P, deps_H = rh.epsilon(Pq, Hq, self.lam_bar)
        rho_q, _ = rh.density(Pq)
        Pe_ = self.beta * rho_q * self.h**2 / (2.0 * np.maximum(eps, 1e-300))
        xi, p2xi = upwind_weight(Pe_)
        eps_art = self.ad_factor * 0.5 * self.beta * rho_q * self.h**2 * xi
        g = 1.0 - self.ad_factor * p2xi  # d(eps + eps_art)/d eps
        rho, drho = rh.density(P)
        Q = rho * H
        gq = [e.grad_at_points(Pe, d) for d in range(self.dim)]
        # element matrices [e, test, trial]
        if self.ad_y is None:
            Ae = e.weighted(eps + eps_art, e.stiffness)
        else:
            Ae = (e.weighted(eps + eps_art, e.stiffness_d[0])
                  + e.weighted(eps + self.ad_y * eps_art, e.stiffness_d[1]))
        We = np.broadcast_to(self._wedge, Ae.shape)
        # streamline diffusion of Q (optional): delta = sd (h/2) xi(Pe), differentiated
        # through eps: d delta/d eps = -sd Pe^2 xi'(Pe) / (beta rho h)
        sd = self.sd_factor
        ax = g * gq[0]
        if sd > 0.0 and self.beta > 0.0:
            delta = sd * 0.5 * self.h * xi
            ddelta = -sd * p2xi / (self.beta * rho_q * self.h)
            We = We + e.weighted(delta, e.streamline)
            ax = ax + ddelta * e.grad_at_points(Q[e.T], 0)
        # d/dcoefficient terms: int phi_trial (a . grad phi_test)
        gy = g if self.ad_y is None else 1.0 - self.ad_y * self.ad_factor * p2xi
        ay = gy * gq[1] if self.dim == 2 else None
        EP = e.coef_grad(deps_P * ax, None if ay is None else deps_P * ay)
        EH = e.coef_grad(deps_H * ax, None if ay is None else deps_H * ay)
        Qe, dQe = Q[e.T], (drho * H)[e.T]
        R = e.scatter(np.einsum("eij,ej->ei", Ae, Pe) + np.einsum("eij,ej->ei", We, Qe))
        JP = e.matrix(Ae + EP + We * dQe[:, None, :])
        JH = e.matrix(EH + We * rho[e.T][:, None, :])
        diagA = e.scatter(np.einsum("eii->ei", Ae))
        return Linearization(R, JP, JH, np.abs(diagA))
