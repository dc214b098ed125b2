"""Time-varying mesh stiffness of a (double-)helical pair, cheapest level first.

- ``iso6336``  ISO 6336-1:2019 c', c_γα, c_γβ (Method B), constant per helix.
- ``pem``      potential energy method per transverse slice (Hertz, bending, shear,
               axial, Sainsot fillet foundation over the generated tooth outline).
- ``tvms``     slicing along the face width, left/right stagger, :class:`MeshStiffness`
               (the periodic stiffness the dynamics model consumes) and
               :func:`mesh_stiffness` for every level (``fe`` uses :mod:`femgear.physics.body`).
"""

from femgear.physics.stiffness.iso6336 import IsoStiffness, iso6336_stiffness
from femgear.physics.stiffness.tvms import MeshStiffness, helix_stiffness, mesh_stiffness, mesh_stiffness_from_scene

__all__ = ["IsoStiffness", "MeshStiffness", "helix_stiffness", "iso6336_stiffness", "mesh_stiffness",
           "mesh_stiffness_from_scene"]
