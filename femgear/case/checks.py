"""The checks of a scene that need its bound gear pair, run once by :func:`femgear.case.build_case`.

The scene's own validation (schema, input ranges, temperatures) is :func:`femgear.scene.load_scene`;
what follows needs the pair and runs where the pair is bound: the tip speed against the rim's
burst speed (:func:`femgear.scene.plausibility.check_operating_limits`), a rim below 0.5 h_t, the bearings
outside the teeth (:func:`check_supports`), the face-resolved wear's needs, the flank modifications' lengths
against the flanks, an undercut member's warning, the pitch-line speed warning (the levels' own checks,
the TEHL levels' ranges and the FE bodies' memory, are :func:`femgear.levels.check_case`'s); the Hertz pressure warning needs the
run's own contact pass (:func:`contact_warnings`, called by the driver after it).
"""

from __future__ import annotations

import math
from typing import Protocol

from femgear.case.pair import undercut_warnings
from femgear.errors import SceneError
from femgear.physics.geometry import GearPair
from femgear.scene.plausibility import (
    check_operating_limits,
    log_warnings,
    pair_warnings,
    pressure_warnings,
    scene_warnings,
)
from femgear.scene.schema import Modifications, Scene


class Case(Protocol):
    """What these checks read of a :class:`femgear.case.Case` (built by that package's ``__init__``, which
    imports this module: the checks name its parts, not the class)."""

    @property
    def scene(self) -> Scene: ...

    @property
    def pair(self) -> GearPair: ...

    @property
    def modifications(self) -> Modifications: ...

    @property
    def warnings(self) -> tuple[str, ...]: ...


def check_bound_case(case: Case, warn: bool = True) -> tuple[str, ...]:
    """Raise :class:`SceneError` for an operating point or a level the bound case cannot run; log the
    pair's plausibility warnings (``warn``) and return the plausibility warnings of the scene and the pair
    (``key: message``; the scene's were logged by :func:`femgear.scene.load_scene`)."""
    scene, pair = case.scene, case.pair
    check_operating_limits(scene, pair)
    check_rims(scene, pair)
    check_supports(scene)
    check_wear_field(scene, pair)
    check_modifications(case)
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


def toothed_width(scene: Scene, member: str) -> float:
    """Axial length of ``member``'s teeth [m]: its face width (``<member>.face_width``, else ``pair.face_width``),
    twice it plus the groove for a double-helical pair."""
    p = scene.pair
    b = getattr(scene, member).face_width or p.face_width
    return 2 * b + p.groove_width if p.kind == "double-helical" else b


def bearing_stations(member: str, span: float, offset: float, width: float) -> tuple[float, float]:
    """(z_L, z_R) of ``member``'s two radial bearings in its frame, the toothed face centred at 0 [m]:
    −offset ∓ span/2 (``<member>.bearing_span``, ``<member>.face_offset``; ``width`` the toothed width).

    :class:`SceneError` naming ``<member>.bearing_span`` for a shaft between the bearings not longer than the
    teeth, ``<member>.face_offset`` for a bearing under the toothed face (|z| < width/2): the face sits between
    the bearings (straddle, |offset| ≤ (span − width)/2) or beyond one of them (overhung,
    |offset| ≥ (span + width)/2)."""
    if not (math.isfinite(span) and span > width):
        raise SceneError(f"{member}.bearing_span", f"the shaft between the bearings ({span:.4g} m) must be longer than "
                                                   f"the toothed face ({width:.4g} m)")
    if not math.isfinite(offset):
        raise SceneError(f"{member}.face_offset", f"must be finite (got {offset!r})")
    z = (-offset - span / 2, -offset + span / 2)
    for side, zj in zip(("left", "right"), z):
        if abs(zj) < width / 2 * (1 - 1e-12):
            raise SceneError(f"{member}.face_offset",
                             f"{offset:.4g} m puts the {side} bearing under the teeth (z = {zj:.4g} m from the face "
                             f"centre; the teeth span ±{width / 2:.4g} m): a straddle mounting needs |face_offset| ≤ "
                             f"{(span - width) / 2:.4g} m, an overhung one ≥ {(span + width) / 2:.4g} m")
    return z


def check_supports(scene: Scene) -> None:
    """Refuse a mounting whose bearings sit under the teeth (:func:`bearing_stations`), whatever the levels."""
    for member in ("pinion", "gear"):
        m = getattr(scene, member)
        bearing_stations(member, m.bearing_span, m.face_offset, toothed_width(scene, member))


def check_modifications(case: Case) -> None:
    """Raise :class:`SceneError` for a relief longer than the active profile or half the helix's face (the
    ``ltca`` level reads the flank modifications only once its member bodies are built, minutes later)."""
    from femgear.physics.ltca.separation import check_modification

    for member in (1, 2):
        check_modification(case.pair, member, case.modifications.member(member))


def check_wear_field(scene: Scene, pair: GearPair) -> None:
    """Raise :class:`SceneError` for ``wear.field = "face"`` without what the face-resolved wear reads: the
    ``ltca`` stiffness's contact-line loads, one contact line per helix at each path position (ε_β ≤ 1)."""
    if scene.wear.field != "face":
        return
    if not scene.physics.spec("stiffness").contact_lines:
        raise SceneError("wear.field", f'"face" needs physics.stiffness = "ltca" (the face-resolved wear reads the '
                                       f"LTCA's contact-line loads; got {scene.physics.stiffness!r})")
    if pair.beta_b == 0:
        raise SceneError("wear.field", '"face" needs a helical pair: a spur contact line lies at one path position '
                                       "(its load map is the Winkler sharing of the path model)")
    if pair.eps_beta > 1:
        raise SceneError("wear.field", f'"face" needs an overlap ratio ε_β ≤ 1 (one contact line per helix at each '
                                       f"path position); this pair has ε_β = {pair.eps_beta:.3f}")


def contact_warnings(case: Case, max_hertz_pressure: float, warn: bool = True) -> tuple[str, ...]:
    """Log the warning of a maximum Hertz pressure ``max_hertz_pressure`` [Pa] of the run's contact pass above
    the flank's contact strength, unless its key was warned already (:attr:`Case.warnings`); return it."""
    return tuple(log_warnings(pressure_warnings(max_hertz_pressure), case.warnings, warn))
