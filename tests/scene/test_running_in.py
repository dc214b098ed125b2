"""Running-in of the flanks (``roughness.state``): the as-manufactured roughness times the running-in factor of
the finishing, read by the ratings and the tribology alike.  Source of the factors: the GearCalc manual
(Geartech), §14.12 "Surface roughness", typical RMS roughness of gear teeth as manufactured and after run-in."""

from __future__ import annotations

import math

import numpy as np
import pytest

from femgear.case import build_case
from femgear.errors import SceneError
from femgear.levels.lubrication import line_friction
from femgear.physics.lubrication.running_in import RUN_IN_FACTOR, RUN_IN_TABLE, run_in_factor
from femgear.rate import scene_info
from femgear.scene import load_scene

STATIC = ['physics.dynamics="none"', 'physics.coupling="one-way"', "numerics.path_points=5"]


def _case(path, *extra):
    return build_case(load_scene(path, [*STATIC, *extra]))


def test_the_factors_are_the_manuals_range_midpoints():
    """Grinding 10–40 → 10–25 µin rms: 17.5/25; honing 6–20 → 5–15: 10/13; hobbing 30–80 → 20–45: 32.5/55."""
    assert RUN_IN_TABLE["ground"] == ((10.0, 40.0), (10.0, 25.0))
    assert run_in_factor("ground") == pytest.approx(0.70) and run_in_factor("shaved") == pytest.approx(0.70)
    assert run_in_factor("honed") == pytest.approx(10 / 13) and run_in_factor("hobbed") == pytest.approx(32.5 / 55)
    assert all(0 < f < 1 for f in RUN_IN_FACTOR.values())
    with pytest.raises(ValueError, match="lapped"):
        run_in_factor("lapped")


def test_run_in_flanks_feed_the_ratings_and_the_tribology(baseline_path):
    new = _case(baseline_path, "roughness.ra=[0.5e-6, 0.3e-6]", 'roughness.finishing="ground"')
    run = _case(baseline_path, "roughness.ra=[0.5e-6, 0.3e-6]", 'roughness.finishing="ground"',
                'roughness.state="run-in"')
    f = run.flanks
    assert f.state == "run-in" and f.run_in_factor == pytest.approx(0.70)
    assert f.ra == pytest.approx((0.35e-6, 0.21e-6)) and f.sigma == pytest.approx(0.70 * new.flanks.sigma)
    assert "run-in" in f.source and line_friction(run).roughness.sigma == f.sigma
    mp_new, mp_run = scene_info(new).rating.micropitting, scene_info(run).rating.micropitting
    np.testing.assert_allclose(mp_run.lambda_GF * f.ra_mean, mp_run.film, rtol=1e-12)     # ISO's λ_GF reads it
    assert np.all(mp_run.lambda_GF > mp_new.lambda_GF)


def test_the_finishing_factor_and_an_own_factor(baseline_path):
    hobbed = _case(baseline_path, 'roughness.finishing="hobbed"', 'roughness.state="run-in"').flanks
    assert hobbed.ra[0] == pytest.approx(1.6e-6 * 32.5 / 55)
    own = _case(baseline_path, "roughness.rq=[0.5e-6, 0.5e-6]", 'roughness.state="run-in"',
                "roughness.run_in_factor=0.5").flanks
    assert own.rq == pytest.approx((0.25e-6, 0.25e-6)) and own.sigma == pytest.approx(0.25e-6 * math.sqrt(2))
    assert "roughness.run_in_factor" in own.source


def test_a_factor_without_the_run_in_state_is_refused(baseline_path):
    with pytest.raises(SceneError, match="roughness.run_in_factor"):
        _case(baseline_path, "roughness.run_in_factor=0.6")
