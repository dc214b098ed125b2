"""Coupling levels (the ``[physics] coupling`` key).

The names are the registry; factories are attached where a level is dispatched.
"""

from femgear.levels.registry import Registry

REGISTRY = Registry("coupling")
REGISTRY.add("one-way", "one dynamic pass with the static sub-model results")
REGISTRY.add("bidirectional", "the outer loop iterated to convergence between dynamics and tribology")
