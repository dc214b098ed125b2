"""Friction and contact temperature at the cheap levels, and the laws the TEHL level shares.

- ``oil``       viscosity η(p, T) (Roelands with temperature, Barus) and density ρ(p, T).
- ``flash``     Blok's flash temperature and the Jaeger band integral.
- ``traction``  Newtonian / Ree–Eyring traction of Hertzian EHL contacts with the
                temperature–traction fixed point; Gupta's thermal film factor.
- ``path``      friction of line contacts with the oil, solids and traction bound (``LineFriction``).
"""

from femgear.physics.lubrication.flash import (
    abel_matrix,
    band_flash_temperature,
    blok_flash_temperature,
    thermal_effusivity,
)
from femgear.physics.lubrication.oil import OilLaw
from femgear.physics.lubrication.traction import (
    Solids,
    TractionResult,
    gupta_thermal_factor,
    hertz_traction,
    shear_stress,
)

__all__ = [
    "OilLaw", "Solids", "TractionResult", "abel_matrix", "band_flash_temperature", "blok_flash_temperature",
    "gupta_thermal_factor", "hertz_traction", "shear_stress", "thermal_effusivity",
]
