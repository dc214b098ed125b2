"""Wear levels (the ``[physics] wear`` key).

The names are the registry; factories are attached where a level is dispatched.
"""

from femgear.levels.registry import Registry

REGISTRY = Registry("wear")
REGISTRY.add("none", "no wear")
REGISTRY.add("archard", "Archard wear along the path (or over the face) with the load updated as the profile wears")
