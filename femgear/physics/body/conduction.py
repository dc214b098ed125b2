"""Steady heat conduction of a gear body with prescribed temperatures (scikit-fem, 2-D or 3-D).

∇·(k∇T) = 0 with Dirichlet data on named boundaries and zero flux elsewhere (insulated), the
conduction model of :mod:`femgear.physics.body.thermal` (section) and :mod:`femgear.physics.ltca.thermal` (body).
"""

from __future__ import annotations

import numpy as np

from femgear.physics.body.forms import conduction


def solve_temperature(mesh, conductivity: float, dirichlet: dict[str, float], order: int = 2):
    """Steady conduction ∇·(k∇T) = 0 with T prescribed on the named boundaries; others insulated.

    Triangles (the 2-D section) or tetrahedra (the 3-D member body, :mod:`femgear.physics.ltca.thermal`).
    """
    from skfem import Basis, ElementTetP1, ElementTetP2, ElementTriP1, ElementTriP2, MeshTet, condense, solve

    if isinstance(mesh, MeshTet):
        elem = ElementTetP2() if order == 2 else ElementTetP1()
    else:
        elem = ElementTriP2() if order == 2 else ElementTriP1()
    basis = Basis(mesh, elem)
    A = conduction(conductivity).assemble(basis)
    T = np.zeros(basis.N)
    D = []
    for name, value in dirichlet.items():
        dofs = basis.get_dofs(mesh.boundaries[name]).flatten()
        T[dofs] = value
        D.append(dofs)
    D = np.unique(np.concatenate(D))
    T = solve(*condense(A, np.zeros(basis.N), x=T, D=D))
    return basis, T


def solve_temperature_cases(mesh, conductivity: float, cases: list[dict[str, float]], order: int = 1):
    """:func:`solve_temperature` for several sets of values on the same named boundaries, one factorisation:
    (basis, [T of each case]).  3-D bodies factor by CHOLMOD where it is installed
    (:class:`femgear.physics.body.elastic3d.Elastic3D`'s), else by SuperLU with the minimum-degree ordering of
    Aᵀ + A; SuperLU's default column ordering took 25 s a case on the FZG A pinion's 55 k-node body."""
    from skfem import Basis, ElementTetP1, ElementTetP2, ElementTriP1, ElementTriP2, MeshTet

    from femgear.physics.body.elastic3d import _CholmodFactor, cholmod_backend

    names = set(cases[0])
    if any(set(c) != names for c in cases):
        raise ValueError("every case must prescribe the same boundaries")
    if isinstance(mesh, MeshTet):
        elem = ElementTetP2() if order == 2 else ElementTetP1()
    else:
        elem = ElementTriP2() if order == 2 else ElementTriP1()
    basis = Basis(mesh, elem)
    A = conduction(conductivity).assemble(basis).tocsr()
    dofs = {n: basis.get_dofs(mesh.boundaries[n]).flatten() for n in cases[0]}
    D = np.unique(np.concatenate(list(dofs.values())))
    free = np.setdiff1d(np.arange(basis.N), D)
    T = np.zeros((basis.N, len(cases)))
    for j, case in enumerate(cases):
        for name, value in case.items():
            T[dofs[name], j] = value
    rhs = -(A[free][:, D] @ T[D])
    Aff = A[free][:, free].tocsr()
    if cholmod_backend() is not None:
        T[free] = _CholmodFactor(Aff).solve(rhs)
    else:
        import scipy.sparse.linalg as sla

        lu = sla.splu(Aff.tocsc(), permc_spec="MMD_AT_PLUS_A", diag_pivot_thresh=0.0, options={"SymmetricMode": True})
        T[free] = lu.solve(rhs)
    return basis, [T[:, j] for j in range(len(cases))]
