"""Messages that tell the truth (issue 37, item 7): every problem of a scene is listed, a unit hint is offered
only where the value is plausible in the hinted unit, and a refusal names the key that is wrong.

Each case here was misreported before: a pydantic error with several problems named one and hid the rest
("and 1 more error"); z₁ = 6 was blamed on the bore with "did you mean 0.012 mm"; a half backlash of 0.15
(mm) was offered as 0.15 µm; a power of 5 MW typed as a torque was offered only as N mm; a module typo in one
half of a double-helical REXS member was reported as a helix-hand problem (tests/rexs/test_half_typo.py).
"""

from __future__ import annotations

from pathlib import Path

import pytest

from femgear.errors import SceneError
from femgear.scene import load_scene

ZOO = Path(__file__).resolve().parents[2] / "studies" / "zoo"


def _refusal(scene: str, *overrides: str) -> SceneError:
    with pytest.raises(SceneError) as info:
        load_scene(ZOO / f"{scene}.toml", overrides)
    return info.value


def test_every_problem_of_a_scene_is_listed_with_its_key():
    err = _refusal("paper_baseline", "pinion.tetth=3", "gear.colour=1", "pair.backlash=-1")
    text = str(err)
    for key in ("pinion.tetth", "gear.colour", "pair.backlash"):
        assert key in text, text
    assert "more error" not in text and "and 2 more: " in text
    assert "did you mean pinion.teeth?" in text      # the unknown key's closest key of its table


def test_an_unknown_key_alone_names_the_closest_key():
    err = _refusal("paper_baseline", "numerics.dynamic_cycles=80")
    assert err.key == "numerics.dynamic_cycles" and err.message == \
        "unknown key (did you mean numerics.dynamics_cycles?)"


def test_too_few_teeth_for_the_shaft_are_blamed_on_the_teeth_not_the_bore():
    """small_spur's pinion sits on a 24 mm motor shaft (bore 12 mm): with 6 teeth of m 2 mm the reference
    radius is 6 mm.  The bore is right; the tooth count is not, and a 0.012 mm bore is no plausible reading."""
    err = _refusal("small_spur", "pinion.teeth=6")
    assert err.key == "pinion.teeth", str(err)
    assert "6 teeth" in err.message and "bore" in err.message and "did you mean" not in err.message


def test_a_bore_too_large_for_its_gear_offers_no_implausible_unit():
    err = _refusal("small_spur", "pinion.bore_radius=0.03")       # off the 24 mm shaft: the bore itself
    assert err.key == "pinion.bore_radius" and "did you mean" not in err.message


def test_a_backlash_typed_in_mm_is_offered_in_mm_not_um():
    err = _refusal("paper_baseline", "pair.backlash=0.15")
    assert err.key == "pair.backlash"
    assert "did you mean 0.15 mm = 0.00015 m?" in err.message, err.message
    assert "µm" not in err.message.split("did you mean")[1]
    typed_in_um = _refusal("paper_baseline", "pair.backlash=150")
    assert "did you mean 150 µm = 0.00015 m?" in typed_in_um.message


def test_a_power_typed_as_torque_is_offered_as_a_power():
    """20 MW of the turbo pair typed as a torque: as N mm it would be 2e4 N m (σ_H0 ≈ 1.1 GPa), as a power in W
    13 013 N m at 14 676 rpm (the scene's own torque): both readings are plausible on this pair, so both are
    offered; on the paper's small pair neither is (5000 N m would be σ_H0 ≈ 2.9 GPa), so none is."""
    err = _refusal("turbo", "operating.torque=2e7")
    assert err.key == "operating.torque"
    assert "2e+07 N mm = 2e+04 N m" in err.message and "a power of 2e+07 W = 13013.5 N m at 14676 rpm" in err.message
    small = _refusal("paper_baseline", "operating.torque=5e6")
    assert "did you mean" not in small.message, small.message
