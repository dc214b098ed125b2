"""Plane linear elasticity on a skfem mesh with a pyamg smoothed-aggregation solver.

:class:`ElasticProblem` assembles K once per mesh, condenses the Dirichlet DOFs and
builds the pyamg hierarchy once (rigid-body modes as near-null space, ``splu``
coarse solver — see notes/stack.md), then solves any number of load cases with
preconditioned CG.  Non-convergence raises :class:`femgear.errors.ConvergenceError`
with the residual history.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field

import numpy as np

from femgear.errors import ConvergenceError
from femgear.physics.body.forms import elasticity, lame, normal_penalty


def rigid_body_modes(basis) -> np.ndarray:
    """The three plane rigid-body modes (x, y translation; rotation) as DOF vectors."""
    ix, iy = basis.split_indices()
    x, y = basis.doflocs
    B = np.zeros((basis.N, 3))
    B[ix, 0] = 1.0
    B[iy, 1] = 1.0
    B[ix, 2] = -y[ix]
    B[iy, 2] = x[iy]
    return B


def _thin_part(basis, lam: float, mu: float, stress: tuple[float, float], mask: np.ndarray, thickness: float):
    """Per-element Lamé constants (n_elements, n_quadrature points): (λ, μ) outside ``mask``, ``thickness`` times
    the plane-stress ``stress`` = (λ*, μ) inside it."""
    mask = np.asarray(mask, bool)
    if mask.shape != (basis.mesh.t.shape[1],):
        raise ValueError(f"thin: the mask needs one entry per element ({basis.mesh.t.shape[1]}), got {mask.shape}")
    if not 0 < thickness <= 1:
        raise ValueError(f"thin: the relative thickness must lie in (0, 1], got {thickness!r}")
    ones = np.ones((1, basis.X.shape[1]))
    return (np.where(mask, thickness * stress[0], lam)[:, None] * ones,
            np.where(mask, thickness * stress[1], mu)[:, None] * ones)


@dataclass
class SolveInfo:
    iterations: int
    residual: float
    seconds: float
    history: list = field(default_factory=list)


class ElasticProblem:
    """K u = f on ``mesh`` with P2 (default) vector elements.

    ``fixed`` maps DOF indices to prescribed values (dict or (idx, values));
    ``rollers`` names boundaries with zero normal displacement (penalty κ = 1e4 E/h).
    ``thin`` = (element mask, relative thickness t): those elements are a thinner part of the section, a web
    between a rim and its hub, in plane stress with t times the stiffness (a 2-D model of a disc of varying
    thickness: the in-plane stiffness per unit area is the thickness times the plane-stress one).
    The hierarchy (``solver='amg'``) or the sparse LU factors (``solver='lu'``, for 2-D
    problems with many load cases) are built lazily on the first solve and reused.
    """

    def __init__(self, mesh, youngs_modulus: float, poisson_ratio: float, plane: str,
                 order: int = 2, rollers: tuple[str, ...] = (), penalty: float = 1e4, solver: str = "amg",
                 thin: tuple[np.ndarray, float] | None = None):
        from skfem import Basis, ElementTriP1, ElementTriP2, ElementVector, FacetBasis

        if solver not in ("amg", "lu"):
            raise ValueError(f"solver must be 'amg' or 'lu', got {solver!r}")
        t0 = time.perf_counter()
        self.solver = solver
        self.mesh = mesh
        self.E, self.nu, self.plane = youngs_modulus, poisson_ratio, plane
        elem = ElementTriP2() if order == 2 else ElementTriP1()
        self.order = order
        self.basis = Basis(mesh, ElementVector(elem))
        lam, mu = lame(youngs_modulus, poisson_ratio, plane)
        if thin is not None:
            lam, mu = _thin_part(self.basis, lam, mu, lame(youngs_modulus, poisson_ratio, "stress"), *thin)
        K = elasticity(lam, mu).assemble(self.basis)
        if rollers:
            facets = np.concatenate([mesh.boundaries[name] for name in rollers])
            fb = FacetBasis(mesh, self.basis.elem, facets=facets)
            h = float(np.mean(mesh.param()))
            K = K + normal_penalty.assemble(fb, kappa=penalty * youngs_modulus / h)
        self.K = K.tocsr()
        self.assembly_seconds = time.perf_counter() - t0
        self._D = np.zeros(0, dtype=np.int64)
        self._uD = np.zeros(0)
        self._ml = None
        self._C = None

    # ---- constraints ----
    def fix(self, dofs: np.ndarray, values: np.ndarray | float = 0.0) -> None:
        """Prescribe ``values`` at ``dofs`` (drops any hierarchy already built)."""
        dofs = np.asarray(dofs, dtype=np.int64)
        vals = np.broadcast_to(np.asarray(values, float), dofs.shape)
        keep = ~np.isin(self._D, dofs)
        self._D = np.concatenate([self._D[keep], dofs])
        self._uD = np.concatenate([self._uD[keep], vals])
        self._ml = None

    def tie(self, name: str) -> None:
        """Hold the mean rigid motion of boundary ``name`` at zero: ∫ u_x ds = ∫ u_y ds = ∫ (x u_y − y u_x) ds = 0
        (Lagrange multipliers; ``solver='lu'``).  The distributing coupling of FE codes (an RBE3 element): the
        boundary carries the body's reactions as a uniform force and a uniform shear flow and deforms freely
        otherwise — a rim on a flexible web or hub, where clamping (:meth:`fix`) is a rim on a rigid shaft."""
        from skfem import FacetBasis, LinearForm

        if self.solver != "lu":
            raise ValueError("tie needs solver='lu' (a bordered, indefinite system)")
        fb = FacetBasis(self.mesh, self.basis.elem, facets=self.mesh.boundaries[name])

        @LinearForm
        def tx(v, w):
            return v[0]

        @LinearForm
        def ty(v, w):
            return v[1]

        @LinearForm
        def rot(v, w):
            return w.x[0] * v[1] - w.x[1] * v[0]

        self._C = np.vstack([form.assemble(fb) for form in (tx, ty, rot)])
        self._ml = None

    def boundary_dofs(self, name: str, component: str | None = None) -> np.ndarray:
        dofs = self.basis.get_dofs(self.mesh.boundaries[name])
        if component is None:
            return dofs.flatten()
        return dofs.flatten()[np.isin(dofs.flatten(), self.basis.split_indices()["xy".index(component)])]

    def nearest_dof(self, point, component: str) -> int:
        idx = self.basis.split_indices()["xy".index(component)]
        d = np.hypot(self.basis.doflocs[0, idx] - point[0], self.basis.doflocs[1, idx] - point[1])
        return int(idx[np.argmin(d)])

    # ---- solve ----
    def _hierarchy(self):
        import pyamg

        t0 = time.perf_counter()
        free = np.setdiff1d(np.arange(self.basis.N), self._D)
        self._free = free
        Kff = self.K[free][:, free].tocsr()
        self._Kff = Kff
        self._KfD = self.K[free][:, self._D].tocsr()
        if self.solver == "lu" and self._C is not None:
            from scipy.sparse import bmat, csr_matrix
            from scipy.sparse.linalg import splu

            Cf = csr_matrix(self._C[:, free])
            self._ml = splu(bmat([[Kff, Cf.T], [Cf, None]]).tocsc())
        elif self.solver == "lu":
            from scipy.sparse.linalg import splu

            self._ml = splu(Kff.tocsc())
        else:
            B = rigid_body_modes(self.basis)[free]
            self._ml = pyamg.smoothed_aggregation_solver(Kff, B=B, coarse_solver="splu", max_coarse=500)
        self.setup_seconds = time.perf_counter() - t0

    def solve(self, f: np.ndarray, tol: float = 1e-10, maxiter: int = 400, case: str = "elasticity") -> tuple[np.ndarray, SolveInfo]:
        """Displacement DOF vector for load vector ``f`` [N]; raises ConvergenceError."""
        if self._ml is None:
            self._hierarchy()
        t0 = time.perf_counter()
        rhs = f[self._free] - self._KfD @ self._uD
        hist: list[float] = []
        if self.solver == "lu" and self._C is not None:
            n_c = self._C.shape[0]
            xl = self._ml.solve(np.concatenate([rhs, -self._C[:, self._D] @ self._uD]))
            x, lagrange = xl[:-n_c], xl[-n_c:]
            r0 = np.linalg.norm(rhs)
            hist = [r0, np.linalg.norm(self._Kff @ x + self._C[:, self._free].T @ lagrange - rhs)]
        elif self.solver == "lu":
            x = self._ml.solve(rhs)
            r0 = np.linalg.norm(rhs)
            hist = [r0, np.linalg.norm(self._Kff @ x - rhs)]
        else:
            x = self._ml.solve(rhs, tol=tol, accel="cg", maxiter=maxiter, residuals=hist)
        res = hist[-1] / max(hist[0], 1e-300) if hist else 0.0
        if not np.all(np.isfinite(x)) or res > tol * 10:
            raise ConvergenceError(case, f"pyamg CG did not reach tol={tol:g}", {"residual": hist})
        u = np.zeros(self.basis.N)
        u[self._free] = x
        u[self._D] = self._uD
        return u, SolveInfo(len(hist) - 1, res, time.perf_counter() - t0, hist)

    @property
    def ndofs(self) -> int:
        return self.basis.N
