"""Fidelity levels per sub-model, read from the registries of :mod:`femgear.levels`.

A scene's ``[physics]`` table names one level per sub-model. Names a registry lists as
``planned`` are part of the design and rejected with a "not available yet" message;
anything else unregistered is an unknown level. A new level is one registration in its
sub-model's registry (``femgear/levels/<submodel>.py``).
"""

from __future__ import annotations

from femgear.levels import REGISTRIES

#: every name of the design per sub-model, cheapest first (registered, then planned)
LEVELS: dict[str, tuple[str, ...]] = {sub: reg.names() + reg.planned for sub, reg in REGISTRIES.items()}
#: the levels that run today
AVAILABLE: dict[str, frozenset[str]] = {sub: frozenset(reg.names()) for sub, reg in REGISTRIES.items()}


def check_level(submodel: str, level: str) -> str | None:
    """Return an error message for ``physics.<submodel> = level``, or None if it is usable."""
    return REGISTRIES[submodel].problem(level)
