"""Gear ratings and mesh losses (pure functions of a :class:`femgear.geometry.GearPair`).

- ``contact_stress``  ISO 6336-2:2019 method B: Z_H, Z_E, Z_ε, Z_β, Z_B/Z_D, σ_H0, σ_H.
- ``permissible``     ISO 6336-2:2019: Z_NT, Z_L, Z_v, Z_R, σ_HP and the safety factor S_H.
- ``power``           mesh power loss and efficiency along the path (μ × normal load × sliding speed).
- ``scene``           the adapters from a scene's ``[rating]`` table and operating point.
"""

from femgear.rating.contact_stress import ContactStress, LoadFactors, contact_stress
from femgear.rating.permissible import MaterialLimits, PittingRating, pitting_rating
from femgear.rating.power import MeshPowerLoss, mesh_power_loss, ohlendorf_loss_factor

__all__ = ["ContactStress", "LoadFactors", "MaterialLimits", "MeshPowerLoss", "PittingRating", "contact_stress",
           "mesh_power_loss", "ohlendorf_loss_factor", "pitting_rating"]
