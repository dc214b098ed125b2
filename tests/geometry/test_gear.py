"""Gear-pair geometry: ISO 21771 identities (tier 1) and worked examples (tier 4)."""

import math

import numpy as np
import pytest

from femgear.errors import SceneError
from femgear.physics.geometry import GearPair, inv, inv_inverse


def khk_helical():
    """KHK Gear Technical Reference, 'profile shifted helical gears, normal system' example."""
    return GearPair.from_parameters(
        z1=12, z2=60, m_n=3e-3, alpha_n=math.radians(20), beta=math.radians(30), b=0.03, x1=0.09809, x2=0.0
    )


def fzg_type_c():
    """FZG type C spur test gear (GEARpie gear library; ISO 14635-1 test gear)."""
    return GearPair.from_parameters(
        z1=16, z2=24, m_n=4.5e-3, alpha_n=math.radians(20), beta=0.0, b=0.014, x1=0.1817, x2=0.1715
    )


def test_involute_inverse_roundtrip():
    for alpha in (0.1, 0.35, 0.4, 0.7, 1.2):
        assert inv_inverse(inv(alpha)) == pytest.approx(alpha, rel=1e-13)


def test_khk_worked_example_matches_published_dimensions():
    p = khk_helical()
    mm = 1e3
    assert math.degrees(p.alpha_t) == pytest.approx(22.79588, abs=1e-5)
    assert math.degrees(p.alpha_wt) == pytest.approx(23.1126, abs=1e-4)
    assert p.a_w * mm == pytest.approx(125.000, abs=1e-3)
    assert 2 * p.rw1 * mm == pytest.approx(41.667, abs=1e-3)
    assert 2 * p.rw2 * mm == pytest.approx(208.333, abs=1e-3)
    assert 2 * p.ra1 * mm == pytest.approx(48.153, abs=2e-3)
    assert 2 * p.ra2 * mm == pytest.approx(213.842, abs=1e-3)
    assert 2 * p.rb1 * mm == pytest.approx(38.322, abs=1e-3)
    assert 2 * p.rb2 * mm == pytest.approx(191.611, abs=1e-3)
    assert 2 * p.rf1 * mm == pytest.approx(34.657, abs=2e-3)
    assert 2 * p.rf2 * mm == pytest.approx(200.346, abs=1e-3)


def test_fzg_type_c_radii_and_contact_ratio():
    p = fzg_type_c()
    mm = 1e3
    assert p.a_w * mm == pytest.approx(91.5, abs=1e-3)
    assert (p.rw1 * mm, p.rw2 * mm) == pytest.approx((36.600, 54.900), abs=1e-3)
    assert (p.ra1 * mm, p.ra2 * mm) == pytest.approx((41.228, 59.182), abs=1e-3)
    assert (p.rf1 * mm, p.rf2 * mm) == pytest.approx((31.193, 49.147), abs=1e-3)
    assert p.p_bt * mm == pytest.approx(13.285, abs=1e-3)
    assert p.eps_alpha == pytest.approx(1.44, abs=5e-3)


@pytest.mark.parametrize("make", [khk_helical, fzg_type_c])
def test_iso21771_identities(make):
    p = make()
    assert math.sin(p.beta_b) == pytest.approx(math.sin(p.beta) * math.cos(p.alpha_n), rel=1e-12)
    assert p.p_bn == pytest.approx(p.p_bt * math.cos(p.beta_b), rel=1e-12)
    assert p.a_w * math.cos(p.alpha_wt) == pytest.approx(p.a * math.cos(p.alpha_t), rel=1e-12)
    assert p.rb1 / p.rb2 == pytest.approx(p.z1 / p.z2, rel=1e-12)
    assert p.rw1 + p.rw2 == pytest.approx(p.a_w, rel=1e-12)
    assert 2 * math.pi * p.rb1 / p.z1 == pytest.approx(p.p_bt, rel=1e-12)
    # the pitch point lies on the path of contact and splits T1T2 in the ratio of the base radii
    assert p.u_start < p.u_pitch < p.u_end
    assert p.u_pitch / (p.line_of_action - p.u_pitch) == pytest.approx(p.rb1 / p.rb2, rel=1e-12)


def test_baseline_contact_ratios(baseline_pair):
    p = baseline_pair
    assert p.eps_beta == pytest.approx(0.0175 * 0.5 / (math.pi * 3e-3), rel=1e-12)
    assert 1.3 < p.eps_alpha < 1.45
    assert p.eps_gamma == pytest.approx(p.eps_alpha + p.eps_beta)


def test_interfering_and_pointed_teeth_are_refused():
    """z = 8 at x = 0 is undercut (a warning, tests/mesh/test_profile.py) and its mate's tip would meet it below
    the base circle (involute interference, T1A < 0): refused; a tooth pointed below its tip: refused."""
    with pytest.raises(SceneError, match="involute interference"):
        GearPair.from_parameters(z1=8, z2=40, m_n=3e-3, alpha_n=math.radians(20), beta=0.0, b=0.02, x1=0.0, x2=0.0)
    with pytest.raises(SceneError, match="pointed"):
        GearPair.from_parameters(z1=10, z2=40, m_n=3e-3, alpha_n=math.radians(20), beta=0.0, b=0.02, x1=1.2, x2=0.0)


def test_low_contact_ratio_is_refused():
    with pytest.raises(SceneError, match="ε_α"):
        GearPair.from_parameters(
            z1=31, z2=34, m_n=3e-3, alpha_n=math.radians(20), beta=math.radians(30), b=0.02, x1=0, x2=0, h_aP=0.5
        )


def test_worked_example_tip_shortening_is_nonpositive():
    assert khk_helical().k_tip <= 0
    assert np.isclose(GearPair.from_parameters(
        z1=20, z2=40, m_n=2e-3, alpha_n=math.radians(20), beta=0.2, b=0.02, x1=0, x2=0).k_tip, 0.0, atol=1e-12)
