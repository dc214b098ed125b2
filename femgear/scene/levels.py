"""Fidelity levels per sub-model, cheapest first, and which of them exist today.

A scene's ``[physics]`` table names one level per sub-model.  Levels listed in
:data:`LEVELS` but not in :data:`AVAILABLE` are part of the design and rejected with a
"not available yet" message; anything else is an unknown level.  When a sub-model's
level lands, add it to :data:`AVAILABLE` (one edit, here).
"""

from __future__ import annotations

LEVELS: dict[str, tuple[str, ...]] = {
    "stiffness": ("constant", "iso6336", "pem", "fe", "ltca"),
    "lubrication": ("none", "constant", "formula", "ehl-line", "ehl-point", "tehl", "tehl-point"),
    "thermal": ("none", "analytic", "fe", "fe3d"),
    "wear": ("none", "archard"),
    "dynamics": ("none", "lumped", "timoshenko"),
    "coupling": ("one-way", "bidirectional"),
}

AVAILABLE: dict[str, frozenset[str]] = {
    "stiffness": frozenset({"constant", "iso6336", "pem", "fe", "ltca"}),
    "lubrication": frozenset({"none", "constant", "formula", "ehl-line", "tehl", "tehl-point"}),
    "thermal": frozenset({"none", "analytic", "fe", "fe3d"}),
    "wear": frozenset({"none", "archard"}),
    "dynamics": frozenset({"none", "lumped", "timoshenko"}),
    "coupling": frozenset({"one-way", "bidirectional"}),
}


def check_level(submodel: str, level: str) -> str | None:
    """Return an error message for ``physics.<submodel> = level``, or None if it is usable."""
    known = LEVELS[submodel]
    if level not in known:
        return f"unknown level {level!r}; choose one of {', '.join(known)}"
    if level not in AVAILABLE[submodel]:
        have = ", ".join(lv for lv in known if lv in AVAILABLE[submodel])
        return f"level {level!r} is not available yet (available now: {have})"
    return None
