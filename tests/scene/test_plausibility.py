"""Scene plausibility: impossible operating points refused, implausible ones warned; strict types.

The scene's own checks run in ``load_scene``; those needing the pair when the case is bound
(``build_case``), the Hertz pressure's after the run's contact pass (``contact_warnings``)."""

from __future__ import annotations

import logging
import math

import pytest

from femgear.case import build_case
from femgear.case.checks import contact_warnings
from femgear.case.pair import pair_from_scene
from femgear.errors import SceneError
from femgear.scene import load_scene


def test_burst_speed_is_the_ring_hoop_stress_at_tabor_yield(baseline_path):
    """v_burst = √(H / 3ρ): 505 m/s for H = 6 GPa, ρ = 7850 kg/m³; the tip speed just below passes."""

    scene = load_scene(baseline_path)
    pair = pair_from_scene(scene)
    v_burst = math.sqrt(6e9 / 3 / 7850.0)
    rpm_burst = v_burst / (2 * math.pi * pair.ra1) * 60       # the pinion tip is the fastest (ra1 ω1 > ra2 ω2)
    build_case(load_scene(baseline_path, [f"operating.speed_rpm={0.99 * rpm_burst!r}"]))
    with pytest.raises(SceneError, match="bursts above 505 m/s") as info:
        build_case(load_scene(baseline_path, [f"operating.speed_rpm={1.01 * rpm_burst!r}"]))
    assert info.value.key == "operating.speed_rpm"


@pytest.mark.parametrize("override,key", [
    ("operating.ambient_temperature=138.0", "operating.ambient_temperature"),
    ("oil.reference_temperature=100.0", "oil.reference_temperature"),
])
def test_temperatures_at_the_roelands_pole_are_refused(baseline_path, override, key):
    with pytest.raises(SceneError) as info:
        load_scene(baseline_path, [override])
    assert info.value.key == key


@pytest.mark.parametrize("override,key", [
    ("pinion.eccentricity=6e-5", "pinion.eccentricity"),
    ("operating.torque=20000.0", "operating.torque"),
    ("operating.ambient_temperature=430.0", "operating.ambient_temperature"),
    ("operating.ambient_temperature=240.0", "operating.ambient_temperature"),
    ("operating.speed_rpm=30000.0", "operating.speed_rpm"),
])
def test_implausible_inputs_are_accepted_with_a_warning_naming_the_key(baseline_path, caplog, override, key):
    with caplog.at_level(logging.WARNING, logger="femgear.scene"):
        _bind_and_contact(baseline_path, [override])
    assert any(r.getMessage().startswith(key) for r in caplog.records), caplog.text
    assert len({r.getMessage().split(":")[0] for r in caplog.records}) == len(caplog.records)   # one line per key


def _bind_and_contact(path, overrides=()):
    """What a run does before its sub-models: load, bind, the contact pass and its plausibility warning."""
    from femgear.levels.contact import contact_pass

    case = build_case(load_scene(path, overrides))
    contact = contact_pass(case)
    return case, contact_warnings(case, float(contact.hertz_pressure.max()))


def test_the_baseline_loads_without_warnings(baseline_path, caplog):
    with caplog.at_level(logging.WARNING, logger="femgear.scene"):
        case, later = _bind_and_contact(baseline_path)
    assert caplog.records == [] and case.warnings == () and later == ()


def test_the_hertz_warning_comes_from_the_runs_contact_pass_once_per_key(baseline_path, caplog):
    """Loading and binding an overloaded scene warn nothing (no contact pass there); the run's pass warns
    once, and not again for a key already warned."""
    from dataclasses import replace

    with caplog.at_level(logging.WARNING, logger="femgear.scene"):
        case = build_case(load_scene(baseline_path, ["operating.torque=20000.0"]))
        assert caplog.records == []
        case, later = _bind_and_contact(baseline_path, ["operating.torque=20000.0"])
    assert [w.split(":")[0] for w in later] == ["operating.torque"] and "GPa is above 3 GPa" in later[0]
    assert contact_warnings(replace(case, warnings=later), 4e9) == ()
    assert contact_warnings(case, 2.9e9) == ()


@pytest.mark.parametrize("override,key", [
    ('pinion.teeth="31"', "pinion.teeth"), ("operating.speed_rpm=true", "operating.speed_rpm"),
    ("pinion.teeth=31.0", "pinion.teeth"), ("operating.torque=inf", "operating.torque"),
    ("oil.viscosity=nan", "oil.viscosity"), ('operating.torque="200"', "operating.torque"),
])
def test_strict_types_and_finite_values(baseline_path, override, key):
    with pytest.raises(SceneError) as info:
        load_scene(baseline_path, [override])
    assert info.value.key == key


def test_an_integer_is_accepted_for_a_float_key(baseline_path):
    assert load_scene(baseline_path, ["operating.torque=150"]).operating.torque == 150.0


@pytest.mark.parametrize("content,message", [(b"\x00\x01\xff" * 10, "not a text file"),
                                             (b"a = 1\x00", "NUL"), (b"[pair\n", "not valid TOML")])
def test_unreadable_scene_files(tmp_path, content, message):
    path = tmp_path / "s.toml"
    path.write_bytes(content)
    with pytest.raises(SceneError, match=message):
        load_scene(path)
    with pytest.raises(SceneError, match="is a folder"):
        load_scene(tmp_path)
