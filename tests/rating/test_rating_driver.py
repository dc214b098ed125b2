"""The four safety factors from a scene: defaults and flags, ``femgear info``, ``RunResult.rating`` and results.json."""

import json
import logging
import math
import subprocess
import sys
from pathlib import Path

import pytest

from femgear.case import build_case
from femgear.levels.contact import contact_pass
from femgear.physics.rating.suite import PairRating
from femgear.rate import rate_case
from femgear.scene import load_scene

ROOT = Path(__file__).resolve().parents[2]
FZG = ROOT / "studies" / "fzg_c14.toml"
ALL_KEYS = ["rating.bending_stress_limit=5.0e8", "rating.root_roughness_rz=[1e-5, 1e-5]", "rating.finishing=\"ground\"",
            "rating.oil_type=\"mineral\"", "rating.scuffing_load_stage=12.0", "rating.micropitting_load_stage=8.0",
            "rating.accuracy_grade=6"]
#: the load factors given (else ISO's K_v and K_Hβ move with K_A)
FIXED_K = ["rating.dynamic_factor=1.0", "rating.face_load_factor=1.0", "rating.transverse_load_factor=1.0"]


def _rate(overrides=()):
    case = build_case(load_scene(FZG, list(overrides)))
    return rate_case(case, contact_pass(case))


def test_defaults_are_said_in_one_line(caplog):
    """One log line (INFO, ``-v``) and the ``defaults`` of the result, which ``femgear info`` prints on one line."""
    with caplog.at_level(logging.INFO, logger="femgear.physics.rating"):
        r = _rate()
    lines = [rec.getMessage() for rec in caplog.records if "defaults used" in rec.getMessage()]
    assert len(lines) == 1 and "rating.scuffing_load_stage=12.0" in lines[0]
    assert "rating.micropitting_load_stage=8.0" in r.defaults
    caplog.clear()
    with caplog.at_level(logging.INFO, logger="femgear.physics.rating"):
        r = _rate(ALL_KEYS)
    assert not any("defaults used" in rec.getMessage() for rec in caplog.records) and r.defaults == ()


def test_inputs_reach_the_factors():
    base = _rate(ALL_KEYS + FIXED_K)
    strong = _rate(ALL_KEYS + FIXED_K + ["rating.bending_stress_limit=6.0e8", "rating.scuffing_load_stage=14.0",
                               "rating.micropitting_load_stage=10.0", "rating.application_factor=1.25"])
    assert strong.bending.S_F[0] == pytest.approx(base.bending.S_F[0] * 6 / 5 / 1.25, rel=1e-12)
    assert strong.scuffing.theta_S > base.scuffing.theta_S
    assert strong.micropitting.lambda_GFP < base.micropitting.lambda_GFP
    spray = _rate(ALL_KEYS + FIXED_K + ["rating.lubrication_method=\"spray\""])
    assert spray.scuffing.theta_M > base.scuffing.theta_M


def test_out_of_range_warns_with_key_and_limit(caplog):
    with caplog.at_level(logging.INFO, logger="femgear.physics.rating"):
        r = _rate(ALL_KEYS + ["rating.root_roughness_rz=[5e-5, 1e-5]"])
    msg = [rec.getMessage() for rec in caplog.records if "flagged" in rec.getMessage()]
    assert len(msg) == 1 and "rating.root_roughness_rz" in msg[0] and "40 µm" in msg[0]
    assert r.flagged("S_F") and not r.flagged("S_B")


def test_marine_pair_flags_the_helix_angle():
    scene = load_scene(ROOT / "studies" / "zoo" / "marine.toml")
    case = build_case(scene)
    pair = case.pair
    r = rate_case(case, contact_pass(case))
    assert math.degrees(pair.beta) > 25
    assert r.flagged("S_lambda") and any("helix_angle_deg" in f and "25°" in f for f in r.flags)
    assert all(math.isfinite(v) and v > 0 for v in r.safety_factors.values())


@pytest.mark.parametrize("scene", [FZG, ROOT / "studies" / "paper_baseline.toml",
                                   *sorted((ROOT / "studies" / "zoo").glob("*.toml"))], ids=lambda p: p.stem)
def test_info_prints_all_safety_factors(scene):
    out = subprocess.run([sys.executable, "-m", "femgear", "info", str(scene), "--json"], capture_output=True,
                         text=True, check=True)
    d = json.loads(out.stdout.strip().splitlines()[-1])
    sf = d["safety_factors"]
    for key in ("S_H", "S_F"):
        assert len(sf[key]) == 2 and all(v > 0 for v in sf[key])
    for key in ("S_B", "S_intS", "S_lambda"):
        assert sf[key] > 0
    assert d["scuffing"]["femgear"]["max_contact_temperature"] > d["scuffing"]["oil_temperature"]
    assert d["micropitting"]["femgear"]["lambda_min"] > 0
    text = subprocess.run([sys.executable, "-m", "femgear", "info", str(scene)], capture_output=True, text=True,
                          check=True).stdout
    assert text.count("  defaults: ") == 1 and "S_lambda: " in text


@pytest.mark.slow
def test_run_carries_the_rating_and_the_writer_only_reads_it(tmp_path, monkeypatch):
    from femgear.case import build_case
    from femgear.edge.io.run import write_run
    from femgear.pipeline import run_case

    result = run_case(build_case(load_scene(FZG, ALL_KEYS)))
    assert isinstance(result.rating, PairRating)

    def boom(*a, **k):
        raise AssertionError("the writer computed a rating")

    monkeypatch.setattr("femgear.rate.rate_case", boom)
    summary, files = write_run(result, tmp_path, plots=True)
    assert summary["safety_factors"]["S_B"] == result.rating.scuffing.S_B
    assert files["rating_path_png"].exists()
    saved = json.loads((tmp_path / "results.json").read_text())["summary"]
    assert saved["bending"]["S_F"] == list(result.rating.bending.S_F)
    assert saved["scuffing"]["femgear"]["lubrication_level"] == "formula"


def test_bad_stage_is_one_line_naming_the_key():
    out = subprocess.run([sys.executable, "-m", "femgear", "info", str(FZG), "--set", "rating.scuffing_load_stage=15"],
                         capture_output=True, text=True)
    assert out.returncode == 2 and "rating.scuffing_load_stage" in out.stderr
