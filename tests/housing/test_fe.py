"""The FE housing: assembly, the parametric mesh's named regions, the rigid seats and the output maps."""

import numpy as np
import pytest
import skfem
from skfem import Basis, BilinearForm, ElementTetP1, ElementTetP2, ElementVector
from skfem.helpers import ddot, div, dot, sym_grad

from femgear.physics.housing.fe import assemble
from femgear.physics.mesh.housing import STATIONS


@pytest.mark.parametrize("order", [1, 2])
def test_vectorised_assembly_equals_scikit_fem(order):
    m = skfem.MeshTet().refined(1)
    m = skfem.MeshTet(m.p * np.array([[1.0], [2.0], [0.5]]) + 0.05 * np.sin(3 * m.p), m.t)
    lam, mu, rho = 1.3, 0.7, 2.0
    b = Basis(m, ElementVector(ElementTetP2() if order == 2 else ElementTetP1()), intorder=2 * order)
    K0 = BilinearForm(lambda u, v, w: 2 * mu * ddot(sym_grad(u), sym_grad(v)) + lam * div(u) * div(v)).assemble(b)
    M0 = BilinearForm(lambda u, v, w: rho * dot(u, v)).assemble(b)
    _, K, M = assemble(m, order, lam, mu, rho)
    assert abs(K - K0).max() < 1e-12 * abs(K0).max()
    assert abs(M - M0).max() < 1e-12 * abs(M0).max()


def test_housing_mesh_regions(housing_mesh):
    b = housing_mesh.mesh.boundaries
    for name in [f"seat_{s}" for s in STATIONS] + ["feet", "outer", "inner"]:
        assert b[name].size > 0, name
    g = housing_mesh.geometry
    for j, s in enumerate(STATIONS):            # every seat facet on its bore, within the bearing's width
        v = housing_mesh.mesh.p[:, housing_mesh.mesh.facets[:, b[f"seat_{s}"]]]
        x, y = g.axis(j)
        assert np.allclose(np.hypot(v[0] - x, v[1] - y), g.bore_radius[j // 2], rtol=1e-6)


def test_rigid_seats_clamped_feet_and_mass(structure, reduced):
    """A seat's nodes follow its master rigidly (a unit master translation moves every seat node by it); the
    clamped housing has no rigid-body mode; the mass is ρ V."""
    T = structure.T
    w = np.zeros(T.shape[1])
    w[structure.seat_dofs[0, 1]] = 1.0                      # pinion_L seat, +y
    u = T @ w
    assert np.isclose(u.max(), 1.0) and np.isclose(u.min(), 0.0) and np.count_nonzero(u) > 10
    assert reduced.frequencies()[0] > 100.0
    assert 5.0 < reduced.mass < 50.0
    assert reduced.sensor_map.shape == (4, reduced.n)
    assert np.isclose(reduced.surface_area.sum(), reduced.surface_area.sum()) and reduced.surface_area.sum() > 0.1


def test_surface_normals_point_outward(housing_mesh):
    """The outer surface's lumped normals point away from the housing: n · (x − c) > 0 at nearly every outer vertex
    (c the cavity's centre; the feet's sides and the bosses' ends are the few exceptions)."""
    from femgear.physics.housing.fe import _outer_surface

    area, normal, verts = _outer_surface(housing_mesh.mesh)
    lo, hi = housing_mesh.geometry.cavity()
    x = housing_mesh.mesh.p[:, verts].T - 0.5 * (lo + hi)
    assert np.mean(np.einsum("vc,vc->v", normal, x) > 0) > 0.9
    assert np.allclose(np.linalg.norm(normal, axis=1), 1.0)
