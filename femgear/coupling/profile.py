"""Flank deviations along the path of contact → mesh excitation over one mesh period.

A deviation h(u) of the flank pair at path position u (positive = material removed:
wear of pinion and gear; thermal expansion enters with the opposite sign) changes the
mesh deflection of a helix by the stiffness-weighted mean of h over the contact lines
that carry load at that instant (uniform stiffness per unit line length; dl = du/sin β_b,
so the mean over a line is the mean over its transverse extent in u).
This is the paper's "comprehensive equivalent error along the line of action"
e_f = (ζ_T + h)_p + (ζ_T + h)_g, taken over the actual contact lines of a helical
mesh instead of a fitted harmonic series, so it carries the helix's load sharing.
The same mean is the change of the dynamic backlash, the paper's
b(t) = b0 + w1 + w2 − ζ_T1 − ζ_T2.
"""

from __future__ import annotations

import numpy as np

from femgear.geometry import GearPair, contact_lines


def _antiderivative(u: np.ndarray, h: np.ndarray, x: np.ndarray) -> np.ndarray:
    """∫_{u0}^{x} h du of the piecewise-linear interpolant of h, exactly (x within [u0, un])."""
    F = np.concatenate([[0.0], np.cumsum(0.5 * (h[1:] + h[:-1]) * np.diff(u))])
    i = np.clip(np.searchsorted(u, x, side="right") - 1, 0, u.size - 2)
    d = x - u[i]
    slope = (h[i + 1] - h[i]) / (u[i + 1] - u[i])
    return F[i] + h[i] * d + 0.5 * slope * d * d


def phase_table(pair: GearPair, u: np.ndarray, deviation: np.ndarray, n_phase: int = 128,
                offset: float = 0.0) -> np.ndarray:
    """Mean of ``deviation`` over the contact lines of one helix at phases i/n_phase [m].

    The deviation is interpolated linearly between the positions ``u`` and integrated
    exactly over each line's extent, so the table is smooth in the phase (no steps at
    the grid spacing, which the dynamics would feel as an excitation).
    """
    u = np.asarray(u, dtype=float)
    deviation = np.asarray(deviation, dtype=float)
    if deviation.shape != u.shape or u.size < 2:
        raise ValueError("deviation must be sampled at the positions u (at least two)")
    table = np.empty(n_phase)
    for i in range(n_phase):
        lines = contact_lines(pair, i / n_phase, offset)
        lo = np.clip(lines.u_lo, u[0], u[-1])
        hi = np.clip(lines.u_hi, u[0], u[-1])
        width = np.sum(hi - lo)
        if width <= 0:
            raise ValueError("the positions u do not cover the contact lines")
        table[i] = np.sum(_antiderivative(u, deviation, hi) - _antiderivative(u, deviation, lo)) / width
    return table


def excitation_tables(pair: GearPair, u: np.ndarray, removed: np.ndarray, stagger: float = 0.0,
                      n_phase: int = 128) -> tuple[tuple[np.ndarray, np.ndarray], np.ndarray]:
    """(e_L, e_R) profile-deviation tables and the backlash change Δb over one mesh period.

    ``removed`` = h1 + h2 − ζ_T1 − ζ_T2 along the path [m]; Δb is the mean of the two
    helices (the pair has one backlash).
    """
    left = phase_table(pair, u, removed, n_phase)
    right = phase_table(pair, u, removed, n_phase, offset=stagger)
    return (left, right), 0.5 * (left + right)
