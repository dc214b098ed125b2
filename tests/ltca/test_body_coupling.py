"""The member bodies hold both helices: cross-helix kernels, the stagger, the groove, the solvers, the cache key."""

import numpy as np
import pytest

from femgear.scene.schema import Modifications


def test_a_load_on_one_helix_deflects_the_other_through_the_body(coarse_model, baseline_pair):
    """The cross kernel (right helix read, left loaded) is largest where the helices meet (the apex, ζ = b)
    and falls off towards the outer ends; in the contact operator it couples points of different helices."""
    from femgear.physics.ltca.contact import bulk_matrix, phase_points

    for member in (1, 2):
        k = coarse_model.kernels[member]
        mid = int(np.nonzero(k.offsets == 0)[0][0])
        nz = k.z.size
        X = np.abs(k.cross[mid]).reshape(k.rho.size, nz, k.rho.size, nz)
        apex = X[:, -1, :, -1].mean()
        outer = X[:, 0, :, 0].mean()
        assert apex > 2 * outer > 0
        assert np.abs(k.cross).max() < np.abs(k.bulk[mid]).max()
    pts = phase_points(baseline_pair, 0.3, 0.0, 8)
    C = bulk_matrix(baseline_pair, coarse_model.kernels, pts)
    across = C[np.ix_(pts.helix == 1, pts.helix == 0)]
    assert np.abs(across).max() > 0
    assert np.allclose(C, C.T)


@pytest.mark.slow
def test_staggered_grooved_body_loads_both_helices(baseline_pair, baseline_force, tmp_path, monkeypatch):
    """A staggered body (groove 5 mm, stagger 0.3) has its own right-helix kernels; loads still sum to the
    force, unmodified flanks still give zero unloaded TE, and a cycle run with another stagger is refused (≈ 18 s)."""
    monkeypatch.setenv("FEMGEAR_CACHE", str(tmp_path))
    from femgear.physics.ltca.analysis import build_model, mesh_cycle

    model = build_model(baseline_pair, 210e9, 0.3, level=0, n_rho=3, n_z=3, n_teeth=3, groove_width=5e-3,
                        stagger=0.3)
    for k in model.kernels.values():
        assert k.bulk_right is not None and k.groove == 5e-3
        assert np.all(np.diag(k.fe_self) > 0)
    r = mesh_cycle(model, baseline_force, Modifications(), n_phases=8, stagger=0.3)
    assert r.load_error.max() < 1e-6
    assert np.all(r.nlte_left == 0.0) and np.all(r.nlte_right == 0.0)
    with pytest.raises(ValueError, match="stagger"):
        mesh_cycle(model, baseline_force, None, n_phases=4, stagger=0.0)


def test_cache_key_holds_the_body_geometry(baseline_pair):
    from femgear.physics.ltca.compliance import _key
    from femgear.physics.mesh.segment import default_spec

    keys = {_key(baseline_pair, 1, default_spec(baseline_pair, 1, 0, **kw), 210e9, 0.3, 1, 5, 5, 1e-3)
            for kw in ({}, {"r_bore": 0.02}, {"groove": 5e-3}, {"groove": 5e-3, "stagger": 0.3})}
    assert len(keys) == 4


def test_sparse_lu_and_sa_cg_give_the_same_displacements():
    import skfem

    from femgear.physics.body.elastic3d import Elastic3D, auto_solver, cholmod_available

    mesh = skfem.MeshTet.init_tensor(np.linspace(0, 0.04, 9), np.linspace(0, 0.01, 4), np.linspace(0, 0.01, 4))
    mesh = mesh.with_boundaries({"bore": lambda x: x[0] < 1e-9})
    f = np.zeros(3 * mesh.p.shape[1])
    tip = np.nonzero(mesh.p[0] > 0.04 - 1e-9)[0]
    f[3 * tip + 1] = -1.0 / tip.size
    lu = Elastic3D(mesh, 210e9, 0.3, order=1, solver="lu")
    amg = Elastic3D(mesh, 210e9, 0.3, order=1, solver="amg", tol=1e-11)
    u_lu, u_amg = lu.solve(f), amg.solve(f)
    assert np.abs(u_lu).max() > 0
    assert np.allclose(u_lu, u_amg, rtol=0, atol=1e-7 * np.abs(u_lu).max())
    assert np.allclose(lu.solve_many(np.column_stack([f, 2 * f]))[:, 1], 2 * u_lu)
    assert Elastic3D(mesh, 210e9, 0.3, order=1, solver="auto").solver == auto_solver(1, 0)
    with pytest.raises(ValueError, match="solver"):
        Elastic3D(mesh, 210e9, 0.3, solver="cholesky")
    if cholmod_available():     # the CHOLMOD block solve: the same displacements
        chol = Elastic3D(mesh, 210e9, 0.3, order=1, solver="cholmod")
        assert np.allclose(chol.solve_many(np.column_stack([f, 2 * f])), np.column_stack([u_lu, 2 * u_lu]),
                           rtol=0, atol=1e-9 * np.abs(u_lu).max())


def test_direct_p1_assembly_equals_scikit_fem():
    """The chunked constant-strain P1 assembly reproduces scikit-fem's form on a distorted mesh."""
    import skfem

    from femgear.physics.body.elastic3d import _elasticity_form, assemble_p1

    mesh = skfem.MeshTet.init_tensor(np.linspace(0, 0.02, 5), np.linspace(0, 0.01, 4), np.linspace(0, 0.01, 3))
    p = mesh.p + 1e-4 * np.sin(mesh.p * 400.0)          # non-affine nodes: every element different
    mesh = skfem.MeshTet(p, mesh.t)
    basis = skfem.Basis(mesh, skfem.ElementVector(skfem.ElementTetP1()), intorder=1)
    K0 = _elasticity_form(1.2e11, 8.1e10).assemble(basis)
    K1 = assemble_p1(mesh, basis.element_dofs, basis.N, 1.2e11, 8.1e10, chunk=7)
    assert abs(K0 - K1).max() < 1e-12 * abs(K0).max()


def test_an_unsettled_hertz_width_fixed_point_raises_with_its_history(coarse_model, baseline_pair, baseline_force):
    """Two passes cannot settle the load-dependent strip width from the uniform start: the solver raises
    ConvergenceError carrying the load change of every pass (decreasing: a linear fixed point), and with
    the default pass limit the same phase converges."""
    from femgear.errors import ConvergenceError
    from femgear.physics.ltca.contact import phase_points, solve_phase

    pts = phase_points(baseline_pair, 0.3, 0.0, 8)
    eps = np.zeros(pts.size)
    with pytest.raises(ConvergenceError) as info:
        solve_phase(baseline_pair, coarse_model.kernels, pts, eps, baseline_force, 210e9, 0.3, max_pass=2)
    changes = info.value.history["load_change"]
    assert len(changes) == 2 and changes[1] < changes[0]
    sol, _, passes = solve_phase(baseline_pair, coarse_model.kernels, pts, eps, baseline_force, 210e9, 0.3)
    assert 2 < passes <= 80 and sol.load.sum() == pytest.approx(baseline_force, rel=1e-9)
