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
