"""ISO 6336-1 Method B against the ISO/TR 6336-30:2017 worked example 1 (analytic limit, tier 3)."""

import math

import pytest

from femgear.physics.geometry.gear import GearPair
from femgear.physics.stiffness.iso6336 import gear_blank_factor, iso6336_stiffness, virtual_teeth


@pytest.fixture(scope="module")
def tr_example():
    # ISO/TR 6336-30 example 1: m_n 8 mm, z 17/103, x 0.145/0, β 15.8°, b 100 mm, rack D
    return GearPair.from_parameters(z1=17, z2=103, m_n=8e-3, alpha_n=math.radians(20), beta=math.radians(15.8),
                                    b=0.1, x1=0.145, x2=0.0, h_aP=1.0, h_fP=1.4, rho_fP=0.39)


def test_virtual_teeth(tr_example):
    p = tr_example
    assert virtual_teeth(17, p.beta, p.beta_b) == pytest.approx(18.905, abs=1e-3)
    assert virtual_teeth(103, p.beta, p.beta_b) == pytest.approx(114.543, abs=1e-3)


def test_reference_values(tr_example):
    # the TR's ε_α = 1.54909 (implied by its c_γα/c'); with it every value matches to 1e-6
    s = iso6336_stiffness(tr_example, eps_alpha=1.549090)
    assert s.c_th == pytest.approx(17.85584, rel=1e-6)
    assert s.c_prime == pytest.approx(12.37047, rel=1e-6)
    assert s.c_gamma_alpha == pytest.approx(17.46485, rel=2e-6)
    assert s.c_gamma_beta == pytest.approx(14.84512, rel=2e-6)


def test_own_contact_ratio_close_to_tr(tr_example):
    # femgear's own ε_α (ISO 21771 tip radii) is within 0.1 % of the TR's
    s = iso6336_stiffness(tr_example)
    assert s.c_gamma_alpha == pytest.approx(17.46485, rel=1e-3)
    assert s.k() == pytest.approx(s.c_gamma_alpha * 100 * 1e6)


def test_low_load_reduction(tr_example):
    full = iso6336_stiffness(tr_example, line_load=200e3)
    low = iso6336_stiffness(tr_example, line_load=50e3)
    assert full.c_prime == pytest.approx(iso6336_stiffness(tr_example).c_prime)
    assert low.c_prime == pytest.approx(full.c_prime * 0.5**0.25)


def test_gear_blank_factor():
    """ISO 6336-1:2019 C_R = 1 + ln(b_s/b)/(5 exp(s_R/(5 m_n))), by hand; b_s/b held to [0.2, 1.2], s_R to ≥ m_n."""
    m = 3e-3
    assert gear_blank_factor(m, 0.2, m) == pytest.approx(1 + math.log(0.2) / (5 * math.exp(0.2)), rel=1e-12)
    assert gear_blank_factor(m, 0.2, m) == pytest.approx(0.73646, abs=1e-5)
    assert gear_blank_factor(5 * m, 0.5, m) == pytest.approx(0.949002, abs=1e-6)
    assert gear_blank_factor(2 * m, 1.0, m) == 1.0
    assert gear_blank_factor(0.5 * m, 0.1, m) == gear_blank_factor(m, 0.2, m)
    with pytest.raises(ValueError, match="gear blank factor"):
        gear_blank_factor(0.0, 0.5, m)
