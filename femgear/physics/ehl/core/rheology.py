"""Lubricant rheology in Hertzian dimensionless form: viscosity and density vs pressure.

All functions take the dimensionless pressure ``P = p / p_h`` (array) and return the
dimensionless value and its derivative d/dP, so that the Newton Jacobian is exact.

Sources
-------
* Barus: eta = eta0 exp(alpha p)  ->  eta_bar = exp(alpha_bar P), alpha_bar = alpha p_h.
* Roelands (isothermal form of the seed paper, eq. 3.1.3, and Venner & Lubrecht 2000,
  sec. 2): eta = eta0 exp{(ln eta0 + 9.67)[(1 + p/p0)^z - 1]}, p0 = 1.96e8 Pa
  (= 1/5.1e-9 Pa), with z = alpha p0 / (ln eta0 + 9.67) when only alpha is known.
* Dowson-Higginson density: rho/rho0 = (5.9e8 + 1.34 p)/(5.9e8 + p), p in Pa (the seed
  paper's (1 + 0.6e-9 p/(1 + 1.7e-9 p)) is the same law written differently).
Pressures below zero (penalty cavitation lets P dip to ~-1e-6) are clamped to 0.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

ROELANDS_P0 = 1.96e8  # Pa
DH_A = 5.9e8  # Pa
DH_B = 1.34

_LN_CAP = 700.0  # exp(+-700) stays finite in float64


@dataclass(frozen=True)
class Rheology:
    """Dimensionless pressure-viscosity and pressure-density laws.

    ``alpha_bar = alpha p_h``. ``viscosity`` is ``"barus"`` or ``"roelands"``; Roelands
    needs ``ph`` (Pa) and ``z``: then ln(eta0) + 9.67 = alpha_bar (p0/p_h) / z, which
    gives the same initial slope alpha as Barus. ``compressible`` switches the
    Dowson-Higginson density on (needs ``ph``).
    """

    alpha_bar: float
    viscosity: str = "barus"
    ph: float | None = None
    z: float = 0.68
    compressible: bool = False

    def __post_init__(self) -> None:
        if self.viscosity not in ("barus", "roelands"):
            raise ValueError(f"viscosity must be 'barus' or 'roelands', not {self.viscosity!r}")
        if (self.viscosity == "roelands" or self.compressible) and not self.ph:
            raise ValueError("Roelands viscosity and Dowson-Higginson density need ph (Pa)")
        if self.alpha_bar < 0:
            raise ValueError("alpha_bar must be >= 0")

    def log_eta(self, P: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """ln(eta/eta0) and its derivative d/dP."""
        Pc = np.maximum(P, 0.0)
        pos = P > 0.0
        if self.viscosity == "barus":
            return self.alpha_bar * Pc, np.where(pos, self.alpha_bar, 0.0)
        ratio = self.ph / ROELANDS_P0
        c = self.alpha_bar / (ratio * self.z)  # = ln(eta0) + 9.67
        base = 1.0 + ratio * Pc
        val = c * (base**self.z - 1.0)
        der = c * self.z * ratio * base ** (self.z - 1.0)
        return val, np.where(pos, der, 0.0)

    def density(self, P: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """rho/rho0 and its derivative d/dP."""
        if not self.compressible:
            return np.ones_like(P), np.zeros_like(P)
        p = np.maximum(P, 0.0) * self.ph
        rho = (DH_A + DH_B * p) / (DH_A + p)
        drho = (DH_B - 1.0) * DH_A / (DH_A + p) ** 2 * self.ph
        return rho, np.where(P > 0.0, drho, 0.0)

    def epsilon(self, P: np.ndarray, H: np.ndarray, lam_bar: float):
        """Poiseuille coefficient eps = rho H^3 / (eta lam_bar) and d eps/dP, d eps/dH.

        H is floored at a tiny positive value so that a bad Newton trial cannot make eps
        negative (the line search rejects such trials anyway).
        """
        le, dle = self.log_eta(P)
        rho, drho = self.density(P)
        Hp = np.maximum(H, 1e-12)
        inv_eta = np.exp(-np.minimum(le, _LN_CAP))
        eps = rho * Hp**3 * inv_eta / lam_bar
        deps_dP = (drho * Hp**3 - rho * Hp**3 * dle) * inv_eta / lam_bar
        deps_dH = np.where(H > 1e-12, 3.0 * rho * Hp**2 * inv_eta / lam_bar, 0.0)
        return eps, deps_dP, deps_dH
