"""The gear pair of a scene (the binding of ``[pair]``, ``[pinion]``, ``[gear]``): kind, basic rack,
face widths, tip diameters and centre distance.

:func:`pair_from_scene` is called once per run, by :func:`femgear.case.build_case`; everything
below the case takes the bound :class:`femgear.physics.geometry.GearPair`.  Every inconsistency is a :class:`SceneError` naming the scene key at fault, so that the
CLI prints one line:

- ``pair.kind = "spur"`` needs ``helix_angle_deg = 0``; the helical kinds need β > 0;
- ``pair.kind = "single-helical"`` needs ``pinion/gear.axial_stiffness`` (its axial mesh
  force F_a = F_t tan β_w is carried by the thrust bearings; a double-helical pair
  balances it between its two helices, a spur pair has none);
- a single-helical or spur pair has one helix: ``pair.stagger`` and
  ``modifications.helix_slope_deviation_right`` must be 0 (the left helix's key is its slope deviation);
- ``pair.basic_rack`` (ISO 53 A–D) sets h_aP, h_fP, ρ_fP; a coefficient given beside it
  must agree with it;
- ``pinion/gear.tip_diameter`` is the tip as made (the tip circle of every level); it derives the
  profile shift where none is given (d_a = d + 2 m_n (h_aP + x + k), ISO 21771 §5.4, with the tip
  alteration k of the centre distance), else it must lie between the shift's shortened and full tips
  d + 2 m_n (h_aP + x + k) … d + 2 m_n (h_aP + x) within ``pair.tip_diameter_tolerance`` (a drawing's
  ±0.1 mm by default; the FZG A pinion's 88.77 mm is 0.09 mm above its full tip);
- an undercut member (x below the rack's x_min) is a warning with its amount
  (:func:`undercut_warnings`), refused only where its involute begins above the start of the active
  profile (:func:`check_active_profile`);
- ``pair.centre_distance`` fixes x1 + x2 by inv α_wt = inv α_t + 2 tan α_n (x1 + x2)/(z1 + z2)
  and is checked against given shifts (to 1e-3 in x1 + x2, about 1e-3 m_n on a_w).
"""

from __future__ import annotations

import math
from dataclasses import replace

from femgear.errors import SceneError
from femgear.physics.geometry.gear import GearPair
from femgear.physics.geometry.involute import inv

#: ISO 53:1998 basic-rack profiles: (h_aP, h_fP, ρ_fP) / m_n, α_P = 20°
BASIC_RACKS = {"A": (1.0, 1.25, 0.38), "B": (1.0, 1.25, 0.30), "C": (1.0, 1.25, 0.25), "D": (1.0, 1.40, 0.39)}
_MEMBERS = ("pinion", "gear")
SHIFT_TOLERANCE = 1e-3    #: x1 + x2 mismatch allowed against the centre distance
#: a given tip diameter this close to the shift's own (shortened) tip is that tip [m]: the round-off of a file
#: that wrote it (REXS, 4 decimals in mm), not a drawing's choice, so the pair stays the one it was written from
TIP_ROUND_OFF = 1e-7


def _check_kind(scene) -> None:
    p = scene.pair
    if p.kind == "spur" and p.helix_angle_deg != 0:
        raise SceneError("pair.helix_angle_deg",
                         f"a spur pair has no helix: set 0, or set pair.kind to 'single-helical' or "
                         f"'double-helical' (got {p.helix_angle_deg:g}°)")
    if p.kind != "spur" and p.helix_angle_deg <= 0:
        raise SceneError("pair.helix_angle_deg",
                         f"a {p.kind} pair needs a helix angle > 0 (for straight teeth set pair.kind = 'spur')")
    if p.kind == "single-helical":
        for name in _MEMBERS:
            if getattr(scene, name).axial_stiffness is None:
                raise SceneError(f"{name}.axial_stiffness",
                                 "a single-helical pair needs the axial (thrust) bearing stiffness of each member: "
                                 "its axial mesh force is not balanced by a second helix")
    if p.kind != "double-helical":
        _check_one_helix(scene)


def _check_one_helix(scene) -> None:
    """A single-helical or spur pair has one helix: no stagger of a second one, no second helix's slope deviation
    (the left helix's keys describe the one helix)."""
    kind = scene.pair.kind
    if scene.pair.stagger != 0:
        raise SceneError("pair.stagger", f"a {kind} pair has one helix: no second helix to stagger (got "
                                         f"{scene.pair.stagger:g}; set 0)")
    if scene.modifications.helix_slope_deviation_right != 0:
        raise SceneError("modifications.helix_slope_deviation_right",
                         f"a {kind} pair has one helix: give its helix slope deviation as "
                         "modifications.helix_slope_deviation_left")


def rack_coefficients(pair_table) -> tuple[float, float, float]:
    """(h_aP, h_fP, ρ_fP) of ``[pair]``: the ISO 53 preset if named, checked against given coefficients."""
    given = (pair_table.addendum_coeff, pair_table.dedendum_coeff, pair_table.root_radius_coeff)
    if pair_table.basic_rack is None:
        return given
    preset = BASIC_RACKS[pair_table.basic_rack]
    keys = ("addendum_coeff", "dedendum_coeff", "root_radius_coeff")
    for key, value, ref in zip(keys, given, preset, strict=True):
        if key in pair_table.model_fields_set and abs(value - ref) > 1e-12:
            raise SceneError(f"pair.{key}", f"{value:g} contradicts pair.basic_rack = {pair_table.basic_rack!r} "
                                            f"({ref:g}); give one of them")
    if "normal_pressure_angle_deg" in pair_table.model_fields_set and pair_table.normal_pressure_angle_deg != 20:
        raise SceneError("pair.normal_pressure_angle_deg", f"ISO 53 racks have α_n = 20° (pair.basic_rack = "
                                                           f"{pair_table.basic_rack!r})")
    return preset


def shift_sum_of_centre_distance(base, a_w: float) -> float:
    """x1 + x2 giving the working centre distance a_w (ISO 21771 eq. for inv α_wt)."""
    cos_wt = base.a * math.cos(base.alpha_t) / a_w
    if not 0 < cos_wt < 1:
        raise SceneError("pair.centre_distance", f"a_w = {a_w * 1e3:.4f} mm is impossible for this pair "
                                                  f"(reference centre distance {base.a * 1e3:.4f} mm)")
    return (inv(math.acos(cos_wt)) - inv(base.alpha_t)) * (base.z1 + base.z2) / (2 * math.tan(base.alpha_n))


def _shift_from_tip(pair, member: int, d_a: float) -> float:
    r = pair.r1 if member == 1 else pair.r2
    return (d_a / 2 - r) / pair.m_n - pair.h_aP - pair.k_tip


def _with(pair, **kw):
    return replace(pair, **kw)


def _resolve_shifts(scene, pair):
    """Apply tip diameters and centre distance to ``pair`` (built with the given shifts)."""
    members = [getattr(scene, n) for n in _MEMBERS]
    given = [("profile_shift" in m.model_fields_set) for m in members]
    a_w = scene.pair.centre_distance
    if a_w is not None:
        total = shift_sum_of_centre_distance(pair, a_w)
        if all(given):
            if abs(pair.x1 + pair.x2 - total) > SHIFT_TOLERANCE:
                raise SceneError("pair.centre_distance",
                                 f"a_w = {a_w * 1e3:.4f} mm needs x1 + x2 = {total:.4f}, the profile shifts give "
                                 f"{pair.x1 + pair.x2:.4f} (a_w = {pair.a_w * 1e3:.4f} mm)")
        elif given[0] or given[1]:
            pair = _with(pair, x2=total - pair.x1) if given[0] else _with(pair, x1=total - pair.x2)
        elif members[0].tip_diameter is None and members[1].tip_diameter is None:
            raise SceneError("pinion.profile_shift", "pair.centre_distance fixes only x1 + x2: give "
                                                     "pinion.profile_shift or the tip diameters")
        else:
            pair = _with(pair, x1=total / 2, x2=total / 2)
    for _ in range(50):  # fixed point: the tip alteration k depends on x1 + x2 (without a_w)
        before = (pair.x1, pair.x2)
        for i, m in enumerate(members):
            if m.tip_diameter is not None and not given[i]:
                x = _shift_from_tip(pair, i + 1, m.tip_diameter)
                pair = _with(pair, **{f"x{i + 1}": x})
                if a_w is not None:  # the other shift follows from the sum
                    j = 2 - i
                    if not given[1 - i] and members[1 - i].tip_diameter is None:
                        pair = _with(pair, **{f"x{j}": total - x})
        if max(abs(pair.x1 - before[0]), abs(pair.x2 - before[1])) < 1e-12:
            break
    if a_w is not None and abs(pair.x1 + pair.x2 - total) > SHIFT_TOLERANCE:
        raise SceneError("pair.centre_distance",
                         f"a_w = {a_w * 1e3:.4f} mm needs x1 + x2 = {total:.4f}; the tip diameters give "
                         f"{pair.x1 + pair.x2:.4f}")
    tips = {}
    for i, m in enumerate(members):
        if m.tip_diameter is not None:
            _check_tip(pair, i + 1, m.tip_diameter, scene.pair.tip_diameter_tolerance)
            if abs(m.tip_diameter - 2 * pair.standard_tip_radius(i + 1)) > TIP_ROUND_OFF:
                tips[f"tip_radius{i + 1}"] = m.tip_diameter / 2
    return _with(pair, **tips)


def _check_tip(pair, member: int, d_a: float, tolerance: float) -> None:
    """A drawing's tip diameter lies between the shortened and the full tip of its profile shift, within
    ``tolerance`` [m] (:class:`SceneError` naming the tip diameter, with what the shift gives)."""
    short, full = (2 * pair.standard_tip_radius(member, shortened) for shortened in (True, False))
    lo, hi = min(short, full), max(short, full)
    if lo - tolerance <= d_a <= hi + tolerance:
        return
    name = _MEMBERS[member - 1]
    x = pair.x1 if member == 1 else pair.x2
    raise SceneError(
        f"{name}.tip_diameter",
        f"d_a = {d_a * 1e3:.4f} mm does not match profile shift x = {x:.4f}: the rack and the shift give "
        f"d + 2 m_n (h_aP + x) = {full * 1e3:.4f} mm, or {short * 1e3:.4f} mm with ISO 21771's tip shortening "
        f"k m_n = {pair.k_tip * pair.m_n * 1e3:.4f} mm (k = (a_w − a)/m_n − (x1 + x2): the tips are turned down by "
        f"that much so that the tip clearance stays c = (h_fP − h_aP) m_n at the working centre distance); a "
        f"drawing's tip lies between the two within pair.tip_diameter_tolerance = {tolerance * 1e3:g} mm: correct "
        f"{name}.profile_shift or {name}.tip_diameter, or widen the tolerance")


def check_active_profile(pair: GearPair) -> None:
    """Refuse (naming ``*.profile_shift``) an undercut so deep that the involute no longer reaches down to the
    start of the active profile: the mating tip would run on the undercut fillet (interference)."""
    from femgear.physics.geometry.profile import tooth_profile

    for member, name in ((1, "pinion"), (2, "gear")):
        if pair.undercut_margin(member) >= 0:
            continue
        r_form, r_sap = tooth_profile(pair, member).r_form, pair.active_root_radius(member)
        if r_form > r_sap:
            raise SceneError(
                f"{name}.profile_shift",
                f"the {name} is undercut so deep (x − x_min = {pair.undercut_margin(member):.3f}) that its involute "
                f"begins at d = {2 * r_form * 1e3:.3f} mm, above the start of the active profile at "
                f"d = {2 * r_sap * 1e3:.3f} mm: the mating tip would run on the undercut fillet; raise "
                f"{name}.profile_shift or {name}.teeth, or lower the mate's tip")


def undercut_warnings(pair: GearPair) -> list[str]:
    """``key: message`` of each undercut member (its amount, and where its involute begins against the start of
    its active profile), not logged."""
    from femgear.physics.geometry.profile import tooth_profile

    out = []
    for member, name in ((1, "pinion"), (2, "gear")):
        margin = pair.undercut_margin(member)
        if margin >= 0:
            continue
        r_form, r_sap = tooth_profile(pair, member).r_form, pair.active_root_radius(member)
        out.append(f"{name}.profile_shift: the {name} is undercut by the generating rack (x − x_min = {margin:.3f}): "
                   f"its involute begins at d = {2 * r_form * 1e3:.3f} mm, "
                   f"{(r_sap - r_form) * 2e3:.3f} mm below the start of its active profile "
                   f"(d = {2 * r_sap * 1e3:.3f} mm), so the contact stays on the involute; the root is thinner")
    return out


def pair_from_scene(scene) -> GearPair:
    """The checked gear pair of a validated scene (:class:`SceneError` naming the key for an impossible one)."""
    _check_kind(scene)
    p = scene.pair
    h_aP, h_fP, rho_fP = rack_coefficients(p)
    widths = [getattr(scene, n).face_width or p.face_width for n in _MEMBERS]
    pair = GearPair(
        z1=scene.pinion.teeth, z2=scene.gear.teeth, m_n=p.normal_module,
        alpha_n=math.radians(p.normal_pressure_angle_deg), beta=math.radians(p.helix_angle_deg),
        b=min(widths), x1=scene.pinion.profile_shift, x2=scene.gear.profile_shift,
        h_aP=h_aP, h_fP=h_fP, rho_fP=rho_fP, kind=p.kind,
    )
    pair = _resolve_shifts(scene, pair)
    pair.check()
    check_active_profile(pair)
    return pair
