"""Gear ratings and mesh losses (pure functions of a :class:`femgear.physics.geometry.GearPair`).

- ``contact_stress``  ISO 6336-2:2019 method B: Z_H, Z_E, Z_ε, Z_β, Z_B/Z_D, σ_H0, σ_H.
- ``permissible``     ISO 6336-2:2019: Z_NT, Z_L, Z_v, Z_R, σ_HP and the safety factor S_H.
- ``bending``         ISO 6336-3 method B: root geometry (30° tangent), Y_F, Y_S, Y_β, …, σ_F0, σ_F, σ_FP, S_F.
- ``scuffing``        ISO/TS 6336-20 flash and ISO/TS 6336-21 integral temperature, S_B, S_intS.
- ``micropitting``    ISO/TS 6336-22 method B: h_Y, λ_GF along the path, λ_GFP, S_λ.
- ``suite``           the four ratings of a pair with validity flags and femgear's own figures (PairRating).
- ``summary``         a PairRating as plain dicts (``femgear info``, ``results.json``).
- ``power``           mesh power loss and efficiency along the path (μ × normal load × sliding speed).
The scene's ``[rating]`` table is bound by :mod:`femgear.rate` (driver level).
"""

from femgear.physics.rating.contact_stress import ContactStress, LoadFactors, contact_stress
from femgear.physics.rating.permissible import MaterialLimits, PittingRating, pitting_rating
from femgear.physics.rating.power import MeshPowerLoss, mesh_power_loss, ohlendorf_loss_factor

__all__ = ["ContactStress", "LoadFactors", "MaterialLimits", "MeshPowerLoss", "PittingRating", "contact_stress",
           "mesh_power_loss", "ohlendorf_loss_factor", "pitting_rating"]
