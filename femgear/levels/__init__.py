"""The levels layer, between the bound Case and the system: the factories of the catalogue's levels.

One :class:`~femgear.levels.registry.Registry` per sub-model maps each level name of the catalogue
(:mod:`femgear.scene.levels`, the one source of names and specs) to a factory ``(case, **options) ->
typed product``. The factories read the Case's typed parts (``case.pair``, ``case.path``,
``case.operating``, its tables) and call the physics leaves with arrays, numbers and typed objects;
the leaves never see a scene. :func:`check_case` runs the checks of the case's levels up front.
"""

from femgear.case import Case
from femgear.levels import coupling, dynamics, housing, lubrication, stiffness, thermal, wear
from femgear.levels.registry import Level, Registry

REGISTRIES: dict[str, Registry] = {
    m.REGISTRY.submodel: m.REGISTRY for m in (stiffness, lubrication, thermal, wear, dynamics, coupling)
}


def check_case(case: Case) -> None:
    """Refuse ``case`` before anything costly runs where one of its levels' checks does (a
    :class:`femgear.errors.SceneError` or :class:`femgear.errors.ResourceError` naming the key): the TEHL
    levels' speed envelope, the FE bodies' memory."""
    for sub, registry in REGISTRIES.items():
        registry.check(getattr(case.levels, sub), case)
    if case.housing is not None:
        housing.REGISTRY.check(case.housing.model, case)


__all__ = ["REGISTRIES", "Level", "Registry", "check_case"]
