"""The checks of a scene that need its bound gear pair, run once by :func:`femgear.case.build_case`.

The scene's own validation (schema, input ranges, temperatures) is :func:`femgear.scene.load_scene`;
what follows needs the pair and runs where the pair is bound: the tip speed against the rim's
burst speed (:func:`femgear.scene.plausibility.check_operating_limits`), a rim below 0.5 h_t, an undercut
member's warning, the face-resolved wear's
needs, the TEHL levels' ranges, the pitch-line speed warning; the Hertz pressure warning needs the
run's own contact pass (:func:`contact_warnings`, called by the driver after it).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from femgear.case.pair import undercut_warnings
from femgear.errors import SceneError
from femgear.levels import stiffness as stiffness_levels
from femgear.levels import thermal as thermal_levels
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
    check_rims(scene, pair)
    check_wear_field(scene, pair)
    check_lubrication_range(case)
    check_fe_resources(case)
    earlier = scene_warnings(scene)        # logged by load_scene (the input ranges' keys cannot collide with these)
    return tuple(earlier) + tuple(log_warnings(pair_warnings(scene, pair) + undercut_warnings(pair), earlier, warn))


def check_rims(scene: Scene, pair: GearPair) -> None:
    """Raise :class:`SceneError` naming ``pinion/gear.bore_radius`` for a rim thinner than ISO 6336-3's lower
    limit 0.5 h_t below the root circle (the message gives the thinnest rim that runs)."""
    from femgear.physics.mesh.section import check_rim

    for member, name in ((1, "pinion"), (2, "gear")):
        bore = getattr(scene, name).bore_radius
        if bore > 0:
            try:
                check_rim(pair, member, bore)
            except ValueError as exc:
                raise SceneError(f"{name}.bore_radius", str(exc).removeprefix("bore_radius=")) from None


def check_fe_resources(case: Case) -> None:
    """Refuse up front the FE bodies of the case's levels whose memory estimate exceeds the budget (the level's
    own check, which names the resolution that fits; the stages check again as they start)."""
    stiffness_levels.check_resources(case)
    thermal_levels.check_resources(case)


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
