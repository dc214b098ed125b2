"""Dynamics levels (the ``[physics] dynamics`` key).

The names are the registry; factories are attached where a level is dispatched.
"""

from femgear.levels.registry import Registry

REGISTRY = Registry("dynamics")
REGISTRY.add("none", "quasi-static: the sub-models run once at the static load")
REGISTRY.add("lumped", "the four helical halves tied rigidly per member on their bearings (12 rigid-member coordinates)")
REGISTRY.add("timoshenko", "helical halves and bearing stations joined by Timoshenko shaft elements (stations condensed)")
