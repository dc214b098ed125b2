"""Pair kinds, basic racks, tip diameters and centre distance from a scene; bad input is one clear line."""

import math
import subprocess
import sys
from pathlib import Path

import pytest

from femgear.case import build_case
from femgear.case.pair import pair_from_scene
from femgear.errors import SceneError
from femgear.scene import load_scene

STUDIES = Path(__file__).resolve().parents[2] / "studies"
FZG = STUDIES / "fzg_c14.toml"


def _error(path, *overrides) -> SceneError:
    with pytest.raises(SceneError) as info:     # the pair is bound and checked with the case
        build_case(load_scene(path, list(overrides)))
    return info.value


def test_fzg_c14_geometry_matches_gearpie():
    """FZG C (GEARpie library): radii root 31.193/49.147, tip 41.228/59.182, pitch 36.600/54.900 mm; ε_α 1.44."""
    p = pair_from_scene(load_scene(FZG))
    assert p.kind == "spur" and p.n_helices == 1 and p.beta_b == 0
    for got, ref in ((p.rf1, 31.193), (p.rf2, 49.147), (p.ra1, 41.228), (p.ra2, 59.182), (p.rw1, 36.600),
                     (p.rw2, 54.900)):
        assert got * 1e3 == pytest.approx(ref, abs=1.5e-3)
    assert p.a_w == pytest.approx(91.5e-3, abs=1e-7)
    assert p.eps_alpha == pytest.approx(1.44, abs=0.005)
    assert p.p_bt * 1e3 == pytest.approx(13.285, abs=1e-3)


def test_spur_with_helix_angle_is_one_line():
    err = _error(FZG, "pair.helix_angle_deg=15")
    assert err.key == "pair.helix_angle_deg" and "spur" in str(err) and "\n" not in str(err)


def test_helical_kind_without_helix_angle():
    err = _error(FZG, "pair.kind=single-helical", "pinion.axial_stiffness=1e8", "gear.axial_stiffness=1e8")
    assert err.key == "pair.helix_angle_deg" and "spur" in str(err)


def test_single_helical_without_axial_support_is_one_line():
    assert pair_from_scene(load_scene(STUDIES / "single_helical.toml")).n_helices == 1
    path = STUDIES / "paper_baseline.toml"
    err = _error(path, "pair.kind=single-helical")
    assert err.key == "pinion.axial_stiffness" and "thrust" in str(err) and "\n" not in str(err)


def test_tip_diameter_inconsistent_with_profile_shift_is_one_line():
    err = _error(FZG, "pinion.tip_diameter=0.0830")
    assert err.key == "pinion.tip_diameter" and "82.45" in str(err) and "\n" not in str(err)


def test_tip_diameter_derives_profile_shift():
    """Without pinion.profile_shift the tip diameter (and a_w's tip alteration) give x1 = 0.1817."""
    import tomllib

    from femgear.scene.load import scene_from_dict

    raw = tomllib.loads(FZG.read_text())
    del raw["pinion"]["profile_shift"]
    p = pair_from_scene(scene_from_dict(raw))
    assert p.x1 == pytest.approx(0.1817, abs=2e-4)
    del raw["gear"]["profile_shift"]
    p = pair_from_scene(scene_from_dict(raw))
    assert p.x2 == pytest.approx(0.1715, abs=2e-4) and p.a_w == pytest.approx(91.5e-3, rel=1e-5)


def test_centre_distance_inconsistent():
    err = _error(FZG, "pair.centre_distance=0.0920")
    assert err.key == "pair.centre_distance" and "x1 + x2" in str(err)


def test_basic_rack_preset_and_conflict():
    p = pair_from_scene(load_scene(FZG, ["pair.basic_rack=B"]))
    assert (p.h_aP, p.h_fP, p.rho_fP) == (1.0, 1.25, 0.30)
    err = _error(FZG, "pair.dedendum_coeff=1.4")
    assert err.key == "pair.dedendum_coeff" and "basic_rack" in str(err)


def test_member_face_width_contact_width():
    p = pair_from_scene(load_scene(FZG, ["gear.face_width=0.020"]))
    assert p.b == pytest.approx(0.014)
    p = pair_from_scene(load_scene(FZG, ["pinion.face_width=0.010"]))
    assert p.b == pytest.approx(0.010)


def test_cli_prints_one_line():
    out = subprocess.run([sys.executable, "-m", "femgear", "info", str(FZG), "--set", "pair.helix_angle_deg=10"],
                         capture_output=True, text=True)
    assert out.returncode == 2
    lines = [ln for ln in out.stderr.splitlines() if ln.strip()]
    assert len(lines) == 1 and "pair.helix_angle_deg" in lines[0]


def test_double_helical_default_kind_unchanged(baseline_pair):
    assert baseline_pair.kind == "double-helical" and baseline_pair.n_helices == 2
    assert math.degrees(baseline_pair.beta) == pytest.approx(30.0)
