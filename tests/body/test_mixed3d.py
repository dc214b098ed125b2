"""P2 where the body bends, P1 elsewhere (:mod:`femgear.physics.body.mixed3d`): validation on a cantilever.

A cantilever (10 × 1 × 1, E = 1000, ν = 0.3) clamped at x = 0 under a unit transverse tip
load: Euler–Bernoulli P L³/(3 E I) = 4.0 plus Timoshenko's shear term P L/(κ G A) = 0.0312
(κ = 5/6, G = E/2.6) gives 4.031 (Timoshenko & Goodier, Theory of Elasticity, §21; the clamped
end's local flexibility adds a little more).  Linear tetrahedra, two across the depth, give
about half of it (stiff in bending); quadratic ones are within 2 %.
"""

from __future__ import annotations

import numpy as np
import pytest
from skfem import LinearForm, MeshTet

from femgear.physics.body.elastic3d import Elastic3D
from femgear.physics.body.mixed3d import MixedElastic3D, free_edges

BEAM = 4.0 + 10 / (5 / 6 * 1e3 / 2.6)      #: Timoshenko tip deflection [m] for P = 1 N


@LinearForm
def _down(v, w):
    return -1.0 * v[1]


def _beam():
    m = MeshTet.init_tensor(np.linspace(0, 10, 21), np.linspace(0, 1, 3), np.linspace(0, 1, 3))
    return m.with_boundaries({"root": lambda x: x[0] < 1e-9, "tip": lambda x: x[0] > 10 - 1e-9})


def _tip(model) -> float:
    f = model.lift(_down.assemble(model.facet_basis(model.mesh.boundaries["tip"])))
    u = model.solve_many(f[:, None])[:, 0]
    return -float(model.probe(u, np.array([[9.99], [0.5], [0.5]]))[1, 0])


@pytest.fixture(scope="module")
def beam():
    return _beam()


def test_quadratic_beam_meets_timoshenko_and_linear_is_stiff(beam):
    n = beam.t.shape[1]
    quad = _tip(MixedElastic3D(beam, 1e3, 0.3, np.ones(n, bool), clamped="root"))
    lin = _tip(MixedElastic3D(beam, 1e3, 0.3, np.zeros(n, bool), clamped="root"))
    assert quad == pytest.approx(BEAM, rel=0.02)
    assert lin < 0.6 * BEAM


def test_all_quadratic_and_all_linear_are_the_uniform_models(beam):
    n = beam.t.shape[1]
    for flags, order in ((np.ones(n, bool), 2), (np.zeros(n, bool), 1)):
        mixed = _tip(MixedElastic3D(beam, 1e3, 0.3, flags, clamped="root"))
        assert mixed == pytest.approx(_tip(Elastic3D(beam, 1e3, 0.3, order=order, clamped="root", solver="auto")),
                                      rel=1e-9)


def test_quadratic_where_it_bends_recovers_most_of_the_beam(beam):
    """The half of the beam at the root (where the moment is largest) quadratic: between P1 and P2, and the
    model stays conforming (a linear field is reproduced exactly: patch test below)."""
    root_half = beam.p[0, beam.t].mean(axis=0) < 5
    tip = _tip(MixedElastic3D(beam, 1e3, 0.3, root_half, clamped="root"))
    assert _tip(MixedElastic3D(beam, 1e3, 0.3, np.zeros(beam.t.shape[1], bool), clamped="root")) < tip < BEAM
    assert tip > 0.9 * BEAM


def test_patch_test_linear_field_is_exact_across_the_interface(beam):
    """Prescribe a linear displacement on the whole boundary of a half-quadratic body (its trace: vertex values,
    zero bubbles): the solution inside is that field, interior bubbles zero — which a non-conforming interface
    would not give."""
    flags = beam.p[0, beam.t].mean(axis=0) < 5
    model = MixedElastic3D(beam, 1e3, 0.3, flags, clamped=None)
    A = np.array([[1e-3, 2e-3, -1e-3], [0.5e-3, -1e-3, 3e-3], [2e-3, 1e-3, 1e-3]])
    lin = np.zeros(model.N)
    nodal = A @ beam.p + np.array([[1e-3], [2e-3], [-1e-3]])
    for c in range(3):
        lin[model.basis.nodal_dofs[c]] = nodal[c]
    boundary = np.unique(beam.facets[:, beam.boundary_facets()])
    on_boundary = np.isin(model.edges, beam.f2e[:, beam.boundary_facets()].ravel())
    bubbles = model.basis.N + 3 * np.nonzero(on_boundary)[0]
    held = np.concatenate([model.basis.nodal_dofs[:, boundary].ravel(), bubbles, bubbles + 1, bubbles + 2])
    K = model.K                                            # no clamp: the full matrix
    free = np.setdiff1d(np.arange(model.N), held)
    rhs = -(K[free][:, held] @ lin[held])
    from scipy.sparse.linalg import spsolve

    u = lin.copy()
    u[free] = spsolve(K[free][:, free].tocsc(), rhs)
    assert np.abs(u - lin).max() < 1e-9 * np.abs(lin).max()
    assert (~on_boundary).any() and free_edges(beam, flags).size == model.edges.size


def test_bad_mask_is_refused(beam):
    with pytest.raises(ValueError, match="quadratic"):
        MixedElastic3D(beam, 1e3, 0.3, np.ones(3, bool), clamped="root")
