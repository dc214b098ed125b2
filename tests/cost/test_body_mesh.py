"""Member-body meshes in module units (issue 26): similar gears get the same mesh, the coarse far-field
layers keep the mesh conforming, the size estimate counts the mesh."""

from dataclasses import replace

import numpy as np
import pytest

from femgear.case.pair import pair_from_scene
from femgear.physics.mesh.segment import (
    body_size,
    coarse_layers,
    default_spec,
    groove_layers,
    member_body,
    mesh_revision,
)


def _boundary_area(mesh, facets) -> float:
    P = mesh.p[:, mesh.facets[:, facets]]
    return float(0.5 * np.linalg.norm(np.cross(P[:, 1] - P[:, 0], P[:, 2] - P[:, 0], axis=0), axis=0).sum())


def _volume(mesh) -> float:
    P = mesh.p[:, mesh.t]
    d = np.einsum("ij,ij->j", P[:, 1] - P[:, 0], np.cross(P[:, 2] - P[:, 0], P[:, 3] - P[:, 0], axis=0))
    return float(np.abs(d).sum() / 6)


@pytest.fixture(scope="module")
def grooved(baseline_scene):
    """The baseline pair with a 10 mm groove (both the far field and the groove layers are graded)."""
    from femgear.scene import load_scene
    from tests.conftest import BASELINE

    scene = load_scene(BASELINE, ["pair.groove_width=0.01"])
    return pair_from_scene(scene), scene


def test_coarse_far_layers_keep_the_body_conforming(grooved):
    """The transition columns match both neighbours: no face is left unmatched (the boundary area, every named
    region's area and the volume equal those of the body swept finely everywhere, up to the twisted rim's
    facets), and every region the fine sweep names is there."""
    pair, _ = grooved
    spec = default_spec(pair, 2, 0, r_bore=0.02, groove=0.01)
    coarse, fine = member_body(pair, 2, spec), member_body(pair, 2, replace(spec, far_dz=0.0))
    assert coarse.p.shape[1] < 0.9 * fine.p.shape[1]
    assert _volume(coarse) == pytest.approx(_volume(fine), rel=1e-3)
    assert _boundary_area(coarse, coarse.boundary_facets()) == pytest.approx(
        _boundary_area(fine, fine.boundary_facets()), rel=1e-3)
    assert set(coarse.boundaries) == set(fine.boundaries)
    for name in ("flank", "loaded_flank", "loaded_flank_right", "groove_floor", "groove_wall", "end0"):
        assert _boundary_area(coarse, coarse.boundaries[name]) == pytest.approx(
            _boundary_area(fine, fine.boundaries[name]), rel=1e-9), name


def test_body_size_counts_the_mesh(grooved):
    pair, _ = grooved
    for member in (1, 2):
        spec = default_spec(pair, member, 0, r_bore=0.02, groove=0.01)
        mesh = member_body(pair, member, spec)
        nodes, tets = body_size(pair, member, spec)
        assert nodes == mesh.p.shape[1]
        assert tets == pytest.approx(mesh.t.shape[1], rel=0.03)


def test_similar_gears_get_the_same_mesh(baseline_pair):
    """All lengths × 2 (module, face width, bore): the same number of nodes and elements."""
    a = baseline_pair
    b = replace(a, m_n=2 * a.m_n, b=2 * a.b)
    for member in (1, 2):
        sa = default_spec(a, member, 1, r_bore=0.02)
        sb = default_spec(b, member, 1, r_bore=0.04)
        assert sb.h_tooth == pytest.approx(2 * sa.h_tooth) and sb.layers == sa.layers
        assert body_size(b, member, sb) == body_size(a, member, sa)


def test_groove_layers_grade_from_the_helices_and_cover_the_groove():
    z = groove_layers(0.0, 0.04, 0.003, 0.35, 0.012)
    assert z[-1] == pytest.approx(0.04) and np.all(np.diff(z) > 0)
    steps = np.diff(np.r_[0.0, z])
    assert steps.max() <= 0.012 * 1.05 and steps[0] < 1.5 * 0.003
    assert z.size < 0.04 / 0.003 - 2


def test_coarse_layers_keep_the_ends_and_the_groove_walls():
    layers = coarse_layers(31, 10, 20, 4)
    assert {0, 10, 20, 30} <= set(layers.tolist())
    assert np.all(np.diff(layers) <= 4)


def test_cache_keys_change_only_where_the_mesh_did(baseline_pair):
    """A body without a groove and with the far layers off is the mesh of before (its cache stays valid)."""
    spec = default_spec(baseline_pair, 1, 1, r_bore=0.02)
    assert mesh_revision(baseline_pair, 1, replace(spec, far_dz=0.0)) is None
    assert mesh_revision(baseline_pair, 1, spec) is not None
