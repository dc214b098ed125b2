"""3-D elasticity with quadratic tetrahedra where the body bends and linear ones elsewhere (conforming).

Linear (P1) tetrahedra are stiff in bending: a gear tooth meshed with a few P1 elements across
its thickness converges at order ≈ 1–1.5 in its compliance (``docs/cost.md``), while quadratic
(P2) ones are far more accurate per element but cost ≈ 7× the DOF on the whole body.
:class:`MixedElastic3D` takes P2 on the elements of a ``quadratic`` mask (the loaded teeth and
their roots, :func:`femgear.physics.mesh.segment.bending_zone`) and P1 on the rest, in the
hierarchical form of P2 (Zienkiewicz & Taylor, *The Finite Element Method*, vol. 1, 6th ed.,
§8.7: P1 shape functions plus one edge bubble 4 λ_a λ_b per edge):

    u = Σ_vertices λ_a u_a + Σ_free edges 4 λ_a λ_b c_e

An edge is *free* (carries a bubble c_e) when every element around it is quadratic and it is
not clamped; on every other edge c_e = 0, so the displacement is linear along it.  A face
between a quadratic and a linear element has three such edges, so its trace is linear from both
sides: the space is conforming (a subspace of P2 on the whole mesh), holds every linear field
(rigid motions included), and the quadratic elements next to the linear ones are transition
elements with some edges linear.  Equivalently u = T ũ with T the map of these unknowns to the
Lagrange P2 unknowns (vertex values; mid-edge value = the mean of its vertices + c_e), and
K̃ = Tᵀ K_P2 T on the quadratic elements plus the P1 stiffness on the linear ones (assembled
directly, :func:`femgear.physics.body.elastic3d.assemble_p1`).  Loads are assembled with P2 on
their facets and taken over by Tᵀ; point readings use the hierarchical shape functions.  The
unknowns are the P1 vertex DOF (scikit-fem's P1 numbering) followed by three per free edge.
"""

from __future__ import annotations

import time

import numpy as np

from femgear.physics.body.elastic3d import (
    P2_ASSEMBLY_CHUNK,
    Elastic3D,
    _assemble_chunks,
    _elasticity_form,
    assemble_p1,
    auto_solver,
    check_arguments,
)


def free_edges(mesh, quadratic: np.ndarray, clamped_facets: np.ndarray | None = None) -> np.ndarray:
    """Indices of the edges of ``mesh`` whose every element is in the ``quadratic`` mask and that do not lie on
    ``clamped_facets``."""
    t2e = mesh.t2e                                         # (6, n_elements)
    linear_edge = np.zeros(mesh.edges.shape[1], bool)
    linear_edge[t2e[:, ~quadratic].ravel()] = True
    if clamped_facets is not None and len(clamped_facets):
        linear_edge[mesh.f2e[:, clamped_facets].ravel()] = True
    touched = np.zeros_like(linear_edge)
    touched[t2e[:, quadratic].ravel()] = True
    return np.nonzero(touched & ~linear_edge)[0]


class MixedElastic3D(Elastic3D):
    """K u = f on a ``MeshTet``: P2 (hierarchical) on the ``quadratic`` elements, P1 elsewhere, ``clamped`` fixed.

    The solvers, block solves and statistics are those of :class:`Elastic3D`; ``quadratic`` (bool per element)
    all False gives its P1 model, all True its P2 model (the same space: the tests compare them).
    """

    def __init__(self, mesh, youngs_modulus: float, poisson_ratio: float, quadratic: np.ndarray,
                 clamped: str | None = "bore", tol: float = 1e-8, maxiter: int = 500, solver: str = "auto"):
        from skfem import Basis, ElementTetP1, ElementTetP2, ElementVector

        quadratic = np.asarray(quadratic, bool)
        if quadratic.shape != (mesh.t.shape[1],):
            raise ValueError(f"quadratic: need one flag per element ({mesh.t.shape[1]}), got shape {quadratic.shape}")
        check_arguments(mesh, solver, clamped)
        t0 = time.perf_counter()
        self.mesh, self.order, self.tol, self.maxiter = mesh, 1, tol, maxiter
        self.E, self.nu = youngs_modulus, poisson_ratio
        self.quadratic = quadratic
        self.basis = Basis(mesh, ElementVector(ElementTetP1()), intorder=1)     # the vertex unknowns
        self.elem2 = ElementVector(ElementTetP2())
        n1 = self.basis.N
        self.edges = free_edges(mesh, quadratic, mesh.boundaries[clamped] if clamped is not None else None)
        self.N = n1 + 3 * self.edges.size
        lam = youngs_modulus * poisson_ratio / ((1 + poisson_ratio) * (1 - 2 * poisson_ratio))
        mu = youngs_modulus / (2 * (1 + poisson_ratio))
        K = assemble_p1(mesh, self.basis.element_dofs, self.N, lam, mu, elements=np.nonzero(~quadratic)[0])
        if quadratic.any():
            self.T = self._lagrange_map()
            K = K + _assemble_chunks(mesh, self.elem2, 2, _elasticity_form(lam, mu), chunk=P2_ASSEMBLY_CHUNK,
                                     elements=np.nonzero(quadratic)[0], transform=self.T)
        else:
            self.T = None
        held = self.basis.get_dofs(mesh.boundaries[clamped]).flatten() if clamped is not None else np.zeros(0, int)
        self.free = np.setdiff1d(np.arange(self.N), held)
        self.K = K[self.free][:, self.free].tocsr()
        self.assembly_seconds = time.perf_counter() - t0
        self.solver = solver if solver != "auto" else auto_solver(2 if quadratic.any() else 1, self.free.size)
        self._ml = None
        self.setup_seconds = self.solve_seconds = 0.0
        self.solves = self.iterations = 0

    def _lagrange_map(self):
        """T (N_P2 × N): the Lagrange P2 unknowns of the whole mesh (scikit-fem's numbering: vertex DOF as P1's,
        then three per edge) from this model's unknowns."""
        from scipy.sparse import coo_matrix

        mesh, n1 = self.mesh, self.basis.N
        n_edges = mesh.edges.shape[1]
        n2 = n1 + 3 * n_edges
        rows, cols, vals = [np.arange(n1)], [np.arange(n1)], [np.ones(n1)]
        edge_dof = n1 + 3 * np.arange(n_edges)                 # component c of edge e: n1 + 3 e + c
        for c in range(3):
            for end in (0, 1):
                rows.append(edge_dof + c)
                cols.append(self.basis.nodal_dofs[c, mesh.edges[end]])
                vals.append(np.full(n_edges, 0.5))
            rows.append(n1 + 3 * self.edges + c)
            cols.append(n1 + 3 * np.arange(self.edges.size) + c)
            vals.append(np.ones(self.edges.size))
        return coo_matrix((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))),
                          shape=(n2, self.N)).tocsr()

    def facet_basis(self, facets: np.ndarray):
        from skfem import FacetBasis

        return FacetBasis(self.mesh, self.elem2 if self.T is not None else self.basis.elem, facets=facets)

    def lift(self, f: np.ndarray) -> np.ndarray:
        if self.T is None:
            return np.concatenate([f, np.zeros(self.N - f.size)])
        return self.T.T @ f

    def near_null(self) -> np.ndarray:
        """Rigid-body modes (N, 6): the P1 ones; the edge bubbles of a linear field are zero."""
        from femgear.physics.body.elastic3d import rigid_body_modes_3d

        B = np.zeros((self.N, 6))
        B[:self.basis.N] = rigid_body_modes_3d(self.basis)
        return B

    def probe_matrices(self, points: np.ndarray) -> list:
        """Point-evaluation matrices (x, y, z component) at ``points`` (3, n): u_c = M_c @ u."""
        from scipy.sparse import csr_matrix

        from femgear.physics.body.elastic3d import locate

        mesh = self.mesh
        points = np.asarray(points, float)
        el = locate(mesh, points)
        x = mesh.p[:, mesh.t[:, el]]                                    # (3, 4, n)
        J = np.transpose(x[:, 1:] - x[:, :1], (2, 0, 1))                # (n, 3, 3)
        lam123 = np.linalg.solve(J, (points - x[:, 0]).T[:, :, None])[:, :, 0]
        lam = np.column_stack([1 - lam123.sum(axis=1), lam123])         # (n, 4) barycentric
        slot = np.full(mesh.edges.shape[1], -1)
        slot[self.edges] = np.arange(self.edges.size)
        n, n1 = points.shape[1], self.basis.N
        mats = []
        for c in range(3):
            rows = [np.repeat(np.arange(n), 4)]
            cols = [self.basis.nodal_dofs[c, mesh.t[:, el].T].ravel()]
            vals = [lam.ravel()]
            for k in range(6):                                          # the element's edges and their bubbles
                e = mesh.t2e[k, el]
                s = slot[e]
                hit = s >= 0
                if not hit.any():
                    continue
                a, b = mesh.edges[:, e[hit]]
                va = _local(mesh.t[:, el[hit]], a)
                vb = _local(mesh.t[:, el[hit]], b)
                idx = np.nonzero(hit)[0]
                rows.append(idx)
                cols.append(n1 + 3 * s[hit] + c)
                vals.append(4 * lam[idx, va] * lam[idx, vb])
            mats.append(csr_matrix((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))),
                                   shape=(n, self.N)))
        return mats

    def probe(self, u: np.ndarray, points: np.ndarray) -> np.ndarray:
        return np.vstack([M @ u for M in self.probe_matrices(points)])


def _local(t: np.ndarray, vertex: np.ndarray) -> np.ndarray:
    """Local index (0–3) of ``vertex`` in each element column of ``t`` (4, n)."""
    return np.argmax(t == vertex[None, :], axis=0)


__all__ = ["MixedElastic3D", "free_edges"]
