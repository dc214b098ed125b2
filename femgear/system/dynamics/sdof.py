"""Kahraman–Singh single-DOF gear-pair oscillator with backlash, and frequency sweeps.

Kahraman & Singh, "Non-linear dynamics of a spur gear pair", JSV 142:49 (1990):
the dynamic transmission error x of a pair with backlash 2b, in the dimensionless
form (lengths over b, time over 1/ω_n):

    x'' + 2 ζ x' + f(x) = F_m + F_a cos(Ω τ),   f = dead zone of half-width 1

(time-invariant mesh stiffness, mean load F_m, one harmonic of the transmission
error F_a).  With F_a/(2ζ) > F_m the teeth separate near Ω ≈ 1; the effective
stiffness drops while separated, the resonance bends to lower Ω (softening), and
slow up- and down-sweeps follow different branches with jumps between them.

The sweep continues the state from one frequency to the next (as a slowly swept
experiment does), integrates ``cycles`` forcing periods with fixed-step RK4 and
measures the last ``measure`` periods.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class SweepResult:
    frequency: np.ndarray      #: Ω [-], in sweep order
    amplitude: np.ndarray      #: half peak-to-peak of x [-]
    contact_loss: np.ndarray   #: fraction of the measured time with |x| ≤ 1 [-]
    back_contact: np.ndarray   #: fraction with x < −1 [-]
    direction: str


def _run(omega, zeta, Fm, Fa, x, v, cycles, measure, steps_per_cycle):
    T = 2 * math.pi / omega
    h = T / steps_per_cycle
    n_total = cycles * steps_per_cycle
    n_meas = measure * steps_per_cycle
    xmin, xmax, loss, back = math.inf, -math.inf, 0, 0
    tz = 2 * zeta

    def acc(t, x, v):
        f = x - 1.0 if x > 1.0 else (x + 1.0 if x < -1.0 else 0.0)
        return Fm + Fa * math.cos(omega * t) - tz * v - f

    t = 0.0
    for i in range(n_total):
        a1 = acc(t, x, v)
        x2, v2 = x + 0.5 * h * v, v + 0.5 * h * a1
        a2 = acc(t + 0.5 * h, x2, v2)
        x3, v3 = x + 0.5 * h * v2, v + 0.5 * h * a2
        a3 = acc(t + 0.5 * h, x3, v3)
        x4, v4 = x + h * v3, v + h * a3
        a4 = acc(t + h, x4, v4)
        x += h / 6 * (v + 2 * v2 + 2 * v3 + v4)
        v += h / 6 * (a1 + 2 * a2 + 2 * a3 + a4)
        t += h
        if i >= n_total - n_meas:
            xmin, xmax = min(xmin, x), max(xmax, x)
            if abs(x) <= 1.0:
                loss += 1
            elif x < -1.0:
                back += 1
    return x, v, 0.5 * (xmax - xmin), loss / n_meas, back / n_meas


def kahraman_singh_sweep(frequencies: np.ndarray, zeta: float = 0.05, mean_load: float = 0.1,
                         alternating_load: float = 0.02, cycles: int = 60, measure: int = 15,
                         steps_per_cycle: int = 64, direction: str = "up") -> SweepResult:
    """Sweep Ω over ``frequencies`` (sorted ascending) up or down, continuing the state."""
    if zeta < 0 or mean_load < 0 or alternating_load < 0:
        raise ValueError("zeta, mean_load and alternating_load must be non-negative")
    if direction not in ("up", "down"):
        raise ValueError(f"direction must be 'up' or 'down' (got {direction!r})")
    w = np.sort(np.asarray(frequencies, dtype=float))
    if direction == "down":
        w = w[::-1]
    if not np.all(w > 0):
        raise ValueError("frequencies must be positive")
    x, v = 1.0 + mean_load, 0.0        # static contact on the drive flank
    amp, loss, back = (np.empty(w.size) for _ in range(3))
    for i, om in enumerate(w):
        x, v, amp[i], loss[i], back[i] = _run(om, zeta, mean_load, alternating_load, x, v, cycles, measure,
                                              steps_per_cycle)
    return SweepResult(frequency=w, amplitude=amp, contact_loss=loss, back_contact=back, direction=direction)
