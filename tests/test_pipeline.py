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
