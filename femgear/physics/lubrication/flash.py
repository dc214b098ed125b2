"""Flash temperature of sliding contacts: Blok's formula and the Jaeger band integral.

Both solids are semi-infinite bodies moving through a band heat source of half-width
b at speeds v1, v2 (high Péclet number).  Under Blok's postulate (equal surface
temperatures, heat partitioned accordingly) the surface temperature rise at x is

    ΔT_s(x) = ∫_{−b}^{x} q(ξ)/√(x − ξ) dξ / (√π (B1 √v1 + B2 √v2)),   B = √(k ρ c),

q the frictional heat flux [W/m²] (Jaeger, Proc. R. Soc. NSW 76 (1942) 203; Blok,
Proc. Gen. Disc. Lubr. 2 (1937) 222).  For the semi-elliptical q = μ |v1 − v2| p its
maximum is Blok's

    ΔT_fl = 1.11 μ w' |v1 − v2| / (√(2b) (B1 √v1 + B2 √v2)),

the form of ISO/TS 6336-20 (2017, eq. for the flash temperature with the local load
w' = X_Γ w_Bt); the test suite checks the integral against it.
"""

from __future__ import annotations

import math

import numpy as np


def thermal_effusivity(conductivity: float, density: float, specific_heat: float) -> float:
    """B = √(k ρ c) [W s^½/(m² K)]."""
    return math.sqrt(conductivity * density * specific_heat)


def blok_flash_temperature(mu, w, vs, b, v1, v2, B1: float, B2: float):
    """Blok's maximum flash temperature [K] of a Hertzian band (semi-elliptic heat source)."""
    vs, v1, v2 = np.abs(vs), np.abs(v1), np.abs(v2)
    return 1.11 * np.asarray(mu) * np.asarray(w) * vs / (np.sqrt(2 * np.asarray(b)) * (B1 * np.sqrt(v1) + B2 * np.sqrt(v2)))


def abel_matrix(n: int) -> np.ndarray:
    """Lower-triangular A with (A q)_i ≈ ∫_{−1}^{x_i} q(ξ)/√(x_i − ξ) dξ on [−1, 1].

    ``n`` equal cells, q constant per cell, x_i the cell centres; exact for
    piecewise-constant q.  Scale by √b for a band of half-width b.
    """
    edges = np.linspace(-1.0, 1.0, n + 1)
    centres = 0.5 * (edges[:-1] + edges[1:])
    d_lo = centres[:, None] - edges[None, :-1]
    d_hi = centres[:, None] - edges[None, 1:]
    A = 2 * (np.sqrt(np.clip(d_lo, 0, None)) - np.sqrt(np.clip(d_hi, 0, None)))
    return np.tril(A)


def band_flash_temperature(q: np.ndarray, b, v1, v2, B1: float, B2: float, A: np.ndarray | None = None) -> np.ndarray:
    """Surface temperature rise [K] along the band for heat flux ``q`` on cell centres.

    ``q`` has shape (..., n) over the n cells of [−b, b]; ``b``, ``v1``, ``v2`` broadcast
    against its leading axes.
    """
    q = np.asarray(q, dtype=float)
    A = abel_matrix(q.shape[-1]) if A is None else A
    b, v1, v2 = (np.asarray(v, dtype=float)[..., None] for v in (b, v1, v2))
    return (q @ A.T) * np.sqrt(b) / (math.sqrt(math.pi) * (B1 * np.sqrt(np.abs(v1)) + B2 * np.sqrt(np.abs(v2))))


def line_flash_temperature(mu, w, R, ue, srr, E_red: float, B1: float, B2: float):
    """Blok's maximum flash temperature [K] of Hertzian line contacts with friction coefficient ``mu`` from
    operating data: load per length ``w`` [N/m], reduced radius ``R`` [m], entrainment speed ``ue`` [m/s],
    slide-to-roll ratio ``srr`` = (v1 − v2)/ue [-] (surface speeds v1,2 = ue (1 ± srr/2)), reduced modulus
    ``E_red`` [Pa] (Hertz half-width b = √(8 w R/(π E'))); arrays broadcast."""
    w, R, ue, srr = np.broadcast_arrays(*(np.asarray(a, dtype=float) for a in (w, R, ue, srr)))
    b = np.sqrt(8 * w * R / (math.pi * E_red))
    return blok_flash_temperature(mu, w, srr * ue, b, ue * (1 + srr / 2), ue * (1 - srr / 2), B1, B2)
