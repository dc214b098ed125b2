"""Coupling levels (the ``[physics] coupling`` key).

Each level's factory returns its catalogue spec (:class:`femgear.scene.levels.CouplingLevel`): whether
the outer loop between dynamics and tribology iterates to convergence or stops after the first dynamic
pass.
"""

from __future__ import annotations

from femgear.levels.registry import Registry

REGISTRY = Registry("coupling")
REGISTRY.register_specs()
