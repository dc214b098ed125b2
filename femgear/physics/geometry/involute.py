"""The involute function and its inverse (ISO 21771 §4)."""

from __future__ import annotations

import math

from scipy.optimize import brentq


def inv(alpha: float) -> float:
    """Involute function inv α = tan α − α."""
    return math.tan(alpha) - alpha


def inv_inverse(value: float) -> float:
    """The angle α in (0, π/2) with inv α = value (value ≥ 0)."""
    if value < 0:
        raise ValueError("the involute function is non-negative")
    if value == 0:
        return 0.0
    return brentq(lambda a: inv(a) - value, 1e-12, math.pi / 2 - 1e-9, xtol=1e-15, rtol=1e-15)
