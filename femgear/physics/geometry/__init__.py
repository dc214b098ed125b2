"""Involute gear-pair geometry and kinematics: spur, single- and double-helical (pure numpy, SI units).

- ``involute``    the involute function and its inverse.
- ``gear``        dimensions, contact ratios and feasibility checks (ISO 21771); ``GearPair.kind``.
- ``kinematics``  radii of curvature and velocities along the path of contact,
                  contact lines of each helix, mesh frequency.
"""

from femgear.physics.geometry.gear import GearPair, inv, inv_inverse
from femgear.physics.geometry.kinematics import (
    ContactLines,
    PathKinematics,
    contact_lines,
    double_helical_contact,
    kinematics,
    mesh_frequency,
    path_positions,
)

__all__ = [
    "ContactLines", "GearPair", "PathKinematics", "contact_lines", "double_helical_contact",
    "inv", "inv_inverse", "kinematics", "mesh_frequency", "path_positions",
]
