"""ISO 6336-2:2019 method B against ISO/TR 6336-30:2017 example 1 (published values, tier 4).

Reference values: ISO/TR 6336-30:2017, example 1 (m_n 8 mm, z 17/103, x 0.145/0, β 15.8°,
b 100 mm, a_w 500 mm, basic rack D, T1 9000 N m, n1 360 min⁻¹, K_A 1, L_h 50 000 h,
ν40 320 mm²/s, σ_Hlim 1500 N/mm², S_Hmin 1), as printed in the TR and reproduced in the
reference column of the ISO/TR self-test of gfsReboucas/Drivetrain (``@ISO_6336``,
``example_01``): z_n 18.905/114.543, Z_H 2.39533, Z_E 189.81170 √(N/mm²), Z_ε 0.803,
Z_β 1.01944, Z_B = Z_D = 1, K_v 1.003, K_Hβ 1.16, σ_H0 1206.58207 and σ_H 1301.35343 N/mm²,
Z_NT 0.91/0.962, Z_L 1.04739, Z_v 0.96911, Z_R 0.96599, σ_HP 1338.48050/1414.52551 N/mm²,
S_H 1.02853/1.08696.  The TR's roughness R_z = 6 µm (R_a 1 µm) is implied by its Z_R.
"""

import math

import pytest

from femgear.physics.geometry.gear import GearPair
from femgear.physics.rating import LoadFactors, MaterialLimits, contact_stress, pitting_rating
from femgear.physics.rating.contact_stress import contact_ratio_factor, single_pair_factors

MPA = 1e6


@pytest.fixture(scope="module")
def tr():
    pair = GearPair.from_parameters(z1=17, z2=103, m_n=8e-3, alpha_n=math.radians(20), beta=math.radians(15.8),
                                    b=0.1, x1=0.145, x2=0.0, h_aP=1.0, h_fP=1.4, rho_fP=0.39, kind="single-helical")
    stress = contact_stress(pair, 9000.0, 206e9, 0.3, LoadFactors(K_A=1.0, K_v=1.003, K_Hbeta=1.16))
    rating = pitting_rating(pair, stress, 360.0, MaterialLimits(sigma_Hlim=1500 * MPA, life_hours=50e3, nu40=320.0,
                                                                Rz=(6e-6, 6e-6)))
    return pair, stress, rating


def test_tr_example_1_z_factors(tr):
    _, s, _ = tr
    assert s.z_n[0] == pytest.approx(18.905, rel=1e-4)
    assert s.z_n[1] == pytest.approx(114.543, rel=1e-4)
    assert s.Z_H == pytest.approx(2.39533, rel=1e-4)
    assert s.Z_E == pytest.approx(189.81170 * math.sqrt(MPA), rel=1e-6)
    assert s.Z_beta == pytest.approx(1.01944, rel=1e-5)
    assert s.Z_eps == pytest.approx(0.803, rel=1e-3)   # femgear's own ε_α (1.5479 vs the TR's 1.5491)
    assert contact_ratio_factor(1.54909, 1.08) == pytest.approx(0.803, rel=1e-3)
    assert s.Z_B == 1.0 and s.Z_D == 1.0
    assert s.F_t == pytest.approx(127352.0, rel=1e-5)


def test_tr_example_1_contact_stress(tr):
    _, s, _ = tr
    assert s.sigma_H0 == pytest.approx(1206.58207 * MPA, rel=1e-3)
    assert s.sigma_H[0] == pytest.approx(1301.35343 * MPA, rel=1e-3)
    assert s.sigma_H[1] == pytest.approx(1301.35343 * MPA, rel=1e-3)


def test_tr_example_1_permissible_and_safety(tr):
    _, _, r = tr
    assert r.pitch_line_velocity == pytest.approx(2.664, rel=1e-3)
    assert r.N_L[0] == pytest.approx(1.080e9, rel=1e-3) and r.N_L[1] == pytest.approx(1.783e8, rel=1e-3)
    assert r.Z_NT[0] == pytest.approx(0.91, rel=1e-3) and r.Z_NT[1] == pytest.approx(0.962, rel=1e-3)
    assert r.Z_L == pytest.approx(1.04739, rel=1e-5)
    assert r.Z_v == pytest.approx(0.96911, rel=1e-5)
    assert r.Z_R == pytest.approx(0.96599, rel=1e-4)
    assert r.sigma_HP[0] == pytest.approx(1338.48050 * MPA, rel=1e-3)
    assert r.sigma_HP[1] == pytest.approx(1414.52551 * MPA, rel=1e-3)
    assert r.S_H[0] == pytest.approx(1.02853, rel=1e-3) and r.S_H[1] == pytest.approx(1.08696, rel=1e-3)
    assert r.safe


def test_spur_sigma_H0_is_hertz_at_pitch_point_times_Z_eps():
    """Spur: σ_H0 / Z_ε is the Hertz pressure of the whole normal force on b at the pitch point (identity)."""
    from femgear.physics.contact.hertz import hertz_line, reduced_modulus

    p = GearPair.from_parameters(z1=16, z2=24, m_n=4.5e-3, alpha_n=math.radians(20), beta=0.0, b=0.014,
                                 x1=0.1817, x2=0.1715, kind="spur")
    s = contact_stress(p, 200.0, 206e9, 0.3)
    rho1, rho2 = p.rb1 * math.tan(p.alpha_wt), p.rb2 * math.tan(p.alpha_wt)
    hz = hertz_line(200.0 / p.rb1 / p.b, rho1 * rho2 / (rho1 + rho2), reduced_modulus(206e9, 0.3))
    assert s.sigma_H0 / s.Z_eps == pytest.approx(hz.max_pressure, rel=1e-12)


def test_spur_Z_B_is_the_pressure_ratio_at_B():
    """Z_B = M_1 = √(ρ_C1 ρ_C2 / (ρ_B1 ρ_B2)) for spur gears: the Hertz ratio of point B to C."""
    p = GearPair.from_parameters(z1=16, z2=24, m_n=4.5e-3, alpha_n=math.radians(20), beta=0.0, b=0.014,
                                 x1=0.1817, x2=0.1715, kind="spur")
    M1, M2, Z_B, Z_D = single_pair_factors(p)
    uB, uC = p.u_end - p.p_bt, p.u_pitch
    ratio = math.sqrt(uC * (p.line_of_action - uC) / (uB * (p.line_of_action - uB)))
    assert M1 == pytest.approx(ratio, rel=1e-12) and Z_B == pytest.approx(ratio) and Z_B > 1
    assert Z_D == 1.0 and M2 < 1


def test_bad_factor():
    with pytest.raises(ValueError, match="K_Hbeta"):
        LoadFactors(K_Hbeta=0.9)
