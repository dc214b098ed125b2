"""Quadrature over the contact lines of one helix on a grid of path positions.

The loads along the path are stored per unit contact-line length at grid positions u_k and
read between them by linear interpolation.  A contact line covers the transverse extent
[u_lo, u_hi] (dl = du / sin β_b), so the force it carries is Σ_k w'_k ∫_line φ_k du / sin β_b
with φ_k the grid's hat functions: :func:`hat_integrals` gives those weights exactly, and
:func:`line_weights` adds them over every line of a helix at each mesh phase.  Nothing here
assumes one line per position: with an overlap ratio ε_β > 1 several lines cover the same u.
"""

from __future__ import annotations

import numpy as np

from femgear.physics.geometry.gear import GearPair
from femgear.physics.geometry.kinematics import contact_lines


def hat_integrals(u: np.ndarray, lo: float, hi: float) -> np.ndarray:
    """∫_lo^hi φ_k(x) dx for the piecewise-linear hat functions φ_k of the grid ``u`` [m] (0 outside it).

    Σ_k f_k · (this) is the exact integral over [lo, hi] of the linear interpolant of f on ``u``."""
    a, b = u[:-1], u[1:]
    h = b - a
    s = np.clip(lo, a, b)
    t = np.clip(hi, a, b)
    left = ((b - s) ** 2 - (b - t) ** 2) / (2 * h)      # φ_j on cell j: (b - x)/h
    right = ((t - a) ** 2 - (s - a) ** 2) / (2 * h)     # φ_{j+1} on cell j: (x - a)/h
    out = np.zeros(u.size)
    out[:-1] += left
    out[1:] += right
    return out


def line_weights(pair: GearPair, u: np.ndarray, phases: np.ndarray, offset: float = 0.0) -> np.ndarray:
    """(phase × position) quadrature weights [m] of the contact lines of one helix in u.

    Entry (i, k) is Σ_lines ∫_line φ_k du over every contact line of the helix at phase i
    (its transverse extent [u_lo, u_hi] clipped to the grid), so that for a load per unit
    line length w'(u) interpolated linearly between the positions, Σ_k w'_k W[i, k] / sin β_b
    is exactly Σ_lines ∫ w' dl.  Where the overlap ratio ε_β exceeds 1 several lines of one
    helix cover the same u at once, and each counts: the weights then sum to about ε_β × the
    grid's extent (a boolean coverage, counting each u once, made the loads ε_β times too high).
    """
    u = np.asarray(u, dtype=float)
    weights = np.zeros((phases.size, u.size))
    for i, ph in enumerate(phases):
        lines = contact_lines(pair, ph, offset)
        for lo, hi in zip(lines.u_lo, lines.u_hi):
            weights[i] += hat_integrals(u, lo, hi)
    return weights
