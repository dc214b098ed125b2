"""Radiated sound power from the normal velocity of a surface: ERP and the ISO/TS 7849 arithmetic.

Equivalent radiated power (radiation efficiency σ = 1, the upper limit of ISO/TS 7849-1's survey method):

    P = Z_c ⟨v_n²⟩ S = ½ Z_c Σ_i A_i |v̂_n,i|²        [W],

with Z_c = ρ c of the air (ISO/TS 7849 normalises to Z_c,n = 411 N s/m³), A_i the area of surface element i and
v̂_n,i the amplitude of its normal velocity at one frequency (a mean square ½|v̂|²).  In levels (ISO/TS 7849-1,
its formula for L_W):

    L_W = L_v + 10 lg(S/S₀) + 10 lg σ + 10 lg(Z_c/Z_c,0),     L_v = 10 lg(⟨v²⟩/v₀²),

v₀ = 5·10⁻⁸ m/s, S₀ = 1 m², Z_c,0 = 400 N s/m³ (so v₀² Z_c,0 S₀ = 10⁻¹² W = P₀ and L_W = 10 lg(P/P₀)).  Part 2 of
the standard replaces σ = 1 by a measured radiation factor per band; ``radiation_factor`` takes one.  Bands and
order lines add as powers (:func:`total_level`); A-weighting by IEC 61672-1 (its closed form at any frequency,
:func:`a_weighting`; its one-decimal table at the nominal octave centres, :data:`A_WEIGHTING_OCTAVES`).
"""

from __future__ import annotations

import math

import numpy as np

V0 = 5.0e-8          #: reference velocity v₀ [m/s]
S0 = 1.0             #: reference area S₀ [m^2]
ZC0 = 400.0          #: reference characteristic impedance Z_c,0 [N s/m^3]
ZC_AIR = 411.0       #: the normalised characteristic impedance of air Z_c,n of ISO/TS 7849 [N s/m^3]
P0 = 1.0e-12         #: reference sound power [W]
#: IEC 61672-1 A-weighting at the nominal octave-band centres 31.5 Hz … 16 kHz [dB]
A_WEIGHTING_OCTAVES = {31.5: -39.4, 63.0: -26.2, 125.0: -16.1, 250.0: -8.6, 500.0: -3.2, 1000.0: 0.0, 2000.0: 1.2,
                       4000.0: 1.0, 8000.0: -1.1, 16000.0: -6.6}


def velocity_level(mean_square: np.ndarray) -> np.ndarray:
    """L_v = 10 lg(⟨v²⟩/v₀²) of a mean-square velocity [m²/s²] → [dB re 5e-8 m/s]."""
    return 10.0 * np.log10(np.asarray(mean_square, dtype=float) / V0**2)


def velocity_level_from_acceleration(peak_acceleration: float, frequency: float) -> float:
    """L_v of a sinusoidal acceleration of amplitude â [m/s²] at ``frequency`` [Hz]: 20 lg(â/(2π f v₀ √2)) [dB]."""
    return 20.0 * math.log10(peak_acceleration / (2 * math.pi * frequency * V0 * math.sqrt(2.0)))


def sound_power_level(lv: np.ndarray, area: float, radiation_factor: np.ndarray | float = 1.0,
                      impedance: float = ZC_AIR) -> np.ndarray:
    """ISO/TS 7849 L_W = L_v + 10 lg(S/S₀) + 10 lg σ + 10 lg(Z_c/Z_c,0) [dB re 1 pW] (module docstring)."""
    return (np.asarray(lv, dtype=float) + 10.0 * math.log10(area / S0)
            + 10.0 * np.log10(np.asarray(radiation_factor, dtype=float)) + 10.0 * math.log10(impedance / ZC0))


def equivalent_radiated_power(area: np.ndarray, normal_velocity: np.ndarray, impedance: float = ZC_AIR) -> np.ndarray:
    """ERP = ½ Z_c Σ_i A_i |v̂_n,i|² [W] of complex normal-velocity amplitudes ``normal_velocity`` (..., n_i) [m/s]
    on elements of ``area`` (n_i,) [m^2]."""
    return 0.5 * impedance * np.abs(np.asarray(normal_velocity)) ** 2 @ np.asarray(area, dtype=float)


def power_level(power: np.ndarray) -> np.ndarray:
    """L_W = 10 lg(P/P₀) [dB re 1 pW] of a sound power [W] (0 W: −inf is not returned, a floor of −100 dB)."""
    return 10.0 * np.log10(np.maximum(np.asarray(power, dtype=float), P0 * 1e-10) / P0)


def total_level(levels: np.ndarray, axis: int = -1) -> np.ndarray:
    """Power sum 10 lg Σ 10^(L/10) of levels [dB] along ``axis``."""
    return 10.0 * np.log10(np.sum(10.0 ** (np.asarray(levels, dtype=float) / 10.0), axis=axis))


def a_weighting(frequency: np.ndarray) -> np.ndarray:
    """A-weighting A(f) = 20 lg R_A(f) + 2.00 dB of IEC 61672-1 (its closed form) at ``frequency`` [Hz] → [dB]."""
    f2 = np.asarray(frequency, dtype=float) ** 2
    ra = 12194.0**2 * f2**2 / ((f2 + 20.6**2) * np.sqrt((f2 + 107.7**2) * (f2 + 737.9**2)) * (f2 + 12194.0**2))
    return 20.0 * np.log10(ra) + 2.00
