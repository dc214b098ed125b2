"""Mesh stiffness levels (the ``[physics] stiffness`` key).

The names are the registry; factories are attached where a level is dispatched.
"""

from femgear.levels.registry import Registry

REGISTRY = Registry("stiffness")
REGISTRY.add("constant", "one mesh stiffness per unit face width, constant in time (stiffness.mesh_stiffness_per_width)")
REGISTRY.add("iso6336", "ISO 6336-1 single-pair stiffness c' and mesh stiffness c_gamma, shared along the contact lines")
REGISTRY.add("pem", "potential-energy tooth compliance (Hertz, bending, shear, axial, foundation) sliced along the face")
REGISTRY.add("fe", "2-D finite-element tooth sections (plane strain) sliced along the face")
REGISTRY.add("ltca", "loaded tooth contact analysis on 3-D FE member bodies with flank modifications")
