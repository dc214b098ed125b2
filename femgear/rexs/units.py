"""Units of REXS attributes: each declared unit converted to the scene's unit, never assumed.

The scene is SI except angles (degrees, ``*_deg`` keys), speeds (rev/min, ``speed_rpm``) and the rating's life
(hours, ``rating.life_hours``);
:func:`to_scene_unit` converts a REXS value to that unit from the unit the file declares, after
checking that the declared unit measures the same quantity as the unit the REXS 1.4 database gives
the attribute (:mod:`femgear.rexs.database`).  An unknown unit, or one of another quantity
(``m`` for a helix angle), is an error naming the component and the attribute.
"""

from __future__ import annotations

import math

#: unit -> (quantity, factor, offset): value_in_scene_unit = factor * value + offset
UNITS: dict[str, tuple[str, float, float]] = {
    "none": ("dimensionless", 1.0, 0.0), "": ("dimensionless", 1.0, 0.0), "-": ("dimensionless", 1.0, 0.0),
    "%": ("dimensionless", 0.01, 0.0),
    "mm": ("length", 1e-3, 0.0), "m": ("length", 1.0, 0.0), "mum": ("length", 1e-6, 0.0),
    "µm": ("length", 1e-6, 0.0), "um": ("length", 1e-6, 0.0), "cm": ("length", 1e-2, 0.0),
    "deg": ("angle", 1.0, 0.0), "°": ("angle", 1.0, 0.0), "rad": ("angle", 180.0 / math.pi, 0.0),
    "1 / min": ("speed", 1.0, 0.0), "rad / s": ("speed", 30.0 / math.pi, 0.0), "1 / s": ("speed", 60.0, 0.0),
    "N m": ("torque", 1.0, 0.0), "N mm": ("torque", 1e-3, 0.0), "kN m": ("torque", 1e3, 0.0),
    "W": ("power", 1.0, 0.0), "kW": ("power", 1e3, 0.0),
    "kg": ("mass", 1.0, 0.0), "g": ("mass", 1e-3, 0.0),
    "kg m^2": ("inertia", 1.0, 0.0), "kg mm^2": ("inertia", 1e-6, 0.0),
    "N / mm^2": ("stress", 1e6, 0.0), "MPa": ("stress", 1e6, 0.0), "Pa": ("stress", 1.0, 0.0),
    "GPa": ("stress", 1e9, 0.0), "N / m^2": ("stress", 1.0, 0.0),
    "kg / dm^3": ("density", 1e3, 0.0), "kg / m^3": ("density", 1.0, 0.0), "g / cm^3": ("density", 1e3, 0.0),
    "mm^2 / s": ("kinematic viscosity", 1e-6, 0.0), "m^2 / s": ("kinematic viscosity", 1.0, 0.0),
    "mPa s": ("dynamic viscosity", 1e-3, 0.0), "Pa s": ("dynamic viscosity", 1.0, 0.0),
    "mm^2 / N": ("compliance", 1e-6, 0.0), "m^2 / N": ("compliance", 1.0, 0.0), "1 / Pa": ("compliance", 1.0, 0.0),
    "1 / GPa": ("compliance", 1e-9, 0.0),
    "C": ("temperature", 1.0, 273.15), "°C": ("temperature", 1.0, 273.15), "K": ("temperature", 1.0, 0.0),
    "1e-6 / C": ("expansion", 1e-6, 0.0), "1e-6 / K": ("expansion", 1e-6, 0.0), "1 / K": ("expansion", 1.0, 0.0),
    "1 / C": ("expansion", 1.0, 0.0),
    "J / (kg K)": ("specific heat", 1.0, 0.0), "W / (m K)": ("conductivity", 1.0, 0.0),
    "N / m": ("stiffness", 1.0, 0.0), "N / mm": ("stiffness", 1e3, 0.0), "N / mum": ("stiffness", 1e6, 0.0),
    "N s / m": ("damping", 1.0, 0.0), "N m / rad": ("torsional stiffness", 1.0, 0.0),
    "N mm / rad": ("torsional stiffness", 1e-3, 0.0),
    "kg m": ("unbalance", 1.0, 0.0), "g mm": ("unbalance", 1e-6, 0.0),
    "HV": ("vickers", 1.0, 0.0),
    "h": ("time", 1.0, 0.0), "s": ("time", 1.0 / 3600.0, 0.0),   # the scene's one time (rating.life_hours) is in h
}


class UnitMismatch(ValueError):
    """The declared unit is unknown or measures another quantity; the message says what was expected."""


def normalise(unit: str | None) -> str | None:
    """One spelling per unit: outer blanks stripped, runs of blanks made one."""
    return None if unit is None else " ".join(unit.split())


def to_scene_unit(value: float, declared: str | None, expected: str) -> float:
    """``value`` given in ``declared`` converted to the scene unit of ``expected``'s quantity.

    Raises :class:`UnitMismatch` for a missing unit on a dimensional attribute, an unknown unit,
    or a unit of another quantity.
    """
    quantity = UNITS[expected][0]
    unit = normalise(declared)
    if unit is None:
        if quantity == "dimensionless":
            return value
        raise UnitMismatch(f"no unit declared (expected {expected!r} or another {quantity} unit)")
    if unit not in UNITS:
        raise UnitMismatch(f"unknown unit {declared!r} (expected {expected!r})")
    got, factor, offset = UNITS[unit]
    if got != quantity:
        raise UnitMismatch(f"unit {declared!r} is not a {quantity} unit (expected {expected!r})")
    inverse = _integer_inverse(factor)
    return (value / inverse if inverse else factor * value) + offset


def from_scene_unit(value: float, unit: str) -> float:
    """A scene value (SI, degrees, rev/min) written in ``unit`` (inverse of :func:`to_scene_unit`)."""
    _, factor, offset = UNITS[unit]
    inverse = _integer_inverse(factor)
    return (value - offset) * inverse if inverse else (value - offset) / factor


def _integer_inverse(factor: float) -> float | None:
    """10ᵏ where ``factor`` is 10⁻ᵏ (mm, µm, mm²/s, ...): dividing by the exact integer rounds once, so 4.5 mm is
    0.0045 m to the last bit (4.5 × 1e-3 is 0.0045000000000000005), and the scene's numbers survive a round trip."""
    if factor >= 1:
        return None
    inverse = round(1.0 / factor)
    return float(inverse) if abs(inverse * factor - 1.0) < 1e-12 else None
