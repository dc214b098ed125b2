"""One roughness description of the flanks (issue 38, item 4): ``[roughness]`` gives R_a or R_q per member and the
finishing; the ratings (λ_GF, μ_mC) and the tribology (the Greenwood–Tripp σ) both read it; the old keys keep
working for one release with a line naming the new key; bad values end in one line naming the key, exit 2."""

from __future__ import annotations

import logging
import math

import numpy as np
import pytest

from femgear.case import build_case
from femgear.edge.cli import main
from femgear.errors import SceneError
from femgear.levels.lubrication import line_friction
from femgear.rate import scene_info
from femgear.scene import load_scene

STATIC = ['physics.dynamics="none"', 'physics.coupling="one-way"', "numerics.path_points=5"]


def _case(path, *extra):
    return build_case(load_scene(path, [*STATIC, *extra]))


def test_ra_per_member_feeds_the_ratings_and_the_tribology(baseline_path):
    case = _case(baseline_path, "roughness.ra=[0.3e-6, 0.5e-6]")
    f = case.flanks
    assert f.ra == (0.3e-6, 0.5e-6) and f.ra_mean == pytest.approx(0.4e-6)
    rq = [a * math.sqrt(math.pi / 2) for a in f.ra]               # Gaussian heights
    assert f.sigma == pytest.approx(math.hypot(*rq), rel=1e-12)
    assert line_friction(case).roughness.sigma == f.sigma
    info = scene_info(case)
    own, mp = info.rating.own, info.rating.micropitting
    np.testing.assert_allclose(own.specific_film * 0.4e-6, own.film, rtol=1e-12)          # femgear's λ
    np.testing.assert_allclose(mp.lambda_GF * 0.4e-6, mp.film, rtol=1e-12)               # ISO's λ_GF


def test_rq_given_sets_ra_and_smooth_keeps_the_ratings_roughness(baseline_path):
    case = _case(baseline_path, "roughness.rq=[0.5e-6, 0.5e-6]", 'roughness.model="smooth"')
    assert case.flanks.ra[0] == pytest.approx(0.5e-6 / math.sqrt(math.pi / 2))
    assert line_friction(case).roughness is None


def test_the_finishing_sets_ra_and_the_default_is_ground(baseline_path):
    assert _case(baseline_path).flanks.ra == (0.4e-6, 0.4e-6)
    assert _case(baseline_path, 'roughness.finishing="hobbed"').flanks.ra == (1.6e-6, 1.6e-6)


@pytest.mark.parametrize("old,new", [("rating.roughness_ra=[0.3e-6, 0.3e-6]", "roughness.ra"),
                                     ('rating.finishing="honed"', "roughness.finishing"),
                                     ("roughness.rq=0.6e-6", "roughness.rq = [R_q1, R_q2]"),
                                     ("roughness.rq=0.0", 'roughness.model = "smooth"')])
def test_the_old_keys_keep_working_with_a_line_naming_the_new_key(baseline_path, caplog, old, new):
    with caplog.at_level(logging.WARNING, logger="femgear"):
        case = _case(baseline_path, old)
    key = old.split("=")[0]
    lines = [r.getMessage() for r in caplog.records if r.getMessage().startswith(key + ":")]
    assert len(lines) == 1 and "deprecated" in lines[0] and new in lines[0], lines
    f = case.flanks
    if key == "rating.roughness_ra":
        assert f.ra == (0.3e-6, 0.3e-6)
    elif key == "rating.finishing":
        assert f.ra == (0.3e-6, 0.3e-6)
    elif old.endswith("0.0"):
        assert f.model == "smooth" and line_friction(case).roughness is None
    else:
        assert line_friction(case).roughness.sigma == 0.6e-6 and f.ra == (0.4e-6, 0.4e-6)


@pytest.mark.parametrize("override,key,words", [
    ("roughness.ra=[0.0, 0.4e-6]", "roughness.ra", ["greater than 0"]),
    ("roughness.ra=[0.4, 0.4]", "roughness.ra", ["impossible", "0.4 µm"]),
    ("roughness.rq=[0.5, 0.5]", "roughness.rq", ["impossible"]),
    ("rating.roughness_ra=[0.4, 0.4]", "rating.roughness_ra", ["impossible"]),
    ("roughness.rq=0.4", "roughness.rq", ["0.4 µm"]),
])
def test_a_roughness_of_zero_or_of_metres_is_refused_naming_the_key(baseline_path, override, key, words):
    with pytest.raises(SceneError) as info:
        load_scene(baseline_path, [override])
    assert info.value.key.startswith(key), str(info.value)
    for word in words:
        assert word in info.value.message, str(info.value)


def test_contradictory_ra_and_rq_are_one_line_exit_2(baseline_path, capsys):
    rc = main(["info", str(baseline_path), "--set", "roughness.ra=[0.4e-6, 0.4e-6]",
               "--set", "roughness.rq=[0.3e-6, 0.5e-6]"])
    err = capsys.readouterr().err.strip().splitlines()
    assert rc == 2 and len(err) == 1 and "roughness.rq" in err[0] and "contradicts" in err[0], err
    consistent = ["roughness.ra=[0.4e-6, 0.4e-6]", "roughness.rq=[0.5e-6, 0.52e-6]"]
    assert _case(baseline_path, *consistent).flanks.rq == (0.5e-6, 0.52e-6)


def test_old_and_new_given_together_is_refused(baseline_path):
    with pytest.raises(SceneError) as info:
        load_scene(baseline_path, ["rating.roughness_ra=[0.3e-6, 0.3e-6]", "roughness.ra=[0.4e-6, 0.4e-6]"])
    assert info.value.key == "rating.roughness_ra"
