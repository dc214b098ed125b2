"""Thermal levels (the ``[physics] thermal`` key): the flank deviation from tooth growth.

The names are the registry; factories are attached where a level is dispatched.
"""

from femgear.levels.registry import Registry

REGISTRY = Registry("thermal")
REGISTRY.add("none", "no thermal growth")
REGISTRY.add("analytic", "free thermal expansion of the tooth from the bulk rise")
REGISTRY.add("fe", "2-D FE heat conduction and thermo-elasticity of the tooth section")
REGISTRY.add("fe3d", "3-D FE heat conduction and thermo-elasticity of the member bodies")
