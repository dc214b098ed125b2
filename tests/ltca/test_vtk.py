"""The LTCA pressure map on the 3-D pinion flanks of both helices (femgear.physics.ltca.flank_map)."""

import math
from pathlib import Path

import numpy as np
import pytest

from femgear.physics.ltca.cycle import LTCACycle
from femgear.scene.schema import Modifications

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def symmetric_cycle(coarse_model, baseline_force):
    from femgear.physics.ltca.analysis import mesh_cycle

    return mesh_cycle(coarse_model, baseline_force, Modifications(crowning=4e-6), n_phases=8)


def test_symmetric_pair_has_the_same_pressure_map_on_both_helices(symmetric_cycle, baseline_pair):
    """Both helices' maps are equal, and each integrates to its helix's cycle-mean LTCA load."""
    from femgear.physics.ltca.flank_map import flank_pressure_map

    fmap = flank_pressure_map(symmetric_cycle, baseline_pair, 210e9, 0.3)
    assert fmap.p_max[0].max() > 1e8
    assert np.allclose(fmap.p_max[0], fmap.p_max[1], rtol=1e-6, atol=1e-6 * fmap.p_max.max())
    assert np.allclose(fmap.w_mean[0], fmap.w_mean[1], rtol=1e-6, atol=1e-6 * fmap.w_mean.max())
    loaded = fmap.p_max[0] > 0
    assert loaded.any(axis=0).mean() > 0.9            # the face columns are crossed by the lines (no stripes in ζ;
    #                                                  the crowning unloads the very ends)
    forces = fmap.helix_force()
    assert forces[0] == pytest.approx(symmetric_cycle.force_left.mean(), rel=0.03)
    assert forces[1] == pytest.approx(symmetric_cycle.force_right.mean(), rel=0.03)


def test_helix_slope_deviation_moves_the_map_load_to_the_other_helix(coarse_model, baseline_force, baseline_pair,
                                                                     symmetric_cycle):
    from femgear.physics.ltca.analysis import mesh_cycle
    from femgear.physics.ltca.flank_map import flank_pressure_map

    r = mesh_cycle(coarse_model, baseline_force, Modifications(crowning=4e-6, helix_slope_deviation_left=10e-6),
                   n_phases=8)
    dev = flank_pressure_map(r, baseline_pair, 210e9, 0.3).helix_force()
    sym = flank_pressure_map(symmetric_cycle, baseline_pair, 210e9, 0.3).helix_force()
    assert dev[1] > 1.05 * dev[0]
    assert dev[0] < sym[0] and dev[1] > sym[1]
    assert dev[0] == pytest.approx(r.force_left.mean(), rel=0.03)
    assert dev[1] == pytest.approx(r.force_right.mean(), rel=0.03)


def test_pressure_map_vtk_lies_on_the_3d_flanks_of_both_helices(symmetric_cycle, baseline_pair, tmp_path):
    """The .vtu holds both helices: the left on the helicoid (r² = ρ² + r_b²), the right its mirror image
    z → 2b + g − z (no stagger), with the same pressures."""
    import meshio

    from femgear.edge.io.ltca import write_flank_pressure

    path = write_flank_pressure(tmp_path / "p.vtu", symmetric_cycle, baseline_pair, 210e9, 0.3)
    m = meshio.read(path)
    helix = m.point_data["helix"]
    left, right = m.points[helix == 0], m.points[helix == 1]
    assert left.shape == right.shape and m.point_data["p_max"].max() > 1e8
    rho = m.point_data["rho"][helix == 0]
    assert np.allclose(np.hypot(left[:, 0], left[:, 1]), np.hypot(rho, baseline_pair.rb1), rtol=1e-12)
    assert left[:, 2].min() == pytest.approx(0.0) and left[:, 2].max() == pytest.approx(baseline_pair.b)
    assert np.allclose(right[:, :2], left[:, :2]) and np.allclose(right[:, 2], 2 * baseline_pair.b - left[:, 2])
    assert np.allclose(m.point_data["p_max"][helix == 0], m.point_data["p_max"][helix == 1], rtol=1e-6,
                       atol=1e-6 * m.point_data["p_max"].max())


def test_right_helix_mapping_lies_on_the_staggered_body_flank(baseline_pair):
    """The right helix's (ρ, ζ) → 3-D map of the pressure map (and of the kernels' reading points) lands on the
    nodes of the body's ``loaded_flank_right`` for a grooved, staggered body."""
    from femgear.physics.ltca.flank import flank_points
    from femgear.physics.mesh.segment import default_spec, frame_of, member_body

    pair = baseline_pair
    spec = default_spec(pair, 1, 0, n_teeth=3, groove=8e-3, stagger=0.3)
    body = member_body(pair, 1, spec)
    nodes = body.p[:, np.unique(body.facets[:, body.boundaries["loaded_flank_right"]])]
    frame = frame_of(pair, 1, 8e-3, 0.3)
    zeta = frame.width - nodes[2]
    rho = np.sqrt(np.maximum(nodes[0] ** 2 + nodes[1] ** 2 - pair.rb1 ** 2, 0.0))
    r0 = math.sqrt(pair.u_start ** 2 + pair.rb1 ** 2)
    active = np.hypot(nodes[0], nodes[1]) > r0 + 1e-6        # the involute part (the flank region reaches the fillet)
    mapped = frame.to_right(flank_points(pair, 1, rho, zeta))
    assert active.sum() > 10
    assert np.abs(mapped - nodes)[:, active].max() < 1e-6


def test_the_main_job_writes_the_pressure_map_with_the_ltca_level(symmetric_cycle, tmp_path):
    """``write_run_paraview`` (``femgear run``'s ParaView output) adds ``ltca_pressure.vtu`` when the stiffness level
    carries an LTCA cycle (here the coarse one in a quasi-static run's result, whose maps the driver's stage
    :func:`femgear.stages.ltca_maps` computes), and only then."""
    import dataclasses

    import meshio

    from femgear.case import build_case
    from femgear.edge.io.paraview_run import write_run_paraview
    from femgear.pipeline import run_case
    from femgear.scene import load_scene
    from femgear.stages import ltca_maps

    scene = load_scene(ROOT / "studies" / "paper_baseline.toml",
                       ['physics.dynamics="none"', 'physics.coupling="one-way"', 'physics.lubrication="constant"',
                        'physics.thermal="none"', 'physics.wear="none"', 'physics.stiffness="iso6336"'])
    result = run_case(build_case(scene))
    assert "ltca_pressure_vtu" not in write_run_paraview(result, tmp_path / "iso")
    ltca = dataclasses.replace(result, stiffness=dataclasses.replace(result.stiffness, level="ltca",
                                                                     ltca=LTCACycle.from_result(symmetric_cycle)))
    assert result.ltca_maps is None
    ltca = dataclasses.replace(ltca, ltca_maps=ltca_maps(ltca))
    files = write_run_paraview(ltca, tmp_path / "ltca")
    assert files["ltca_pressure_vtu"] == tmp_path / "ltca" / "ltca_pressure.vtu"
    m = meshio.read(files["ltca_pressure_vtu"])
    assert set(np.unique(m.point_data["helix"])) == {0, 1} and m.point_data["p_max"].max() > 1e8
    assert not list((tmp_path / "ltca").glob(".*tmp*"))


def test_edge_contacts_are_flagged_not_shown_as_hertz_pressures(coarse_model, baseline_force, baseline_pair, tmp_path):
    """Unmodified flanks: the contact lines end on the tip edge and the face ends, whose short last pieces carry
    many times the mean load per length (64 phases meet such a piece: 7.6 GPa at the tip/face-end corner
    against a 0.50 GPa median on this mesh).  The map's largest pressure lies on a flagged edge node; inside the
    flank the pressure stays within a factor 2 of its median (1.57 here: the
    single-/double-contact variation), and the .vtu carries the flag."""
    import meshio

    from femgear.edge.io.ltca import write_flank_pressure
    from femgear.physics.ltca.analysis import mesh_cycle
    from femgear.physics.ltca.flank_map import flank_pressure_map

    r = mesh_cycle(coarse_model, baseline_force, Modifications(), n_phases=64)
    fmap = flank_pressure_map(r, baseline_pair, 210e9, 0.3)
    p = fmap.p_max[0]
    assert fmap.edge[np.unravel_index(np.argmax(p), p.shape)]
    inner = p[~fmap.edge & (p > 0)]
    assert p.max() > 2.0 * inner.max()                 # the edge value is not a Hertz pressure of the line
    assert inner.max() < 2.0 * np.median(inner)
    m = meshio.read(write_flank_pressure(tmp_path / "e.vtu", r, baseline_pair, 210e9, 0.3))
    assert set(np.unique(m.point_data["edge"])) == {0, 1}
