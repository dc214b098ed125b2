"""The checks of a scene that need its bound gear pair, run once by :func:`femgear.case.build_case`.

The scene's own validation (schema, input ranges, temperatures) is :func:`femgear.scene.load_scene`;
what follows needs the pair and runs where the pair is bound: the tip speed against the rim's
burst speed (:func:`femgear.scene.plausibility.check_operating_limits`), an undercut member's warning, the face-resolved wear's
needs, the TEHL levels' ranges, the pitch-line speed warning; the Hertz pressure warning needs the
run's own contact pass (:func:`contact_warnings`, called by the driver after it).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from femgear.errors import SceneError
from femgear.levels import stiffness as stiffness_levels
from femgear.scene.plausibility import (
    check_operating_limits,
    log_warnings,
    pair_warnings,
    pressure_warnings,
    scene_warnings,
)
from femgear.scene.schema import Scene

if TYPE_CHECKING:
    from femgear.case import Case
    from femgear.physics.geometry import GearPair


def check_bound_case(case: Case, warn: bool = True) -> tuple[str, ...]:
    """Raise :class:`SceneError` for an operating point or a level the bound case cannot run; log the
    pair's plausibility warnings (``warn``) and return the plausibility warnings of the scene and the pair
    (``key: message``; the scene's were logged by :func:`femgear.scene.load_scene`)."""
    scene, pair = case.scene, case.pair
    check_operating_limits(scene, pair)
    check_wear_field(scene, pair)
    check_lubrication_range(case)
    from femgear.case.pair import undercut_warnings

    earlier = scene_warnings(scene)        # logged by load_scene (the input ranges' keys cannot collide with these)
    return tuple(earlier) + tuple(log_warnings(pair_warnings(scene, pair) + undercut_warnings(pair), earlier, warn))


def check_lubrication_range(case: Case) -> None:
    """Refuse the lubrication level up front outside its validated range (the checks its registry lists)."""
    from femgear.levels.lubrication import check_range

    check_range(case)


def check_wear_field(scene: Scene, pair: GearPair) -> None:
    """Raise :class:`SceneError` for ``wear.field = "face"`` without what the face-resolved wear reads: the
    ``ltca`` stiffness's contact-line loads, one contact line per helix at each path position (ε_β ≤ 1)."""
    if scene.wear.field != "face":
        return
    if not stiffness_levels.has_contact_lines(scene.physics.stiffness):
        raise SceneError("wear.field", f'"face" needs physics.stiffness = "ltca" (the face-resolved wear reads the '
                                       f"LTCA's contact-line loads; got {scene.physics.stiffness!r})")
    if pair.eps_beta > 1:
        raise SceneError("wear.field", f'"face" needs an overlap ratio ε_β ≤ 1 (one contact line per helix at each '
                                       f"path position); this pair has ε_β = {pair.eps_beta:.3f}")


def contact_warnings(case: Case, max_hertz_pressure: float, warn: bool = True) -> tuple[str, ...]:
    """Log the warning of a maximum Hertz pressure ``max_hertz_pressure`` [Pa] of the run's contact pass above
    the flank's contact strength, unless its key was warned already (:attr:`Case.warnings`); return it."""
    return tuple(log_warnings(pressure_warnings(max_hertz_pressure), case.warnings, warn))
