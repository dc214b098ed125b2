"""Film formulas: hand-computed values (tier 4) and their asymptotes (tier 3)."""

import math

import numpy as np
import pytest

from femgear.physics.contact import (
    dowson_higginson_minimum,
    dowson_toyoda_central,
    hamrock_dowson_central,
    hamrock_dowson_minimum,
    moes_line,
    moes_line_central,
    moes_point,
    nvm_central,
)

# NVM (1994) central film, circular contact, computed by hand from the published formula
NVM_TABLE = {(10, 10): 4.832, (20, 10): 4.708, (50, 10): 4.595, (100, 10): 4.497, (200, 10): 4.380,
             (500, 10): 4.196, (1000, 10): 4.035, (20, 5): 3.276, (20, 20): 7.076, (100, 20): 6.876}


@pytest.mark.parametrize("ML,value", NVM_TABLE.items())
def test_nvm_hand_values(ML, value):
    assert nvm_central(*ML) == pytest.approx(value, abs=6e-4)


def test_nvm_asymptotes_circular():
    # rigid-isoviscous 41.3 M^-2 and elastic-isoviscous 2.42 M^-2/15 (L = 0)
    assert nvm_central(1e-2, 0.0) / (41.3 * 1e-2**-2) == pytest.approx(1.0, abs=2e-3)
    assert nvm_central(1e6, 0.0) / (2.42 * 1e6 ** (-2 / 15)) == pytest.approx(1.0, abs=5e-3)
    # elastic-piezoviscous 1.247 M^-1/12 L^3/4 at large M and L
    M, L = 1e6, 60.0
    assert nvm_central(M, L) / (1.247 * M ** (-1 / 12) * L**0.75) == pytest.approx(1.0, abs=0.01)


def test_nvm_elliptic_ratio_one_is_circular_and_wide_contacts_get_thicker_films():
    assert nvm_central(50.0, 10.0, ratio=1.0) == pytest.approx(nvm_central(50.0, 10.0))
    # λ = R_x/R_y < 1: the side leakage falls, the film grows
    assert nvm_central(50.0, 10.0, ratio=0.2) > nvm_central(50.0, 10.0)


def test_moes_line_hand_value_and_asymptotes():
    assert moes_line_central(20.0, 10.0) == pytest.approx(5.1005, abs=5e-4)
    assert moes_line_central(1e-3, 0.0) / (3.0 / 1e-3) == pytest.approx(1.0, abs=1e-3)
    assert moes_line_central(1e7, 0.0) / (2.621 * 1e7 ** (-0.2)) == pytest.approx(1.0, abs=0.01)


def test_dowson_toyoda_in_moes_units_has_no_speed_dependence():
    """3.06 U^0.69 G^0.56 W'^-0.1 / √(2U) = 1.897 L^0.56 M^-0.1 for any U."""
    G = 22e-9 * 2.3e11
    for U in (1e-12, 1e-11, 1e-10):
        W = 2e-4
        M, L = moes_line(W, U, G)
        H = dowson_toyoda_central(U, G, W) / math.sqrt(2 * U)
        assert H == pytest.approx(3.06 * 2**-0.69 * L**0.56 * M**-0.10, rel=1e-12)


def test_moes_line_formula_agrees_with_dowson_toyoda_in_the_ep_regime():
    U, G, W = 1e-11, 5000.0, 1e-4
    M, L = moes_line(W, U, G)
    H_dt = dowson_toyoda_central(U, G, W) / math.sqrt(2 * U)
    assert moes_line_central(M, L) == pytest.approx(H_dt, rel=0.10)


def test_hamrock_dowson_circular_prefactors_and_hand_value():
    assert hamrock_dowson_central(1.0, 1.0, 1.0) == pytest.approx(1.919, abs=1e-3)
    assert hamrock_dowson_minimum(1.0, 1.0, 1.0) == pytest.approx(1.833, abs=1e-3)
    U, G, W = 1e-11, 5000.0, 1e-6
    hand = 2.69 * 1e-11**0.67 * 5000**0.53 * 1e-6**-0.067 * (1 - 0.61 * math.exp(-0.73 * 1.0339))
    assert hamrock_dowson_central(U, G, W) == pytest.approx(hand, rel=1e-12)


def test_hamrock_dowson_is_near_nvm_in_its_fit_range():
    """HD and NVM agree within ~20 % for M = 10–300, L = 5–12 (HD's fit range)."""
    U, G = 5e-12, 4600.0
    for W in (1e-7, 5e-7, 2e-6):
        M, L = moes_point(W, U, G)
        H_hd = hamrock_dowson_central(U, G, W) / math.sqrt(2 * U)
        assert H_hd == pytest.approx(float(nvm_central(M, L)), rel=0.2), (M, L)


def test_line_minimum_below_central():
    U, G = np.array([1e-12, 1e-11, 1e-10]), 4600.0
    assert np.all(dowson_higginson_minimum(U, G, 1e-4) < dowson_toyoda_central(U, G, 1e-4))
