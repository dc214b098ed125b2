"""Backlash: the dead-zone gap function of the mesh deflection.

Kahraman & Singh (JSV 142:49, 1990) and the paper's f_gap: with the (half) backlash
b(t) ≥ 0 and the mesh deflection δ along the line of action [m],

    f(δ) = δ − b   for δ >  b      (drive-side contact)
         = 0       for |δ| ≤ b     (contact loss, teeth separated)
         = δ + b   for δ < −b      (back-side contact)

The elastic mesh force is k(t) f(δ).  femgear measures δ from the tooth position where
the drive flanks just touch plus b, exactly as the paper writes it, so in steady drive
δ ≈ b + F/k.
"""

from __future__ import annotations

import numpy as np


def gap_function(delta: np.ndarray | float, backlash: np.ndarray | float) -> np.ndarray:
    """Dead-zone f(δ; b) [m] (vectorised)."""
    delta = np.asarray(delta, dtype=float)
    return np.where(delta > backlash, delta - backlash, np.where(delta < -backlash, delta + backlash, 0.0))


def contact_indicator(delta: np.ndarray | float, backlash: np.ndarray | float) -> np.ndarray:
    """1 where a flank is in contact (|δ| > b), else 0: the derivative df/dδ."""
    delta = np.asarray(delta, dtype=float)
    return (np.abs(delta) > backlash).astype(float)
