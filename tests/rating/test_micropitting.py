"""ISO/TS 6336-22 method B: the film formula against Dowson–Higginson, a hand calculation, the GF-C identity.

No published worked example of ISO/TS 6336-22 (its annex example or ISO/TR 15144-2, an FVA or
textbook example with all inputs printed) could be read from the sources available here (case-study
pages were reachable only in their introductions), so the checks are hand calculations written out
and identities of the method.
"""

import math

import numpy as np
import pytest

from femgear.physics.contact.film import dowson_higginson_minimum
from femgear.physics.geometry.gear import GearPair
from femgear.physics.rating.micropitting import FZG_C, local_film, micropitting_rating, reference_film_thickness
from femgear.physics.rating.scuffing import ScuffingInputs, flash_path, fzg_torque

ALPHA = 15e-9


def _eta(T):
    return 0.0118 * math.exp(-0.028 * (T - 363.15))


def _inputs(**kw):
    base = dict(oil_temperature=363.15, oil_viscosity=0.0118, Ra=(0.5e-6, 0.5e-6))
    base.update(kw)
    return ScuffingInputs(**base)


def test_isothermal_film_is_dowson_higginson():
    """With a temperature-independent viscosity (S_GF = 1) h_Y = 1.6 ρ G^0.6 U^0.7 W^-0.13 (Dowson & Higginson
    1961) equals their 1977 form 2.65 G^0.54 U^0.7 W^-0.13 (femgear.physics.contact.film) within 3 % at G ≈ 3400."""
    p = GearPair(**FZG_C)
    u, h, lam, _ = local_film(p, 200.0, 2175.0, _inputs(), lambda T: 0.0118, ALPHA)
    E_r = 206e9 / 0.91
    R = u * (p.line_of_action - u) / p.line_of_action
    w1 = 2175 * 2 * math.pi / 60
    ue = 0.5 * (w1 * u + w1 / p.u * (p.line_of_action - u))
    w = flash_path(p, 200.0, 2175.0, _inputs()).line_load
    H = dowson_higginson_minimum(0.0118 * ue / (E_r * R), ALPHA * E_r, w / (E_r * R))
    assert h == pytest.approx(H * R, rel=0.03)
    assert lam == pytest.approx(h / 0.5e-6)


def test_local_film_by_hand_at_the_pitch_point():
    """At C (no sliding, θ_fl = 0): h_C = 1.6 ρ_C G^0.6 U^0.7 W^-0.13 (η(θ_M)/η(38 °C))^0.22, written out."""
    p = GearPair(**FZG_C)
    u, h, _, theta_M = local_film(p, 200.0, 2175.0, _inputs(), _eta, ALPHA)
    i = int(np.argmin(np.abs(u - p.u_pitch)))
    E_r = 206e9 / 0.91
    rho = p.u_pitch * (p.line_of_action - p.u_pitch) / p.line_of_action
    v_sum = 2 * 2175 * 2 * math.pi / 60 * p.u_pitch
    w = 200.0 / p.r1 / (0.014 * math.cos(p.alpha_wt))             # X_Γ = 1 in single contact
    hand = 1.6 * rho * (ALPHA * E_r) ** 0.6 * (_eta(theta_M) * v_sum / (2 * E_r * rho)) ** 0.7 \
        * (w / (E_r * rho)) ** -0.13 * (_eta(theta_M) / _eta(311.15)) ** 0.22
    assert h[i] == pytest.approx(hand, rel=1e-9)


def test_gf_c_gear_at_its_failure_stage():
    """The FZG C gear in the GF-C/8.3/90 test at the failure stage has λ_GF,min = λ_GFT, so S_λ = 1/1.4."""
    p = GearPair(**FZG_C)
    rpm = 8.3 / (math.pi * 2 * p.rw1) * 60
    for stage in (7, 9):
        r = micropitting_rating(p, fzg_torque(stage), rpm, _inputs(), _eta, ALPHA, stage)
        assert r.lambda_GFmin == pytest.approx(r.lambda_GFT, rel=1e-12)
        assert r.S_lambda == pytest.approx(1 / 1.4, rel=1e-12)


def test_higher_stage_oil_is_safer_and_load_thins_the_film():
    lam_T = [reference_film_thickness(s, _inputs(), _eta, ALPHA) for s in range(3, 13)]
    assert np.all(np.diff(lam_T) < 0)
    p = GearPair(**FZG_C)
    films = [float(np.min(local_film(p, T, 2175.0, _inputs(), _eta, ALPHA)[1])) for T in (50.0, 200.0, 500.0)]
    assert films[0] > films[1] > films[2]
