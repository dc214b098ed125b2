"""Unit conversion from the declared unit, and the ν40/ν100 viscosity law (ASTM D341)."""

from __future__ import annotations

import math

import pytest

from femgear.rexs.units import UnitMismatch, from_scene_unit, to_scene_unit
from femgear.rexs.viscosity import kinematic_viscosity, temperature_coefficient


@pytest.mark.parametrize("value, unit, expected, result", [
    (6.0, "mm", "mm", 6e-3), (6e-3, "m", "mm", 6e-3), (12.0, "mum", "mm", 12e-6),
    (20.0, "deg", "deg", 20.0), (math.pi / 9, "rad", "deg", 20.0), (20.0, "°", "deg", 20.0),
    (60.0, "C", "C", 333.15), (333.15, "K", "C", 333.15),
    (210000.0, "N / mm^2", "N / mm^2", 210e9), (210.0, "GPa", "N / mm^2", 210e9),
    (7.85, "kg / dm^3", "kg / dm^3", 7850.0), (220.0, "mm^2 / s", "mm^2 / s", 220e-6),
    (0.018, "mm^2 / N", "mm^2 / N", 18e-9), (11.5, "1e-6 / C", "1e-6 / C", 11.5e-6),
    (1480.0, "1 / min", "1 / min", 1480.0), (2 * math.pi, "rad / s", "1 / min", 60.0),
    (500.0, "N m", "N m", 500.0), (5e5, "N mm", "N m", 500.0), (3.0, "N  /  mm^2", "N / mm^2", 3e6),
])
def test_declared_units_convert_to_the_scene_unit(value, unit, expected, result):
    assert to_scene_unit(value, unit, expected) == pytest.approx(result, rel=1e-14)


@pytest.mark.parametrize("unit", ["mm", "deg", "C", "N / mm^2", "kg / dm^3", "mm^2 / s", "1e-6 / C", "mum"])
def test_writing_inverts_reading(unit):
    assert to_scene_unit(from_scene_unit(0.123456789, unit), unit, unit) == pytest.approx(0.123456789, rel=1e-15)


@pytest.mark.parametrize("unit, expected, words", [
    ("deg", "mm", "not a length unit"), ("furlong", "mm", "unknown unit"), (None, "mm", "no unit declared"),
    ("mm", "none", "not a dimensionless unit"),
])
def test_a_unit_of_another_quantity_is_refused(unit, expected, words):
    with pytest.raises(UnitMismatch, match=words):
        to_scene_unit(1.0, unit, expected)


def test_walther_passes_through_both_data_sheet_points():
    assert kinematic_viscosity(220e-6, 19e-6, 313.15) == pytest.approx(220e-6, rel=1e-12)
    assert kinematic_viscosity(220e-6, 19e-6, 373.15) == pytest.approx(19e-6, rel=1e-12)


def test_temperature_coefficient_is_the_log_slope_of_eta():
    """β_T = −d ln(ν ρ)/dT, against a central difference of the same law (ρ ∝ 1 − ε ΔT)."""
    eps, t, h = 6.5e-4, 333.15, 1e-3
    nu = [kinematic_viscosity(220e-6, 19e-6, t + s * h) * (1 - eps * s * h) for s in (-1, 1)]
    numeric = -(math.log(nu[1]) - math.log(nu[0])) / (2 * h)
    assert temperature_coefficient(220e-6, 19e-6, t, eps) == pytest.approx(numeric, rel=1e-6)
    assert 0.02 < numeric < 0.06     # a mineral oil near 60 °C


def test_every_unit_of_the_shipped_table_converts():
    """Each 1.4 unit femgear maps, and each of its custom units, is one the converter knows."""
    from femgear.rexs.database import ATTRIBUTES, CUSTOM
    from femgear.rexs.units import UNITS

    units = {u for u, _, _ in ATTRIBUTES.values()} | {u for u, _ in CUSTOM.values()}
    assert units <= set(UNITS), units - set(UNITS)
    assert all(attr.startswith("custom_femgear_") for _, attr in CUSTOM)
    assert not set(ATTRIBUTES) & set(CUSTOM)
