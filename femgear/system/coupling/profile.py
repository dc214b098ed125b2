"""Flank deviations along the path of contact → drive/coast deviation tables over one mesh period.

A deviation h(u) of the flank pair at path position u (positive = material removed:
wear of pinion and gear; thermal expansion enters with the opposite sign) moves the
contact threshold of a helix by the stiffness-weighted mean of h over the contact
lines at that instant (uniform stiffness per unit line length; dl = du/sin β_b, so the
mean over a line is the mean over its transverse extent in u) — the paper's
"comprehensive equivalent error along the line of action" taken over the actual
contact lines of a helical mesh instead of a fitted harmonic series.

Wear acts on the loaded (drive) flanks, thermal expansion on both: the drive table
is the line mean of h1 + h2 − ζ_T1 − ζ_T2, the coast table that of −(ζ_T1 + ζ_T2).
The coast flanks mesh along the mirror path; ζ_T depends on the radius only, so
its coast table uses the drive table of ζ (exact for the uniform expansion, within the
ζ ripple of a mesh cycle otherwise).  How the tables enter the dynamics, once each:
:class:`femgear.system.dynamics.model.MeshDeviation`.
"""

from __future__ import annotations

import numpy as np

from femgear.physics.geometry import GearPair, contact_lines
from femgear.system.dynamics.model import MeshDeviation


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
    the grid spacing, which the dynamics would feel as an excitation).  A spur pair's
    lines each cover the whole face at one position: the mean is that over the pairs in
    contact (equal lengths b).
    """
    u = np.asarray(u, dtype=float)
    deviation = np.asarray(deviation, dtype=float)
    if deviation.shape != u.shape or u.size < 2:
        raise ValueError("deviation must be sampled at the positions u (at least two)")
    table = np.empty(n_phase)
    for i in range(n_phase):
        lines = contact_lines(pair, i / n_phase, offset)
        if pair.beta_b == 0:
            if lines.u_lo.size == 0:
                raise ValueError("no tooth pair in contact")
            table[i] = float(np.mean(np.interp(lines.u_lo, u, deviation)))
            continue
        lo = np.clip(lines.u_lo, u[0], u[-1])
        hi = np.clip(lines.u_hi, u[0], u[-1])
        width = np.sum(hi - lo)
        if width <= 0:
            raise ValueError("the positions u do not cover the contact lines")
        table[i] = np.sum(_antiderivative(u, deviation, hi) - _antiderivative(u, deviation, lo)) / width
    return table


def mesh_deviation(pair: GearPair, u: np.ndarray, wear: np.ndarray, thermal: np.ndarray, stagger: float = 0.0,
                   n_phase: int = 128) -> MeshDeviation | None:
    """Drive/coast deviation tables of both helices (None when there is no deviation).

    ``wear`` = h1 + h2 and ``thermal`` = ζ_T1 + ζ_T2 along the path [m].
    """
    if not (np.any(wear) or np.any(thermal)):
        return None
    offsets = (0.0, stagger)
    zeta = np.array([phase_table(pair, u, thermal, n_phase, off) for off in offsets])
    worn = np.array([phase_table(pair, u, wear, n_phase, off) for off in offsets])
    return MeshDeviation(drive=worn - zeta, coast=-zeta)


def harmonic_fit(e: np.ndarray, m: int) -> tuple[np.ndarray, np.ndarray]:
    """Least-squares fit of e(φ) = a0 + Σ_k a_k cos 2πkφ + b_k sin 2πkφ (k ≤ m) on φ = i/n.

    Returns the fitted curve and the amplitudes |c_k| = √(a_k² + b_k²), k = 0..m (c_0 = mean)."""
    phi = np.arange(e.size) / e.size
    cols = [np.ones_like(phi)] + [f(2 * np.pi * k * phi) for k in range(1, m + 1) for f in (np.cos, np.sin)]
    A = np.array(cols).T
    coef = np.linalg.lstsq(A, e, rcond=None)[0]
    amps = np.concatenate([[abs(coef[0])], np.hypot(coef[1::2], coef[2::2])])
    return A @ coef, amps
