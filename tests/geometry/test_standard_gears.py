"""Standard gears entered as published (issue 37 item 5): tip diameters are data, undercut is a warning.

The FZG A scuffing test gear (ISO 14635-1, ``studies/zoo/fzg_a.toml``): m 4.5 mm, z 16/24, x 0.8532/−0.5,
a 91.5 mm, d_a 88.77/112.5 mm.  Its pinion's drawing tip is 0.09 mm above d + 2 m_n (h_aP + x) (no tip
shortening) and 0.27 mm above the shortened one; its wheel is undercut (x − x_min = −0.096).  Entered so,
it has ε_α = 1.3611 (the zoo block's hand figure, tests/zoo/hand_figures.py).
"""

import tomllib
from pathlib import Path

import pytest

from femgear.case import build_case
from femgear.case.pair import pair_from_scene
from femgear.errors import SceneError
from femgear.scene import scene_from_dict

FZG_A = Path(__file__).resolve().parents[2] / "studies" / "zoo" / "fzg_a.toml"


def _scene(**over):
    data = tomllib.loads(FZG_A.read_text())
    for key, value in over.items():
        table, name = key.split(".")
        data[table][name] = value
    return scene_from_dict(data, warn=False)


def test_the_drawings_tips_are_the_tips():
    pair = pair_from_scene(_scene())
    assert (2 * pair.ra1, 2 * pair.ra2) == (pytest.approx(88.77e-3, abs=1e-12), pytest.approx(112.5e-3, abs=1e-12))
    assert pair.eps_alpha == pytest.approx(1.361066, abs=1e-5)
    # what the shift gives without and with ISO 21771's tip shortening k m_n (k = 1.5/4.5 − 0.3532)
    assert 2 * pair.standard_tip_radius(1, shortened=False) == pytest.approx(88.6788e-3, abs=1e-7)
    assert pair.k_tip == pytest.approx(1.5 / 4.5 - 0.3532, abs=2e-5)


def test_a_tip_outside_the_drawing_tolerance_is_refused_with_the_tip_shortening_explained():
    with pytest.raises(SceneError) as info:
        pair_from_scene(_scene(**{"pinion.tip_diameter": 89.0e-3}))
    assert info.value.key == "pinion.tip_diameter"
    text = str(info.value)
    assert "88.6788 mm" in text and "tip shortening" in text and "pair.tip_diameter_tolerance" in text
    # the same tip, accepted with a wider tolerance, is the tip as made
    pair = pair_from_scene(_scene(**{"pinion.tip_diameter": 89.0e-3, "pair.tip_diameter_tolerance": 0.5e-3}))
    assert 2 * pair.ra1 == pytest.approx(89.0e-3, abs=1e-12)
    # the old 0.002 m_n rule would have refused the standard's own 88.77 mm: 0.09 mm is within 0.1 mm
    with pytest.raises(SceneError, match="pinion.tip_diameter"):
        pair_from_scene(_scene(**{"pair.tip_diameter_tolerance": 0.05e-3}))


def test_the_undercut_wheel_is_a_warning_with_its_amount():
    case = build_case(_scene())
    undercut = [w for w in case.warnings if w.startswith("gear.profile_shift")]
    assert len(undercut) == 1
    assert "x − x_min = -0.096" in undercut[0] and "below the start of its active profile" in undercut[0]
