"""Inputs checked in engineering terms (issue 25 item 6, :mod:`femgear.scene.ranges`).

Each unit slip of the issue is refused on the key the user typed, with the likely unit, before
any geometry; plausible-but-unusual values warn once, naming the key; every shipped scene
loads without a range warning.
"""

from __future__ import annotations

import logging
import math
from pathlib import Path

import pytest

from femgear.errors import SceneError
from femgear.scene import load_scene
from femgear.scene.ranges import _iso1328, _nominal_contact_stress

ROOT = Path(__file__).resolve().parents[2]
BASE = ROOT / "studies" / "paper_baseline.toml"
MARINE = ROOT / "studies" / "zoo" / "marine.toml"

#: (override, key, words the message must hold: the likely unit and its SI value)
SLIPS = [
    ("pair.normal_module=6", "pair.normal_module", ["6 mm", "0.006 m"]),
    ("pair.face_width=120", "pair.face_width", ["120 mm", "0.12 m"]),
    ("oil.pressure_viscosity=20", "oil.pressure_viscosity", ["GPa⁻¹", "2e-08"]),
    ("oil.viscosity=39.7", "oil.viscosity", ["cSt"]),
    ("gear.eccentricity=1.0", "gear.eccentricity", ["µm"]),
    ("operating.speed_rpm=1e-6", "operating.speed_rpm", ["pitch-line speed"]),
    ("operating.ambient_temperature=40.0", "operating.ambient_temperature", ["40 °C", "313.1 K"]),
    ("oil.reference_temperature=60.0", "oil.reference_temperature", ["60 °C", "333.1 K"]),
    ("operating.torque=2e7", "operating.torque", ["σ_H0"]),
    ("pinion.shaft_diameter=40.0", "pinion.shaft_diameter", ["40 mm"]),
    ("errors.profile_error=0.01", "errors.profile_error", ["ISO 1328"]),
    ("pair.backlash=50.0", "pair.backlash", ["50 µm"]),
    ("material.youngs_modulus=210.0", "material.youngs_modulus", ["210 GPa"]),
    ("oil.density=0.87", "oil.density", ["g/cm³"]),
    ("gear.bearing_span=500.0", "gear.bearing_span", ["500 mm"]),
    ("thermal.flank_temperature_rise=313.0", "thermal.flank_temperature_rise", ["not an absolute"]),
    ("material.thermal_expansion=11.6", "material.thermal_expansion", ["µm/(m K)", "1.16e-05"]),
    ("roughness.rq=0.4", "roughness.rq", ["0.4 µm"]),
    ("oil.specific_heat=2.0", "oil.specific_heat", ["kJ/(kg K)"]),
]


@pytest.mark.parametrize("scene", [BASE, MARINE], ids=["baseline", "marine"])
@pytest.mark.parametrize("override,key,words", SLIPS, ids=[s[1] for s in SLIPS])
def test_unit_slips_are_refused_on_the_key_typed(scene, override, key, words, monkeypatch):
    import femgear.physics.geometry as geometry

    def no_geometry(*args, **kwargs):  # the check must come first (load_scene builds no geometry at all)
        raise AssertionError("geometry was derived before the input ranges were checked")

    monkeypatch.setattr(geometry.GearPair, "__init__", no_geometry)
    with pytest.raises(SceneError) as info:
        load_scene(scene, [override])
    assert info.value.key == key, str(info.value)
    for word in words:
        assert word in info.value.message, str(info.value)


@pytest.mark.parametrize("override,key", [
    ("oil.pressure_viscosity=3e-9", "oil.pressure_viscosity"),   # water-glycol
    ("oil.viscosity=2.0", "oil.viscosity"),                       # VG 680 cold
    ("operating.speed_rpm=1.0", "operating.speed_rpm"),           # boundary lubrication, slow-speed wear tests
    ("pinion.eccentricity=2e-4", "pinion.eccentricity"),          # above the backlash
    ("pair.backlash=1e-3", "pair.backlash"),
    ("thermal.flank_temperature_rise=180.0", "thermal.flank_temperature_rise"),
])
def test_unusual_values_warn_once_naming_the_key(override, key, caplog):
    with caplog.at_level(logging.WARNING, logger="femgear.scene"):
        load_scene(BASE, [override])
    lines = [r.getMessage() for r in caplog.records if r.getMessage().startswith(key)]
    assert len(lines) == 1, caplog.text


def test_eccentricity_above_the_backlash_is_one_line(caplog):
    """Both reasons (backlash, ISO 1328 runout) in ONE line for the key."""
    with caplog.at_level(logging.WARNING, logger="femgear.scene"):
        load_scene(BASE, ["gear.eccentricity=1e-3"])
    lines = [r.getMessage() for r in caplog.records]
    assert len(lines) == 1 and lines[0].startswith("gear.eccentricity") and "backlash" in lines[0], lines


@pytest.mark.parametrize("path", sorted((ROOT / "studies").glob("*.toml")) + sorted((ROOT / "studies" / "zoo").glob("*.toml")),
                         ids=lambda p: p.name)
def test_shipped_scenes_load_without_range_warnings(path, caplog):
    import tomllib

    if "pair" not in tomllib.loads(path.read_text()):
        pytest.skip("not a scene (a sweep file)")
    with caplog.at_level(logging.WARNING, logger="femgear.scene"):
        load_scene(path)
    # the turbo pair's > 100 m/s warning is plausibility's, stated in its scene
    others = [m for m in (r.getMessage() for r in caplog.records) if "m/s is above 100 m/s" not in m]
    assert others == [], others


def test_iso1328_tolerances_match_the_standards_formulas():
    """ISO 1328-1:2013 at class 5, m 3 mm, d 100 mm: f_fα = 2.5√3 + 0.17√100 + 0.5 = 6.530 µm,
    F_p = 0.9 + 12.5 + 7 = 20.4 µm (F_r = 0.8 F_p); √2 per class."""
    f_f, F_r = _iso1328(3e-3, 0.1, 5)
    assert f_f == pytest.approx(6.530e-6, rel=1e-3) and F_r == pytest.approx(0.8 * 20.4e-6, rel=1e-9)
    f_f7, _ = _iso1328(3e-3, 0.1, 7)
    assert f_f7 == pytest.approx(2 * f_f, rel=1e-12)


def test_nominal_contact_stress_is_isos_sigma_h0_without_z_eps_z_beta():
    """The torque check's σ_H0 against femgear's ISO 6336-2 σ_H0 on the baseline (x = 0: same Z_H),
    divided by Z_ε Z_β that the check leaves out."""
    from femgear.case import build_case
    from femgear.rate import pitting_of
    from femgear.summary import rating_summary

    scene = load_scene(BASE)
    rating = rating_summary(pitting_of(build_case(scene)))
    d1 = 31 * 3e-3 / math.cos(math.radians(30))
    nominal = _nominal_contact_stress(scene, 200.0, d1)
    assert nominal == pytest.approx(rating["sigma_H0"] / (rating["Z_eps"] * rating["Z_beta"]), rel=1e-6)
