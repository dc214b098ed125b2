"""Flank deviations along the path of contact → mesh excitation over one mesh period.

A deviation h(u) of the flank pair at path position u (positive = material removed:
wear of pinion and gear; thermal expansion enters with the opposite sign) changes the
mesh deflection of a helix by the stiffness-weighted mean of h over the contact lines
that carry load at that instant (uniform stiffness per unit line length; dl = du/sin β_b).
This is the paper's "comprehensive equivalent error along the line of action"
e_f = (ζ_T + h)_p + (ζ_T + h)_g, taken over the actual contact lines of a helical
mesh instead of a fitted harmonic series, so it carries the helix's load sharing.
The same mean is the change of the dynamic backlash, the paper's
b(t) = b0 + w1 + w2 − ζ_T1 − ζ_T2.
"""

from __future__ import annotations

import numpy as np

from femgear.geometry import GearPair
from femgear.wear.load_sharing import phase_coverage, trapezoid_weights


def phase_table(pair: GearPair, u: np.ndarray, deviation: np.ndarray, n_phase: int = 128,
                offset: float = 0.0) -> np.ndarray:
    """Mean of ``deviation`` over the contact lines of one helix at phases i/n_phase [m]."""
    u = np.asarray(u, dtype=float)
    deviation = np.asarray(deviation, dtype=float)
    if deviation.shape != u.shape:
        raise ValueError("deviation must be sampled at the positions u")
    phases = np.arange(n_phase) / n_phase
    cover = phase_coverage(pair, u, phases, offset).astype(float)
    w = cover * trapezoid_weights(u)[None, :]
    total = w.sum(axis=1)
    if np.any(total <= 0):
        raise ValueError("the position grid is too coarse: some phases have no contact line on it")
    return (w @ deviation) / total


def excitation_tables(pair: GearPair, u: np.ndarray, removed: np.ndarray, stagger: float = 0.0,
                      n_phase: int = 128) -> tuple[tuple[np.ndarray, np.ndarray], np.ndarray]:
    """(e_L, e_R) profile-deviation tables and the backlash change Δb over one mesh period.

    ``removed`` = h1 + h2 − ζ_T1 − ζ_T2 along the path [m]; Δb is the mean of the two
    helices (the pair has one backlash).
    """
    left = phase_table(pair, u, removed, n_phase)
    right = phase_table(pair, u, removed, n_phase, offset=stagger)
    return (left, right), 0.5 * (left + right)
