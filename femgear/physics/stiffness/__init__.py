"""Time-varying mesh stiffness of a (double-)helical pair, cheapest level first.

- ``iso6336``  ISO 6336-1:2019 c', c_γα, c_γβ (Method B), constant per helix.
- ``pem``      potential energy method per transverse slice (Hertz, bending, shear,
               axial, Sainsot fillet foundation over the generated tooth outline).
- ``tvms``     k'(u) integrated over every contact line of the face, left/right stagger,
               :class:`MeshStiffness` (the periodic stiffness the dynamics model consumes): a uniform
               table (:func:`uniform_mesh_stiffness`) or one from k'(u) (:func:`integrated_mesh_stiffness`).

The levels (``constant``, ``iso6336``, ``pem``, ``fe``, ``ltca``) are the factories of
:mod:`femgear.levels.stiffness` (the registry, for a case); a bare pair calls the physics
(:func:`~femgear.physics.stiffness.pem.pem_mesh_stiffness`, :func:`uniform_mesh_stiffness`).
"""

from femgear.physics.stiffness.iso6336 import IsoStiffness, iso6336_stiffness
from femgear.physics.stiffness.tvms import (
    MeshStiffness,
    helix_stiffness,
    integrated_mesh_stiffness,
    uniform_mesh_stiffness,
)

__all__ = ["IsoStiffness", "MeshStiffness", "helix_stiffness", "iso6336_stiffness", "integrated_mesh_stiffness",
           "uniform_mesh_stiffness"]
