"""Oil viscosity from the two data sheet points REXS carries: ASTM D341 (Ubbelohde–Walther), as the oil
library uses it (:mod:`femgear.physics.lubrication.walther`), and α between REXS's 38 °C and the oil's reference."""

import math

from femgear.physics.lubrication.walther import (
    T40,
    T100,
    kinematic_viscosity,
    temperature_coefficient,
    walther_constants,
)

T38 = 311.15   #: the temperature of REXS's lubricant pressure_viscosity_coefficient_at_38_degrees_celsius [K]


def pressure_viscosity_from(alpha_t: float, temperature: float, eta0: float, beta_t: float, t0: float) -> float:
    """α0 at the reference ``t0`` [1/Pa] of the Roelands law (η0, β_T at t0) whose α at ``temperature`` is
    ``alpha_t`` (the inverse of :meth:`femgear.physics.lubrication.oil.OilLaw.pressure_viscosity`: Roelands'
    α(T) = α0 ((T − 138)/(T0 − 138))^(−S0); S0 does not depend on α)."""
    s0 = beta_t * (t0 - 138.0) / (math.log(eta0) + 9.67)
    return alpha_t * ((temperature - 138.0) / (t0 - 138.0)) ** s0


__all__ = ["T38", "T40", "T100", "kinematic_viscosity", "pressure_viscosity_from", "temperature_coefficient",
           "walther_constants"]
