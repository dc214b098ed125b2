"""Dimensional lubricant laws: viscosity η(p, T) and density ρ(p, T), SI units.

Roelands with temperature, in the form of the paper (its §3.1.3; Roelands 1966,
Houpert 1985):

    η = η0 exp{(ln η0 + 9.67) [−1 + (1 + 5.1e−9 p)^z0 ((T − 138)/(T0 − 138))^(−S0)]}

with z0 = α / (5.1e−9 (ln η0 + 9.67)) and S0 = β_T (T0 − 138)/(ln η0 + 9.67), so that
the initial slopes are the Barus α and the temperature coefficient β_T.  Barus with
temperature, η = η0 exp(α p − β_T (T − T0)), is the option the published film
formulas assume.  Density: Dowson–Higginson, ρ = ρ0 (1 + 0.6e−9 p/(1 + 1.7e−9 p))
(1 − ε (T − T0)).

:meth:`OilLaw.at` re-bases a law at another temperature: the same η(p, T) and ρ(p, T) everywhere, with
η0, α, β_T and ρ0 taken at the new reference (for Roelands, α(T) = z0 · 5.1e−9 (ln η(0, T) + 9.67)
and β_T(T) = S0 (ln η(0, T) + 9.67)/(T − 138): the pressure–viscosity coefficient falls as the oil
warms, as measured for mineral oils — Tribology Handbook (IMechE), Table 25: 2.4/2.1/1.6e−8 1/Pa
at 30/60/100 °C for a heavy paraffinic machine oil).  So an oil given at one temperature is
carried to the temperature the contact sees by its own laws.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

_P_ROELANDS = 5.1e-9   # 1/Pa  (= 1/1.96e8 Pa)
_LN_CAP = 700.0


@dataclass(frozen=True)
class OilLaw:
    """Viscosity and density of an oil as functions of pressure [Pa] and temperature [K]."""

    eta0: float          #: viscosity at p = 0, T = T0 [Pa s]
    alpha: float         #: Barus pressure-viscosity coefficient [1/Pa]
    beta_t: float        #: temperature-viscosity coefficient [1/K]
    T0: float            #: reference temperature [K]
    rho0: float = 870.0  #: density at p = 0, T = T0 [kg/m³]
    expansion: float = 6.5e-4  #: density-temperature coefficient ε [1/K]
    model: str = "roelands"

    def __post_init__(self) -> None:
        if self.model not in ("roelands", "barus"):
            raise ValueError(f"model must be 'roelands' or 'barus' (got {self.model!r})")
        for name in ("eta0", "T0", "rho0"):
            if not getattr(self, name) > 0:
                raise ValueError(f"{name} must be positive (got {getattr(self, name)!r})")
        if self.model == "roelands" and not self.T0 > 138.0:
            raise ValueError("Roelands needs T0 > 138 K")

    @classmethod
    def from_table(cls, oil, reference_temperature: float, model: str = "roelands") -> OilLaw:
        """The law of an ``[oil]`` table (viscosity, pressure_viscosity, temperature_viscosity, density,
        thermal_expansion) whose viscosity holds at ``reference_temperature`` [K]."""
        return cls(eta0=oil.viscosity, alpha=oil.pressure_viscosity, beta_t=oil.temperature_viscosity,
                   T0=reference_temperature, rho0=oil.density, expansion=oil.thermal_expansion, model=model)

    @classmethod
    def from_table_at(cls, oil, reference_temperature: float, temperature: float, model: str = "roelands") -> OilLaw:
        """The law of an ``[oil]`` table given at ``reference_temperature`` [K], re-based at ``temperature`` [K]."""
        return cls.from_table(oil, reference_temperature, model).at(temperature)

    def at(self, temperature: float) -> OilLaw:
        """The same law with its reference at ``temperature`` [K]: η0, α, β_T, ρ0 and ε there, identical
        η(p, T) and ρ(p, T) at every pressure and temperature (to round-off)."""
        T = float(temperature)
        if not T > 0 or (self.model == "roelands" and not T > 138.0):
            raise ValueError(f"cannot re-base the oil law at T = {T!r} K")
        shrink = 1 - self.expansion * (T - self.T0)
        if not shrink > 0:
            raise ValueError(f"density law gives ρ ≤ 0 at T = {T:g} K")
        return OilLaw(eta0=float(self.viscosity(0.0, T)), alpha=float(self.pressure_viscosity(T)),
                      beta_t=float(self.temperature_viscosity(T)), T0=T, rho0=self.rho0 * shrink,
                      expansion=self.expansion / shrink, model=self.model)

    def pressure_viscosity(self, T) -> np.ndarray:
        """α(T) = ∂ln η/∂p at p = 0 [1/Pa]: Barus' constant α; Roelands' z0 · 5.1e−9 (ln η(0, T) + 9.67)."""
        if self.model == "barus":
            return np.full(np.shape(T), self.alpha) if np.ndim(T) else np.asarray(self.alpha)
        return self.z0 * _P_ROELANDS * (np.log(self.viscosity(0.0, T)) + 9.67)

    def temperature_viscosity(self, T) -> np.ndarray:
        """β_T(T) = −∂ln η/∂T at p = 0 [1/K]: Barus' constant β_T; Roelands' S0 (ln η(0, T) + 9.67)/(T − 138)."""
        if self.model == "barus":
            return np.full(np.shape(T), self.beta_t) if np.ndim(T) else np.asarray(self.beta_t)
        T = np.asarray(T, dtype=float)
        return self.s0 * (np.log(self.viscosity(0.0, T)) + 9.67) / (T - 138.0)

    @property
    def z0(self) -> float:
        """Roelands pressure index z0 = α / (5.1e−9 (ln η0 + 9.67))."""
        return self.alpha / (_P_ROELANDS * (math.log(self.eta0) + 9.67))

    @property
    def s0(self) -> float:
        """Roelands temperature index S0 = β_T (T0 − 138)/(ln η0 + 9.67)."""
        return self.beta_t * (self.T0 - 138.0) / (math.log(self.eta0) + 9.67)

    def log_viscosity_ratio(self, p, T) -> np.ndarray:
        """ln(η/η0) at pressure ``p`` [Pa] and temperature ``T`` [K] (p < 0 taken as 0)."""
        p = np.maximum(np.asarray(p, dtype=float), 0.0)
        T = np.asarray(T, dtype=float)
        if self.model == "barus":
            return np.minimum(self.alpha * p - self.beta_t * (T - self.T0), _LN_CAP)
        if np.any(T <= 138.0):
            raise ValueError("Roelands viscosity is undefined at T ≤ 138 K")
        c = math.log(self.eta0) + 9.67
        val = c * (-1.0 + (1.0 + _P_ROELANDS * p) ** self.z0 * ((T - 138.0) / (self.T0 - 138.0)) ** (-self.s0))
        return np.minimum(val, _LN_CAP)

    def viscosity(self, p, T) -> np.ndarray:
        """η(p, T) [Pa s]."""
        return self.eta0 * np.exp(self.log_viscosity_ratio(p, T))

    def density(self, p, T) -> np.ndarray:
        """ρ(p, T) [kg/m³], Dowson–Higginson with linear thermal expansion."""
        p = np.maximum(np.asarray(p, dtype=float), 0.0)
        return self.rho0 * (1 + 0.6e-9 * p / (1 + 1.7e-9 * p)) * (1 - self.expansion * (np.asarray(T) - self.T0))
