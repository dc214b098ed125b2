"""Point location in the 3-D bodies and the distributing (mean-motion) support of the 2-D sections.

- :func:`femgear.physics.body.elastic3d.locate` finds the tetrahedron of points given by barycentric weights, and
  the probe matrices built on it equal scikit-fem's ``probes`` (to round-off) without its all-element search.
- :meth:`femgear.physics.body.elastic.ElasticProblem.tie` under a self-equilibrated load gives the free body's
  deformation, with the bore's mean rigid motion zero: a statically determinate support plus the rigid motion
  that cancels the bore's mean.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from femgear.physics.geometry.gear import GearPair


@pytest.fixture(scope="module")
def body():
    from femgear.physics.mesh.segment import default_spec, member_body

    p = GearPair.from_parameters(z1=24, z2=30, m_n=4e-3, alpha_n=math.radians(20), beta=math.radians(25),
                                 b=12e-3, x1=0.0, x2=0.0)
    return member_body(p, 1, default_spec(p, 1, 0, r_bore=0.02))


@pytest.mark.parametrize("order", [1, 2])
def test_probes_find_the_element_and_match_scikit_fem(body, order):
    """P1 on a member body (thin tetrahedra at the tips, the layers), P2 on a box (its assembly is quick)."""
    from skfem import MeshTet

    from femgear.physics.body.elastic3d import Elastic3D, locate

    if order == 2:
        body = MeshTet.init_tensor(*(np.linspace(0.0, 0.01, 7),) * 3)
    rng = np.random.default_rng(3)
    el = rng.integers(0, body.t.shape[1], 60)
    w = rng.dirichlet(np.ones(4) * 3, 60).T                        # strictly inside each element
    x = np.einsum("dvn,vn->dn", body.p[:, body.t[:, el]], w)
    assert np.array_equal(locate(body, x), el)
    model = Elastic3D(body, 2e11, 0.3, order=order, solver="amg", clamped=None)
    u = rng.standard_normal(model.basis.N)
    ours = model.probe(u, x)
    skfem = np.vstack([b.probes(x) @ c for c, b in model.basis.split(u)])
    np.testing.assert_allclose(ours, skfem, rtol=0, atol=1e-12 * np.abs(skfem).max())


def test_a_point_outside_the_body_is_refused(body):
    from femgear.physics.body.elastic3d import locate

    with pytest.raises(ValueError, match="outside the body"):
        locate(body, np.array([[0.0], [0.0], [0.006]]))         # on the axis, inside the bore


def test_the_tie_holds_the_bores_mean_motion_and_leaves_the_free_deformation():
    from skfem import FacetBasis, LinearForm

    from femgear.physics.body.elastic import ElasticProblem, rigid_body_modes
    from femgear.physics.mesh.section import annulus

    mesh = annulus(0.02, 0.05, 0.004)
    E, nu = 2e11, 0.3

    @LinearForm
    def squeeze(v, w):                         # a radial pressure ∝ cos 2θ on the outer circle: self-equilibrated
        r = np.hypot(w.x[0], w.x[1])
        c2 = (w.x[0] ** 2 - w.x[1] ** 2) / r**2
        return -1e6 * c2 * (w.x[0] * v[0] + w.x[1] * v[1]) / r

    tied = ElasticProblem(mesh, E, nu, "strain", solver="lu")
    f = squeeze.assemble(FacetBasis(mesh, tied.basis.elem, facets=mesh.boundaries["outer"]))
    tied.tie("inner")
    u_tie, _ = tied.solve(f)
    free = ElasticProblem(mesh, E, nu, "strain", solver="lu")  # statically determinate: three DOF on the bore
    dofs = [free.nearest_dof((0.02, 0.0), "x"), free.nearest_dof((0.02, 0.0), "y"), free.nearest_dof((-0.02, 0.0), "y")]
    free.fix(np.array(dofs), 0.0)
    u_det, _ = free.solve(f)
    C, R = tied._C, rigid_body_modes(tied.basis)
    u_free = u_det - R @ np.linalg.solve(C @ R, C @ u_det)       # the rigid motion that zeroes the bore's mean
    assert np.abs(C @ u_tie).max() <= 1e-12 * np.abs(u_tie).max() * np.abs(C).sum()
    np.testing.assert_allclose(u_tie, u_free, atol=1e-9 * np.abs(u_free).max())
