"""`femgear run` honours every physics level it accepts (none is silently ignored)."""

import pytest

from femgear.pipeline import run_scene
from femgear.scene import load_scene


@pytest.mark.parametrize("level", ["analytic"])
def test_thermal_level_reports_flank_deviation(baseline_path, tmp_path, level):
    scene = load_scene(baseline_path, [f'physics.thermal="{level}"', "thermal.flank_temperature_rise=30"])
    s = run_scene(scene, tmp_path, plots=False).summary
    assert 1e-6 < s["thermal"]["deviation_pitch_pinion"] < 2e-5


def test_stiffness_level_is_computed(baseline_path, tmp_path):
    s = run_scene(load_scene(baseline_path, ['physics.stiffness="pem"']), tmp_path, plots=False).summary
    assert s["stiffness"]["level"] == "pem" and s["stiffness"]["ripple_total"] > 0.01


def test_lubrication_levels(baseline_path, tmp_path):
    none = run_scene(load_scene(baseline_path, ['physics.lubrication="none"']), tmp_path, plots=False).summary
    const = run_scene(load_scene(baseline_path, ['physics.lubrication="constant"', "friction.coefficient=0.07"]),
                      tmp_path, plots=False).summary
    assert "friction" not in none
    assert const["friction"]["mu_mean"] == pytest.approx(0.07)


def test_ehl_line_level_gives_a_u_shaped_friction(baseline_path, tmp_path):
    scene = load_scene(baseline_path, ['physics.lubrication="ehl-line"', 'physics.dynamics="none"',
                                       'physics.coupling="one-way"', "numerics.path_points=9", "numerics.ehl_level=4"])
    f = run_scene(scene, tmp_path, plots=False).summary["friction"]
    assert f["mu_pitch"] < 1e-3 < 0.01 < f["mu_max"] < 0.1


@pytest.mark.parametrize("scene_file", ["fzg_c14.toml", "single_helical.toml"])
def test_one_mesh_pairs_run_coupled_dynamics(scene_file, tmp_path):
    """Spur and single-helical pairs through the coupled pipeline (lumped level, one mesh in the
    mid-plane): the mean dynamic mesh force carries F_bn (within the friction-loss share, 1 %),
    the absent right mesh carries nothing, and a spur pair has no axial response."""
    from pathlib import Path

    base = Path(__file__).resolve().parents[1] / "studies" / scene_file
    scene = load_scene(base, ['physics.dynamics="lumped"', 'physics.coupling="one-way"',
                              "numerics.dynamics_cycles=40.0", "numerics.transient_cycles=20.0"])
    s = run_scene(scene, tmp_path, plots=False).summary
    a = s["dynamics"]["amplitudes"]
    assert a["mesh_force.L.mean"] == pytest.approx(s["contact"]["normal_force"], rel=0.01)
    assert a["mesh_force.R.mean"] == 0.0 and a["mesh_force.R.amplitude"] == 0.0
    if scene_file.startswith("fzg"):
        assert a["gear.displacement.z"] < 1e-12 and a["pinion.displacement.z"] < 1e-12
