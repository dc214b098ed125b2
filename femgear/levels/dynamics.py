"""Dynamics levels (the ``[physics] dynamics`` key).

Each level's factory returns its catalogue spec (:class:`femgear.scene.levels.DynamicsLevel`), the
attributes the driver and the model builder read instead of comparing level names: whether the run is
dynamic at all (``none`` is quasi-static) and whether the helix halves are joined by shaft elements
(``timoshenko``) or tied rigidly per member (``lumped``).
"""

from __future__ import annotations

from femgear.levels.registry import Registry
from femgear.scene.levels import DynamicsLevel

REGISTRY = Registry("dynamics")
REGISTRY.register_specs()


def model_level(name: str | None, default: str) -> DynamicsLevel:
    """The rotor model's level: ``name`` if given, else ``default`` (``physics.dynamics``) when that is a
    dynamic level, else the cheapest dynamic level (a quasi-static case asking for a model gets the cheapest
    one, ``lumped``)."""
    if name is not None:
        return REGISTRY.catalogue.spec(name)
    chosen = REGISTRY.catalogue.spec(default)
    return chosen if chosen.is_dynamic else next(s for s in REGISTRY.catalogue.levels if s.is_dynamic)
