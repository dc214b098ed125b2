"""Oil viscosity from the two data sheet points REXS carries: ASTM D341 (Ubbelohde–Walther), as the oil
library uses it (:mod:`femgear.physics.lubrication.walther`)."""

from femgear.physics.lubrication.walther import (
    T40,
    T100,
    kinematic_viscosity,
    temperature_coefficient,
    walther_constants,
)

__all__ = ["T40", "T100", "kinematic_viscosity", "temperature_coefficient", "walther_constants"]
