"""Level names offered by the CLI's options, read from the one source of level names.

Every option that takes a fidelity level (``femgear dynamics --level``, ``--stiffness``) takes
its choices from :func:`level_choices`, so the help and the accepted values follow the levels a
scene accepts.  Only this function reads the level table: when the table moves, re-point it here.
"""

from __future__ import annotations


def level_choices(submodel: str, exclude: tuple[str, ...] = ()) -> tuple[str, ...]:
    """The usable levels of ``submodel`` (``physics.<submodel>``), cheapest first, less ``exclude``."""
    from femgear.scene.levels import AVAILABLE, LEVELS

    return tuple(lv for lv in LEVELS[submodel] if lv in AVAILABLE[submodel] and lv not in exclude)


__all__ = ["level_choices"]
