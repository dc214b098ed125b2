"""The levels layer, between the bound Case and the physics leaves.

One :class:`~femgear.levels.registry.Registry` per sub-model maps each level name to a
factory ``(case, **options) -> typed product``. The factories read the Case's typed
parts (``case.pair``, ``case.path``, ``case.operating``, its tables) and call the
physics leaves with arrays, numbers and typed objects; the leaves never see a scene.
The registries are the one source of level names (scene schema, CLI, docs).
"""

from femgear.levels import coupling, dynamics, lubrication, stiffness, thermal, wear
from femgear.levels.registry import Level, Registry

REGISTRIES: dict[str, Registry] = {
    m.REGISTRY.submodel: m.REGISTRY for m in (stiffness, lubrication, thermal, wear, dynamics, coupling)
}

__all__ = ["REGISTRIES", "Level", "Registry"]
