"""3-D linear elasticity on a tetrahedral skfem mesh, solved many times with one pyamg hierarchy.

:class:`Elastic3D` assembles K once (P1 or P2 vector tetrahedra, isotropic σ = 2μ ε +
λ tr ε I), clamps the named ``clamped`` region and builds one smoothed-aggregation
hierarchy with the six rigid-body modes as near-null space and a ``splu`` coarse
solver (notes/stack.md: the default ``pinv`` coarse solver is 30× slower with rigid
modes).  Every load case is then one preconditioned CG solve.

Two solvers (``solver``):

- ``"amg"``: the SA-CG solve costs one to two seconds per load case at 50–100 k DOF here
  (measured by ``studies/benchmarks/ltca.py``).  Non-convergence raises
  :class:`femgear.errors.ConvergenceError` with the residual history.
- ``"lu"``: one sparse factorisation (scipy's SuperLU) with the minimum-degree ordering of
  Kᵀ + K and symmetric mode (no pivoting off the diagonal: K is SPD), then every block of
  load cases is two triangular solves.  With the default COLAMD column ordering SuperLU had not
  finished a 65 k-DOF P1 tet matrix after 5 min; with MMD on Kᵀ + K a 58 k-DOF P1 member body
  factors in 26 s (83 M entries in L + U, ≈ 1 GB) and 63 load cases take 5 s together, against
  82 s of SA-CG (2 cores under load, 23 Nov 2026).  The factor's fill grows fast with P2, where
  the AMG stays.  A solution whose relative residual exceeds 1e-8 raises ConvergenceError.
  (CHOLMOD is not in the environment.)  ``"auto"``: ``lu`` for P1 up to :data:`LU_MAX_DOFS`
  free DOF (memory: ≈ 1 GB at 58 k DOF, a few GB at 140 k), ``amg`` otherwise.
"""

from __future__ import annotations

import time
from dataclasses import dataclass

import numpy as np

from femgear.errors import ConvergenceError

LU_MAX_DOFS = 160_000  #: ``solver="auto"``: the sparse LU up to this many free DOF (P1 only), SA-CG above


def _elasticity_form(lam: float, mu: float):
    from skfem import BilinearForm
    from skfem.helpers import ddot, eye, sym_grad, trace

    @BilinearForm
    def form(u, v, w):
        eps = sym_grad(u)
        return ddot(2.0 * mu * eps + lam * eye(trace(eps), 3), sym_grad(v))

    return form


def rigid_body_modes_3d(basis) -> np.ndarray:
    """Three translations and three rotations (about x, y, z) as DOF vectors, shape (N, 6)."""
    ix, iy, iz = basis.split_indices()
    x, y, z = basis.doflocs
    B = np.zeros((basis.N, 6))
    B[ix, 0] = B[iy, 1] = B[iz, 2] = 1.0
    B[iy, 3], B[iz, 3] = -z[iy], y[iz]           # rotation about x
    B[iz, 4], B[ix, 4] = -x[iz], z[ix]           # about y
    B[ix, 5], B[iy, 5] = -y[ix], x[iy]           # about z
    return B


@dataclass(frozen=True)
class SolveStats:
    """Cost of an :class:`Elastic3D` model (seconds, counts)."""

    ndofs: int
    assembly_seconds: float
    setup_seconds: float
    solve_seconds: float
    solves: int
    iterations: int        #: CG iterations of all solves together
    factor_nnz: int = 0    #: entries of L + U (``lu``; 0 for ``amg``): ≈ 12 bytes each in memory


class Elastic3D:
    """K u = f on a ``MeshTet`` with P``order`` vector elements, ``clamped`` region fixed.

    ``clamped`` None: no region is clamped; ``fixed`` (DOF indices) are held at zero besides it
    (e.g. a statically determinate support of a free body, :mod:`femgear.body.thermal3d`).
    """

    def __init__(self, mesh, youngs_modulus: float, poisson_ratio: float, order: int = 2,
                 clamped: str | None = "bore", tol: float = 1e-8, maxiter: int = 500, solver: str = "amg",
                 fixed=None):
        from skfem import Basis, ElementTetP1, ElementTetP2, ElementVector

        if order not in (1, 2):
            raise ValueError(f"order must be 1 or 2, got {order!r}")
        if solver not in ("amg", "lu", "auto"):
            raise ValueError(f"solver must be 'amg', 'lu' or 'auto', got {solver!r}")
        if clamped is not None and clamped not in mesh.boundaries:
            raise ValueError(f"clamped: the mesh has no region {clamped!r} (has {', '.join(mesh.boundaries)})")
        t0 = time.perf_counter()
        self.mesh, self.order, self.tol, self.maxiter = mesh, order, tol, maxiter
        self.E, self.nu = youngs_modulus, poisson_ratio
        elem = ElementVector(ElementTetP2() if order == 2 else ElementTetP1())
        self.basis = Basis(mesh, elem, intorder=2 * (order - 1) if order == 2 else 1)
        lam = youngs_modulus * poisson_ratio / ((1 + poisson_ratio) * (1 - 2 * poisson_ratio))
        mu = youngs_modulus / (2 * (1 + poisson_ratio))
        K = _elasticity_form(lam, mu).assemble(self.basis).tocsr()
        held = [np.asarray(fixed if fixed is not None else [], dtype=np.int64)]
        if clamped is not None:
            held.append(self.basis.get_dofs(mesh.boundaries[clamped]).flatten())
        self.free = np.setdiff1d(np.arange(self.basis.N), np.concatenate(held))
        self.K = K[self.free][:, self.free].tocsr()
        self.assembly_seconds = time.perf_counter() - t0
        self.solver = solver if solver != "auto" else ("lu" if order == 1 and self.free.size <= LU_MAX_DOFS else "amg")
        self._ml = None
        self.setup_seconds = 0.0
        self.solve_seconds = 0.0
        self.solves = 0
        self.iterations = 0

    def _hierarchy(self):
        import pyamg

        t0 = time.perf_counter()
        B = rigid_body_modes_3d(self.basis)[self.free]
        self._ml = pyamg.smoothed_aggregation_solver(self.K, B=B, coarse_solver="splu", max_coarse=500)
        self.setup_seconds = time.perf_counter() - t0

    def _factor(self):
        import scipy.sparse.linalg as sla

        t0 = time.perf_counter()
        self._ml = sla.splu(self.K.tocsc(), permc_spec="MMD_AT_PLUS_A", diag_pivot_thresh=0.0,
                            options={"SymmetricMode": True})
        self.setup_seconds = time.perf_counter() - t0

    def solve_many(self, F: np.ndarray, case: str = "3-D elasticity") -> np.ndarray:
        """Displacements (basis.N, m) for the load vectors F (basis.N, m) [N]: one block solve with ``lu``."""
        F = np.asarray(F, float)
        if self.solver == "amg":
            return np.column_stack([self.solve(F[:, j], case=f"{case}, load {j}") for j in range(F.shape[1])])
        if self._ml is None:
            self._factor()
        t0 = time.perf_counter()
        rhs = F[self.free]
        x = self._ml.solve(rhs)
        res = np.linalg.norm(self.K @ x - rhs, axis=0) / np.maximum(np.linalg.norm(rhs, axis=0), 1e-300)
        if not np.all(np.isfinite(x)) or res.max() > 1e-8:
            raise ConvergenceError(case, f"sparse LU solution has relative residual {res.max():.3g}",
                                   {"residual": res.tolist()})
        U = np.zeros((self.basis.N, F.shape[1]))
        U[self.free] = x
        self.solve_seconds += time.perf_counter() - t0
        self.solves += F.shape[1]
        return U

    def solve(self, f: np.ndarray, case: str = "3-D elasticity") -> np.ndarray:
        """Displacement DOF vector (length ``basis.N``) for the load vector ``f`` [N]."""
        if self.solver == "lu":
            return self.solve_many(np.asarray(f, float)[:, None], case)[:, 0]
        if self._ml is None:
            self._hierarchy()
        t0 = time.perf_counter()
        rhs = f[self.free]
        hist: list[float] = []
        x0 = np.zeros_like(rhs)
        x = self._ml.solve(rhs, x0=x0, tol=self.tol, accel="cg", maxiter=self.maxiter, residuals=hist)
        res = hist[-1] / max(hist[0], 1e-300) if hist else 0.0
        if not np.all(np.isfinite(x)) or res > 10 * self.tol:
            raise ConvergenceError(case, f"SA-CG did not reach tol={self.tol:g} (relative residual {res:.3g})",
                                   {"residual": hist})
        u = np.zeros(self.basis.N)
        u[self.free] = x
        self.solve_seconds += time.perf_counter() - t0
        self.solves += 1
        self.iterations += len(hist) - 1
        return u

    def probe_matrices(self, points: np.ndarray) -> list:
        """Sparse point-evaluation matrices (x, y, z component) at ``points`` (3, n): u_c = M_c @ u."""
        from scipy.sparse import csr_matrix

        mats = []
        for idx, (_, b) in zip(self.basis.split_indices(), self.basis.split(np.zeros(self.basis.N))):
            P = b.probes(points).tocoo()
            mats.append(csr_matrix((P.data, (P.row, idx[P.col])), shape=(points.shape[1], self.basis.N)))
        return mats

    def probe(self, u: np.ndarray, points: np.ndarray) -> np.ndarray:
        """Displacement vectors at ``points`` (3, n) → (3, n) [m]."""
        comps = self.basis.split(u)
        return np.vstack([b.probes(points) @ c for c, b in comps])

    def stats(self) -> SolveStats:
        nnz = int(self._ml.L.nnz + self._ml.U.nnz) if self.solver == "lu" and self._ml is not None else 0
        return SolveStats(self.basis.N, self.assembly_seconds, self.setup_seconds, self.solve_seconds,
                          self.solves, self.iterations, nnz)
