"""Friction level 'formula': oil laws, flash temperature, Eyring traction (tiers 1, 3)."""

import math

import numpy as np
import pytest
from scipy import integrate

from femgear.case import build_case
from femgear.levels.contact import contact_pass
from femgear.levels.lubrication import line_friction
from femgear.physics.lubrication import (
    OilLaw,
    Solids,
    abel_matrix,
    band_flash_temperature,
    blok_flash_temperature,
    gupta_thermal_factor,
    hertz_traction,
)

OIL = OilLaw(eta0=0.08, alpha=22e-9, beta_t=0.042, T0=313.0)
STEEL = Solids(B1=math.sqrt(46 * 7850 * 470), B2=math.sqrt(46 * 7850 * 470), k_oil=0.14)


def test_roelands_slopes_are_barus_alpha_and_beta_t():
    assert OIL.viscosity(0.0, 313.0) == pytest.approx(0.08, rel=1e-14)
    dp, dT = 1.0, 1e-4
    slope_p = (OIL.log_viscosity_ratio(dp, 313.0) - OIL.log_viscosity_ratio(0.0, 313.0)) / dp
    slope_T = (OIL.log_viscosity_ratio(0.0, 313.0 + dT) - OIL.log_viscosity_ratio(0.0, 313.0 - dT)) / (2 * dT)
    assert slope_p == pytest.approx(22e-9, rel=1e-6)
    assert slope_T == pytest.approx(-0.042, rel=1e-6)
    # the paper's indices for its oil
    assert OIL.z0 == pytest.approx(0.604, abs=2e-3) and OIL.s0 == pytest.approx(1.029, abs=2e-3)
    # Roelands grows slower than Barus at high pressure
    assert OIL.viscosity(1e9, 313.0) < OilLaw(0.08, 22e-9, 0.042, 313.0, model="barus").viscosity(1e9, 313.0)


def test_abel_matrix_is_exact_for_piecewise_constant_flux():
    n = 40
    x = -1 + (2 * np.arange(n) + 1) / n
    assert np.allclose(abel_matrix(n) @ np.ones(n), 2 * np.sqrt(x + 1), rtol=1e-12)


def test_band_integral_reproduces_blok_for_a_semi_elliptic_source():
    n, b, v1, v2, mu, p_h, vs = 1500, 1e-4, 1.5, 0.8, 0.05, 1e9, 0.7
    x = -1 + (2 * np.arange(n) + 1) / n
    q = mu * p_h * np.sqrt(1 - x**2) * vs
    rise = band_flash_temperature(q, b, v1, v2, STEEL.B1, STEEL.B2)
    w = math.pi * b * p_h / 2
    blok = blok_flash_temperature(mu, w, vs, b, v1, v2, STEEL.B1, STEEL.B2)
    assert rise.max() == pytest.approx(float(blok), rel=0.01)


def contact(srr, ue=1.0, w=84e3, b=1.07e-4, p_h=0.5e9, h=0.7e-6):
    return dict(w=w, b=b, p_h=p_h, h=h, v1=ue * (1 + srr / 2), v2=ue * (1 - srr / 2))


def test_isothermal_newtonian_limit_is_the_pressure_integral():
    cold = Solids(B1=1e12, B2=1e12, k_oil=1e12)
    c = contact(0.1)
    r = hertz_traction(**c, T_bulk=313.0, oil=OIL, solids=cold, model="newtonian", n=2000)
    rate = abs(c["v1"] - c["v2"]) / c["h"]
    exact = integrate.quad(lambda x: OIL.viscosity(c["p_h"] * math.sqrt(1 - (x / c["b"]) ** 2), 313.0), -c["b"], c["b"],
                           limit=200)[0] * rate
    assert r.traction[0] == pytest.approx(exact, rel=1e-3)
    assert r.flash_max[0] < 1e-6


def test_eyring_traction_is_linear_at_small_slip_and_saturates():
    srr = np.array([1e-4, 2e-4, 0.2, 0.4, 0.8])
    r = hertz_traction(**contact(srr), T_bulk=313.0, oil=OIL, solids=STEEL, model="eyring")
    assert r.mu[1] / r.mu[0] == pytest.approx(2.0, rel=0.02)
    assert r.mu[4] / r.mu[3] < 1.5 and r.mu[3] / r.mu[2] < 1.6        # sublinear: saturating
    assert np.all(np.diff(r.mu) > 0)
    assert 0.01 < r.mu[3] < 0.1


def test_zero_sliding_gives_zero_friction_and_heating():
    r = hertz_traction(**contact(0.0), T_bulk=313.0, oil=OIL, solids=STEEL)
    assert r.mu[0] == 0.0 and r.flash_max[0] == 0.0 and r.film_max[0] == 0.0


def test_gupta_factor_limits():
    assert gupta_thermal_factor(0.5e9, 2.3e11, 0.0, 1e-6, 0.08, 0.042, 0.14) == pytest.approx(1.0, abs=1e-4)
    f = gupta_thermal_factor(0.5e9, 2.3e11, np.array([0.0, 1.0]), 20.0, 0.08, 0.042, 0.14)
    assert 0 < f[1] < f[0] < 1


def test_friction_along_the_baseline_path_is_u_shaped_with_its_minimum_at_the_pitch(baseline_scene):
    case = build_case(baseline_scene)
    c = contact_pass(case)
    r = line_friction(case).along(c, case.operating.ambient_temperature)
    assert np.argmin(r.mu) == c.pitch_index
    assert r.mu[c.pitch_index] < 0.2 * r.mu.max()
    assert 0.01 < r.mu.max() < 0.1
    i = c.pitch_index
    assert np.all(np.diff(r.mu[: i + 1]) < 0) and np.all(np.diff(r.mu[i:]) > 0)
    assert 1.0 < r.flash_max.max() < 100.0


def test_gupta_factor_is_floored_and_flagged_outside_its_fit():
    """Beyond its fit Gupta's numerator turns negative (a negative film): the factor is
    floored and the points are reported; inside the fit it is untouched."""
    from femgear.physics.lubrication.traction import GUPTA_FLOOR, gupta_out_of_range, gupta_thermal_factor

    args = dict(E_red=2.3e11, srr=0.3, eta0=0.08, beta_t=0.03, k_f=0.13)
    p_h = np.array([0.5e9, 5e9])
    ue = np.array([1.0, 60.0])
    phi = gupta_thermal_factor(p_h, ue=ue, **args)
    assert phi[1] == GUPTA_FLOOR and GUPTA_FLOOR < phi[0] < 1
    flags = gupta_out_of_range(p_h, args["E_red"], ue, args["eta0"], args["beta_t"], args["k_f"])
    assert list(flags) == [False, True]
