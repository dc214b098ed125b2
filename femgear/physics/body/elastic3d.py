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
- ``"cholmod"``: a supernodal sparse Cholesky factor with a METIS ordering (CHOLMOD), then block
  solves of all load cases.  Far less fill than SuperLU's minimum degree: the marine pinion body
  (102 k DOF) factors within the memory its assembly needs, where SuperLU needs several GB
  (``docs/cost.md``).  Two bindings (:func:`cholmod_backend`): the system's CHOLMOD through
  ``scikit-sparse`` (SuiteSparse and OpenBLAS from the distribution; ``make`` installs them where it
  can), else the ``cholespy`` wheel, which carries its own METIS and reference BLAS and is 10–20×
  slower on these bodies (its METIS refinement took 90 % of the time: the marine gear's
  ``p2-bending`` body, 185 k DOF, 212 s against 14 s on one core, ``docs/cost.md``).
  ``"auto"``: ``cholmod`` when either binding is installed, else ``lu`` for P1 up to
  :data:`LU_MAX_DOFS` free DOF (memory: ≈ 1 GB at 58 k DOF, a few GB at 140 k), else ``amg``.

Assembly.  P1 stiffness matrices are assembled directly (constant strain per tetrahedron,
exact: K_(a i)(b j) = V [μ δ_ij ∇φ_a·∇φ_b + μ ∂_j φ_a ∂_i φ_b + λ ∂_i φ_a ∂_j φ_b]) in chunks
of :data:`ASSEMBLY_CHUNK` elements; P2 by scikit-fem over element chunks.  Chunks keep the
assembly's transient memory bounded (scikit-fem over the whole marine pinion body peaked at
1.5 GB for a 0.4 GB result), so the peak stays linear in the DOF.
"""

from __future__ import annotations

import functools
import time
from dataclasses import dataclass

import numpy as np

from femgear.errors import ConvergenceError

LU_MAX_DOFS = 160_000  #: ``solver="auto"`` without CHOLMOD: the sparse LU up to this many free DOF (P1 only), SA-CG above
ASSEMBLY_CHUNK = 40_000  #: elements per assembly chunk (P1: 144 matrix entries an element)
P2_ASSEMBLY_CHUNK = 8_000  #: P2 elements per scikit-fem assembly chunk (900 entries an element: ≈ 0.3 GB transient)
SOLVE_CHUNK = 16         #: load cases per block solve (a progress step)
SOLVERS = ("amg", "lu", "cholmod", "auto")


@functools.cache
def cholmod_backend() -> str | None:
    """The CHOLMOD binding the ``cholmod`` solver uses: ``"scikit-sparse"`` (the system's CHOLMOD, scikit-sparse
    0.4), else ``"cholespy"`` (the wheel), else None."""
    try:
        from sksparse.cholmod import analyze  # noqa: F401  (scikit-sparse 0.4's API; 0.5 changed it)
    except ImportError:
        pass
    else:
        return "scikit-sparse"
    try:
        import cholespy  # noqa: F401
    except ImportError:
        return None
    return "cholespy"


def cholmod_available() -> bool:
    """True when a CHOLMOD binding (:func:`cholmod_backend`) can be imported."""
    return cholmod_backend() is not None


def auto_solver(order: int, ndofs: int) -> str:
    """The solver ``"auto"`` picks for ``ndofs`` free DOF of order ``order``."""
    if cholmod_available():
        return "cholmod"
    return "lu" if order == 1 and ndofs <= LU_MAX_DOFS else "amg"


def solver_name(solver: str) -> str:
    """``solver`` as the progress lines name it: ``cholmod`` with its binding."""
    return f"cholmod ({cholmod_backend()})" if solver == "cholmod" else solver


def solve_cost(dofs: int, tets: int, order: int = 1, n_loads: int = 1, solver: str = "auto") -> tuple[float, float]:
    """(peak resident memory [B], wall time [s]) expected for meshing, assembling, factoring (or the SA
    hierarchy) and ``n_loads`` solves of a body with ``dofs`` unknowns and ``tets`` elements.

    Fitted to measurements on the shared 2-core machine (``python studies/benchmarks/cost.py``, docs/cost.md):
    the process and the mesh ≈ 0.3 GB + 4 kB per DOF (basis, matrix, load vectors); CHOLMOD's factor
    ≈ 110 n^(4/3) B (METIS fill of these swept bodies; ×1.3 for quadratic elements with cholespy's METIS; the
    system's CHOLMOD: 93 and 114 n^(4/3) B measured on the marine gear's P1 and p2-bending bodies, and the
    whole p2-bending marine LTCA peaked at 1.93 GiB where this gives 2.06 GiB); SuperLU's (minimum degree) ≈ 420 n^(4/3) B;
    SA-AMG ≈ 3 kB per DOF.  Times: ≈ 65 µs per DOF to mesh and assemble (80 µs before the probes located
points by a k-d tree of the elements; ``python studies/benchmarks/estimates.py`` on five zoo pairs then gave
CPU / estimate 0.76–1.24 for the ``ltca`` bodies and 0.84–1.10 for the ``fe3d`` ones, memory 0.74–1.18), the factor ≈ 3.5 s (n/1e5)^1.5 with
    the system's CHOLMOD (scikit-sparse, one BLAS thread; marine bodies: P1 88 k / 106 k DOF 3.4 / 3.9 s,
    p2-bending 96 k / 185 k DOF 5.1 / 14.1 s, ×1.3² for quadratic elements) and ≈ 40 s (n/1e5)^1.5 with cholespy,
    0.3 µs per DOF and load case to solve; SA-CG ≈ 13 µs per DOF and load case.  Checked against the CPU
    times of the cold LTCA (both members and the mesh cycle; cholespy): baseline level 1 / 3 and marine level 1
    measured 23 / 82 / 120 s, modelled 23 / 65 / 120 s.
    """
    solver = auto_solver(order, dofs) if solver == "auto" else solver
    n = float(max(dofs, 1))
    memory = 0.3e9 + 4.0e3 * n + 8.0 * n * n_loads
    seconds = 6.5e-5 * n + 1e-5 * tets
    if solver == "cholmod":      # quadratic elements couple more unknowns per row: more fill (marine gear, docs/cost.md)
        dense = 1.0 if order == 1 else 1.3
        system = cholmod_backend() == "scikit-sparse"
        memory += 110.0 * (1.0 if system else dense) * n ** (4 / 3)
        seconds += (3.5 if system else 40.0) * dense**2 * (n / 1e5) ** 1.5 + 3e-7 * n * n_loads
    elif solver == "lu":
        memory += 420.0 * n ** (4 / 3)
        seconds += 60.0 * (n / 1e5) ** 1.6 + 5e-7 * n * n_loads
    else:
        memory += 3.0e3 * n
        seconds += 1.3e-5 * n * n_loads * (2.0 if order == 2 else 1.0)
    return memory, seconds


def _elasticity_form(lam: float, mu: float):
    from skfem import BilinearForm
    from skfem.helpers import ddot, eye, sym_grad, trace

    @BilinearForm
    def form(u, v, w):
        eps = sym_grad(u)
        return ddot(2.0 * mu * eps + lam * eye(trace(eps), 3), sym_grad(v))

    return form


def assemble_p1(mesh, element_dofs: np.ndarray, n: int, lam: float, mu: float, chunk: int = ASSEMBLY_CHUNK,
                elements: np.ndarray | None = None):
    """Stiffness matrix (n × n CSR) of P1 vector tetrahedra, local DOF 3a + i = component i of vertex a.

    Constant strain per element (exact, module docstring); ``element_dofs`` (12, n_elements) maps the
    local DOF to the global ones (scikit-fem's numbering); ``elements``: only these (indices; None: all).
    """
    from scipy.sparse import coo_matrix, csr_matrix

    K = csr_matrix((n, n))
    eye3 = np.eye(3)
    elements = np.arange(mesh.t.shape[1]) if elements is None else np.asarray(elements)
    for lo in range(0, elements.size, chunk):
        sel = elements[lo:lo + chunk]
        t = mesh.t[:, sel]
        x = mesh.p[:, t]                                           # (3, 4, ne)
        J = np.transpose(x[:, 1:] - x[:, :1], (2, 0, 1))           # (ne, 3 coords, 3 edges)
        Jinv = np.linalg.inv(J)
        vol = np.abs(np.linalg.det(J)) / 6.0
        g = np.concatenate([-Jinv.sum(axis=1, keepdims=True), Jinv], axis=1)   # (ne, 4 vertices, 3): ∇φ_a
        dots = np.einsum("eak,ebk->eab", g, g)
        Ke = (mu * dots[:, :, None, :, None] * eye3[None, None, :, None, :]
              + mu * np.einsum("eaj,ebi->eaibj", g, g) + lam * np.einsum("eai,ebj->eaibj", g, g))
        Ke = (Ke * vol[:, None, None, None, None]).reshape(-1, 12, 12)
        dofs = element_dofs[:, sel].T                              # (ne, 12)
        rows = np.broadcast_to(dofs[:, :, None], Ke.shape).ravel()
        cols = np.broadcast_to(dofs[:, None, :], Ke.shape).ravel()
        part = coo_matrix((Ke.ravel(), (rows, cols)), shape=(n, n)).tocsr()
        K = K + part
    return K


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


def check_arguments(mesh, solver: str, clamped: str | None) -> None:
    """ValueError for an unknown ``solver``, ``cholmod`` without a CHOLMOD binding, or a ``clamped`` region the mesh lacks."""
    if solver not in SOLVERS:
        raise ValueError(f"solver must be one of {', '.join(SOLVERS)}, got {solver!r}")
    if solver == "cholmod" and not cholmod_available():
        raise ValueError("solver 'cholmod' needs scikit-sparse or cholespy (pip install cholespy)")
    if clamped is not None and clamped not in mesh.boundaries:
        raise ValueError(f"clamped: the mesh has no region {clamped!r} (has {', '.join(mesh.boundaries)})")


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
    (e.g. a statically determinate support of a free body, :mod:`femgear.physics.ltca.thermal`).
    """

    def __init__(self, mesh, youngs_modulus: float, poisson_ratio: float, order: int = 2,
                 clamped: str | None = "bore", tol: float = 1e-8, maxiter: int = 500, solver: str = "amg",
                 fixed=None):
        from skfem import Basis, ElementTetP1, ElementTetP2, ElementVector

        if order not in (1, 2):
            raise ValueError(f"order must be 1 or 2, got {order!r}")
        check_arguments(mesh, solver, clamped)
        t0 = time.perf_counter()
        self.mesh, self.order, self.tol, self.maxiter = mesh, order, tol, maxiter
        self.E, self.nu = youngs_modulus, poisson_ratio
        elem = ElementVector(ElementTetP2() if order == 2 else ElementTetP1())
        intorder = 2 * (order - 1) if order == 2 else 1
        self.basis = Basis(mesh, elem, intorder=intorder)
        lam = youngs_modulus * poisson_ratio / ((1 + poisson_ratio) * (1 - 2 * poisson_ratio))
        mu = youngs_modulus / (2 * (1 + poisson_ratio))
        if order == 1:
            K = assemble_p1(mesh, self.basis.element_dofs, self.basis.N, lam, mu)
        else:
            K = _assemble_chunks(mesh, elem, intorder, _elasticity_form(lam, mu), chunk=P2_ASSEMBLY_CHUNK)
        held = [np.asarray(fixed if fixed is not None else [], dtype=np.int64)]
        if clamped is not None:
            held.append(self.basis.get_dofs(mesh.boundaries[clamped]).flatten())
        self.N = self.basis.N    #: unknowns of the model (the length of a displacement vector)
        self.free = np.setdiff1d(np.arange(self.basis.N), np.concatenate(held))
        self.K = K[self.free][:, self.free].tocsr()
        self.assembly_seconds = time.perf_counter() - t0
        self.solver = solver if solver != "auto" else auto_solver(order, self.free.size)
        self._ml = None
        self.setup_seconds = 0.0
        self.solve_seconds = 0.0
        self.solves = 0
        self.iterations = 0

    def _hierarchy(self):
        import pyamg

        t0 = time.perf_counter()
        B = self.near_null()[self.free]
        self._ml = pyamg.smoothed_aggregation_solver(self.K, B=B, coarse_solver="splu", max_coarse=500)
        self.setup_seconds = time.perf_counter() - t0

    def _factor(self):
        t0 = time.perf_counter()
        if self.solver == "cholmod":
            self._ml = _CholmodFactor(self.K)
        else:
            import scipy.sparse.linalg as sla

            self._ml = sla.splu(self.K.tocsc(), permc_spec="MMD_AT_PLUS_A", diag_pivot_thresh=0.0,
                                options={"SymmetricMode": True})
        self.setup_seconds = time.perf_counter() - t0

    def solve_many(self, F: np.ndarray, case: str = "3-D elasticity", progress=None) -> np.ndarray:
        """Displacements (basis.N, m) for the load vectors F (basis.N, m) [N]: block solves of
        :data:`SOLVE_CHUNK` load cases with one factor (``lu``, ``cholmod``), one SA-CG solve each with
        ``amg``.  ``progress``: called with the number of load cases done after each block."""
        F = np.asarray(F, float)
        m = F.shape[1]
        U = np.zeros((self.N, m))
        if self.solver == "amg":
            for j in range(m):
                U[:, j] = self.solve(F[:, j], case=f"{case}, load {j}")
                if progress is not None:
                    progress(j + 1)
            return U
        if self._ml is None:
            self._factor()
        for lo in range(0, m, SOLVE_CHUNK):
            t0 = time.perf_counter()
            rhs = F[self.free, lo:lo + SOLVE_CHUNK]
            x = self._ml.solve(rhs)
            res = np.linalg.norm(self.K @ x - rhs, axis=0) / np.maximum(np.linalg.norm(rhs, axis=0), 1e-300)
            if not np.all(np.isfinite(x)) or res.max() > 1e-8:
                raise ConvergenceError(case, f"sparse {self.solver} solution has relative residual {res.max():.3g}",
                                       {"residual": res.tolist()})
            U[self.free, lo:lo + SOLVE_CHUNK] = x
            self.solve_seconds += time.perf_counter() - t0
            self.solves += rhs.shape[1]
            if progress is not None:
                progress(min(m, lo + SOLVE_CHUNK))
        return U

    def solve(self, f: np.ndarray, case: str = "3-D elasticity") -> np.ndarray:
        """Displacement DOF vector (length ``basis.N``) for the load vector ``f`` [N]."""
        if self.solver in ("lu", "cholmod"):
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
        u = np.zeros(self.N)
        u[self.free] = x
        self.solve_seconds += time.perf_counter() - t0
        self.solves += 1
        self.iterations += len(hist) - 1
        return u

    def near_null(self) -> np.ndarray:
        """Rigid-body modes (N, 6): the near-null space of the SA hierarchy."""
        return rigid_body_modes_3d(self.basis)

    def facet_basis(self, facets: np.ndarray):
        """scikit-fem ``FacetBasis`` on ``facets`` for load vectors; :meth:`lift` takes its vectors to the model's."""
        from skfem import FacetBasis

        return FacetBasis(self.mesh, self.basis.elem, facets=facets)

    def lift(self, f: np.ndarray) -> np.ndarray:
        """A load vector assembled on :meth:`facet_basis` as a load vector of the model (here: itself)."""
        return f

    def probe_matrices(self, points: np.ndarray) -> list:
        """Sparse point-evaluation matrices (x, y, z component) at ``points`` (3, n): u_c = M_c @ u."""
        from scipy.sparse import csr_matrix

        points = np.asarray(points, float)
        cells = locate(self.mesh, points)
        mats = []
        for idx, (_, b) in zip(self.basis.split_indices(), self.basis.split(np.zeros(self.basis.N))):
            P = point_matrix(b, points, cells)
            mats.append(csr_matrix((P.data, (P.row, idx[P.col])), shape=(points.shape[1], self.basis.N)))
        return mats

    def probe(self, u: np.ndarray, points: np.ndarray) -> np.ndarray:
        """Displacement vectors at ``points`` (3, n) → (3, n) [m]."""
        return np.vstack([M @ u for M in self.probe_matrices(points)])

    def stats(self) -> SolveStats:
        nnz = int(self._ml.L.nnz + self._ml.U.nnz) if self.solver == "lu" and self._ml is not None else 0
        return SolveStats(self.N, self.assembly_seconds, self.setup_seconds, self.solve_seconds,
                          self.solves, self.iterations, nnz)


def locate(mesh, points: np.ndarray, k: int = 16, tol: float = 1e-6) -> np.ndarray:
    """The tetrahedron of ``mesh`` holding each of ``points`` (3, n): index per point.

    Candidates are the ``k`` elements with the nearest centroids (a k-d tree, built once per mesh), widened
    fourfold for the points none of them holds, up to every element; a point is held where its barycentric
    coordinates are ≥ −``tol`` (the best candidate is taken, so a point on a shared face or a hair outside
    a faceted curved boundary finds one).  scikit-fem's own finder searched every element for all points at
    once when one point missed its ten nearest: 300 k elements × a thousand flank readings was 7 GB on the FZG
    A pinion's 3-D body (thin tetrahedra at its narrow tip).  Raises ValueError for a point outside the mesh.
    """
    points = np.asarray(points, float)
    tree = _centroid_tree(mesh)
    n_el = mesh.t.shape[1]
    cells = np.full(points.shape[1], -1, dtype=np.int64)
    todo = np.arange(points.shape[1])
    kk = min(k, n_el)
    while todo.size:
        best, score = _best_of(mesh, points[:, todo], tree.query(points[:, todo].T, kk)[1].reshape(todo.size, kk))
        hit = score >= -tol
        cells[todo[hit]] = best[hit]
        todo = todo[~hit]
        if todo.size and kk == n_el:
            x = points[:, todo[0]]
            raise ValueError(f"point ({x[0]:.6g}, {x[1]:.6g}, {x[2]:.6g}) m lies outside the body's mesh")
        kk = min(4 * kk, n_el)
    return cells


def _centroid_tree(mesh):
    """k-d tree of the element centroids of ``mesh``, kept on the mesh object (built once)."""
    tree = getattr(mesh, "_femgear_tree", None)
    if tree is None:
        from scipy.spatial import cKDTree

        tree = cKDTree(mesh.p[:, mesh.t].mean(axis=1).T)
        object.__setattr__(mesh, "_femgear_tree", tree)
    return tree


def _best_of(mesh, x: np.ndarray, cand: np.ndarray, chunk: int = 4096) -> tuple[np.ndarray, np.ndarray]:
    """For points ``x`` (3, n) and candidate elements ``cand`` (n, k): the candidate with the largest smallest
    barycentric coordinate, and that coordinate (≥ 0 inside)."""
    best = np.empty(x.shape[1], dtype=np.int64)
    score = np.empty(x.shape[1])
    for lo in range(0, x.shape[1], chunk):
        c = cand[lo:lo + chunk]                                       # (m, k)
        v = mesh.p[:, mesh.t[:, c]]                                   # (3, 4, m, k)
        J = np.moveaxis(v[:, 1:] - v[:, :1], (0, 1), (-2, -1))        # (m, k, 3, 3): columns the edge vectors
        rhs = (x[:, lo:lo + chunk, None] - v[:, 0])                   # (3, m, k)
        lam = np.linalg.solve(J, np.moveaxis(rhs, 0, -1)[..., None])[..., 0]     # (m, k, 3)
        low = np.minimum(lam.min(axis=-1), 1 - lam.sum(axis=-1))
        j = np.argmax(low, axis=1)
        best[lo:lo + chunk] = c[np.arange(c.shape[0]), j]
        score[lo:lo + chunk] = low[np.arange(c.shape[0]), j]
    return best, score


def point_matrix(basis, points: np.ndarray, cells: np.ndarray):
    """Point-evaluation matrix (COO, one row per point) of a scalar ``basis`` at ``points`` (3, n) inside the
    elements ``cells``: the shape functions at the points' reference coordinates."""
    from scipy.sparse import coo_matrix

    ref = basis.mapping.invF(points[:, :, None], tind=cells)
    phis = np.array([basis.elem.gbasis(basis.mapping, ref, k, tind=cells)[0] for k in range(basis.Nbfun)])
    n = points.shape[1]
    rows = np.tile(np.arange(n), basis.Nbfun)
    cols = basis.element_dofs[:, cells].ravel()
    return coo_matrix((phis.ravel(), (rows, cols)), shape=(n, basis.N))


def _assemble_chunks(mesh, elem, intorder: int, form, chunk: int = ASSEMBLY_CHUNK, elements: np.ndarray | None = None,
                     transform=None):
    """``form`` assembled by scikit-fem over chunks of elements (``elements``: only these; None: all) and summed
    (bounded transient memory); ``transform`` (a sparse T): the sum of Tᵀ K_chunk T instead."""
    from skfem import Basis

    K = None
    elements = np.arange(mesh.t.shape[1]) if elements is None else np.asarray(elements)
    for lo in range(0, elements.size, chunk):
        part = form.assemble(Basis(mesh, elem, intorder=intorder, elements=elements[lo:lo + chunk])).tocsr()
        if transform is not None:
            part = (transform.T @ part @ transform).tocsr()
        K = part if K is None else K + part
    return K


class _CholmodFactor:
    """CHOLMOD's Cholesky factor of an SPD matrix (METIS ordering; the binding of :func:`cholmod_backend`);
    ``solve`` takes one or a block of right-hand sides.  CHOLMOD running out of memory raises MemoryError.

    The system's CHOLMOD runs parts of its supernodal factor in a GNU OpenMP team (of a fixed size, whatever
    ``OMP_NUM_THREADS`` says), and GNU OpenMP does not survive ``fork``: a forked child that factors again
    waits forever for its parent's team.  So the first factor marks the process unsafe to fork
    (:func:`femgear.perf.mark_fork_unsafe`), and :func:`femgear.perf.interruptible` then runs the later
    body stages in this process (``tests/body/test_cholmod_fork.py``).
    """

    def __init__(self, K):
        self.n = K.shape[0]
        self.backend = cholmod_backend()
        if self.backend == "scikit-sparse":
            from sksparse.cholmod import CholmodOutOfMemoryError, cholesky

            from femgear.perf import mark_fork_unsafe

            mark_fork_unsafe("the system's CHOLMOD started its OpenMP threads")
            try:
                self._f = cholesky(K.T if K.format == "csr" else K.tocsc(), ordering_method="metis")  # Kᵀ = K
            except CholmodOutOfMemoryError as exc:
                raise MemoryError(f"CHOLMOD factor of {self.n} DOF: {exc}") from exc
            return
        from cholespy import CholeskySolverD, MatrixType

        C = K.tocoo()
        self._s = CholeskySolverD(self.n, C.row.astype(np.int32), C.col.astype(np.int32),
                                  np.ascontiguousarray(C.data, dtype=np.float64), MatrixType.COO)

    def solve(self, rhs: np.ndarray) -> np.ndarray:
        b = np.ascontiguousarray(rhs, dtype=np.float64)
        if self.backend == "scikit-sparse":
            return self._f(b)
        x = np.zeros_like(b)
        self._s.solve(b, x)
        return x
