"""One REXS cylindrical stage → a femgear scene dictionary, every value with its REXS source.

:func:`convert` returns a :class:`Conversion`: the raw scene (validated later by
:func:`femgear.scene.scene_from_dict`), the REXS component and attribute behind each scene key, and
the keys the model did not provide (with the value used and why).  Values that appear on several
components (the module of both gears, the profile shift of both flanks of both halves, ...) must
agree, else the error names both.  The pair geometry is mapped here; material, oil, operating
point and modifications in :mod:`femgear.rexs.tables`.

Readings (ISO 21771 terms):

- the pinion is the stage's ``gear_1``; the hand is the sign of ``helix_angle_reference_diameter``
  (a mating external pair is +β/−β);
- ``pair.face_width`` is the smaller member face width (the contact width), a member's own width
  is kept where it differs;
- double-helical: the groove is |u_A − u_B| − b between the halves' ``u_coordinate_on_shaft``
  (taken as the middle of each half's face);
- ``pair.backlash`` is half the stage's total normal backlash j_bn (the mean of its minimum and
  maximum); a backlash not in the model is half the recommended minimum of ISO/TR 10064-2,
  j_bn,min = 2/3 (0.06 mm + 0.0005 a + 0.03 m_n);
- the dedendum h_fP/m_n comes from the rack-shaped tool (its addendum h_aP0*), else from the root
  diameter, d_f = d − 2 m_n (h_fP − x); the root radius ρ_fP/m_n is the tool's tip radius factor.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

from femgear.rexs.lookup import flanks_of, tools_of
from femgear.rexs.model import Component, Model
from femgear.rexs.stages import PairParts

MEMBERS = ("pinion", "gear")
TIP_TOLERANCE = 2e-3    #: diameter mismatch allowed between REXS values, in units of m_n (as the scene's)

Source = tuple[Component, str]


@dataclass
class Conversion:
    """The scene dictionary of one stage and where each value came from."""

    model: Model
    stage: Component
    parts: PairParts
    data: dict[str, Any] = field(default_factory=dict)
    sources: dict[str, list[Source]] = field(default_factory=dict)
    defaults: dict[str, str] = field(default_factory=dict)    #: key -> why this value (not in the model)
    unused: list[str] = field(default_factory=list)           #: what the model holds and femgear does not use
    overridden: set[str] = field(default_factory=set)         #: keys set by --set instead of the model

    # ---- recording
    def put(self, key: str, value: Any, sources: list[Source] | tuple = ()) -> None:
        table, _, leaf = key.rpartition(".")
        node = self.data
        for part in table.split("."):
            node = node.setdefault(part, {})
        node[leaf] = value
        self.sources[key] = list(sources)

    def default(self, key: str, value: Any, why: str) -> None:
        self.put(key, value)
        self.defaults[key] = why

    def drop(self, key: str) -> None:
        """Forget ``key`` (its value, sources and default), if it was recorded."""
        table, _, leaf = key.rpartition(".")
        node: Any = self.data
        for part in table.split("."):
            node = node.get(part) if isinstance(node, dict) else None
        if isinstance(node, dict):
            node.pop(leaf, None)
        self.sources.pop(key, None)
        self.defaults.pop(key, None)

    def get(self, key: str) -> Any:
        node: Any = self.data
        for part in key.split("."):
            if not isinstance(node, dict) or part not in node:
                return None
            node = node[part]
        return node

    # ---- reading
    def agree(self, comps: list[Component] | tuple, attr: str, why: str, *, required: bool = False,
              rel: float = 1e-9, absolute: bool = False) -> tuple[Any, list[Source]]:
        """The value of ``attr`` on every component that has it; they must agree (``rel``).

        ``absolute``: compare magnitudes (the helix angle of both hands).  Returns (None, []) when no
        component has it, unless ``required``.
        """
        found = [(c, self.model.value(c, attr)) for c in comps]
        found = [(c, v) for c, v in found if v is not None]
        if not found:
            if required and comps:
                raise self.model.error(comps[0], attr, f"missing: femgear needs {why}")
            return None, []
        first, v0 = found[0]
        for comp, v in found[1:]:
            a, b = (abs(v0), abs(v)) if absolute else (v0, v)
            same = a == b if not isinstance(a, float) else abs(a - b) <= rel * max(abs(a), abs(b))
            if not same:
                raise self.model.error(comp, attr, f"{v!r} differs from {v0!r} on {first.label()}: femgear has one "
                                                   f"value for {why}")
        return v0, [(c, attr) for c, _ in found]


def _flanks(model: Model, gears) -> list[Component]:
    return [f for g in gears for f in flanks_of(model, g)]


def pair_geometry(conv: Conversion) -> None:
    """``[pair]`` and the geometry keys of ``[pinion]``/``[gear]``."""
    model, parts = conv.model, conv.parts
    gears = parts.members[0] + parts.members[1]
    m_n, src = conv.agree(gears, "normal_module", "the normal module of the pair", required=True)
    if m_n <= 0:
        raise model.error(gears[0], "normal_module", f"must be positive (got {m_n * 1e3:g} mm)")
    conv.put("pair.kind", parts.kind, [(g, "helix_angle_reference_diameter") for g in gears])
    conv.put("pair.normal_module", m_n, src)
    _helix(conv, parts)
    widths = []
    for name, halves in zip(MEMBERS, parts.members, strict=True):
        z, src = conv.agree(halves, "number_of_teeth", f"the tooth count of the {name}", required=True)
        if z <= 0:
            raise model.error(halves[0], "number_of_teeth", f"must be positive (got {z}): an internal gear? femgear "
                                                            "models external pairs")
        conv.put(f"{name}.teeth", z, src)
        b, src = conv.agree(halves, "face_width", f"the face width of both {name} halves", required=True)
        widths.append((b, src))
        d_a, src = conv.agree(halves, "tip_diameter", f"the tip diameter of the {name}")
        if d_a is not None:
            conv.put(f"{name}.tip_diameter", d_a, src)
        inner, src = conv.agree(halves, "inner_diameter", f"the bore of the {name}")
        if inner is not None:
            conv.put(f"{name}.bore_radius", inner / 2, src)
    b_min = min(b for b, _ in widths)
    conv.put("pair.face_width", b_min, [s for b, src in widths if b == b_min for s in src])
    for name, (b, src) in zip(MEMBERS, widths, strict=True):
        if b != b_min:
            conv.put(f"{name}.face_width", b, src)
    if parts.kind == "double-helical":
        _groove(conv, parts, [b for b, _ in widths])
    else:
        groove, src = conv.agree(parts.stages, "custom_femgear_groove_width", "the groove width")
        if groove is not None:
            conv.put("pair.groove_width", groove, src)
    _profile(conv, parts, m_n)
    _stage_values(conv, parts)


def _helix(conv: Conversion, parts: PairParts) -> None:
    model = conv.model
    gears = parts.members[0] + parts.members[1]
    beta, src = conv.agree(gears, "helix_angle_reference_diameter", "the helix angle of the pair", required=True,
                           absolute=True)
    p, g = parts.members[0][0], parts.members[1][0]
    beta_p = model.value(p, "helix_angle_reference_diameter")
    beta_g = model.value(g, "helix_angle_reference_diameter")
    if beta_p * beta_g > 0:
        raise model.error(g, "helix_angle_reference_diameter",
                          f"{beta_g:+g}° has the same hand as its mate {p.label()} ({beta_p:+g}°): mixed hands, a "
                          "mating external pair needs opposite hands (+β / −β)")
    if abs(beta) >= 45:
        raise model.error(p, "helix_angle_reference_diameter", f"|β| = {abs(beta):g}° is outside femgear's range (< 45°)")
    conv.put("pair.helix_angle_deg", abs(beta), src)


def _groove(conv: Conversion, parts: PairParts, widths: list[float]) -> None:
    model = conv.model
    grooves = []
    for halves, b in zip(parts.members, widths, strict=True):
        u = [model.value(h, "u_coordinate_on_shaft") for h in halves]
        if None in u:
            conv.default("pair.groove_width", 0.0, "the halves' u_coordinate_on_shaft is not in the model")
            return
        grooves.append((abs(u[0] - u[1]) - b, halves))
    (g1, h1), (g2, h2) = grooves
    if abs(g1 - g2) > 1e-6 * max(widths):
        raise model.error(h2[0], "u_coordinate_on_shaft",
                          f"the groove between the halves {h2[0].id}, {h2[1].id} is {g2 * 1e3:.4f} mm, between the "
                          f"mating halves {h1[0].id}, {h1[1].id} {g1 * 1e3:.4f} mm: femgear needs one groove width")
    if g1 < -1e-9 * max(widths):
        raise model.error(h1[1], "u_coordinate_on_shaft", f"the halves overlap by {-g1 * 1e3:.4f} mm (their distance "
                                                          "is less than the face width)")
    conv.put("pair.groove_width", max(g1, 0.0) if g1 > 1e-12 else 0.0,
             [(h, "u_coordinate_on_shaft") for _, hs in grooves for h in hs] +
             [(h, "face_width") for _, hs in grooves for h in hs])


def _profile(conv: Conversion, parts: PairParts, m_n: float) -> None:
    """Pressure angle, addendum, profile shifts, dedendum and root radius of the basic rack."""
    model = conv.model
    flanks = _flanks(model, parts.members[0] + parts.members[1])
    tools = [t for g in parts.members[0] + parts.members[1] for t in tools_of(model, g)]
    alpha, src = conv.agree(flanks + tools, "normal_pressure_angle", "the normal pressure angle of the pair")
    if alpha is None:
        conv.default("pair.normal_pressure_angle_deg", 20.0, "no normal_pressure_angle on the flanks: 20° assumed")
    else:
        conv.put("pair.normal_pressure_angle_deg", alpha, src)
    h_a, src = conv.agree(flanks, "addendum_coefficient_basic_profile", "the basic-rack addendum of the pair")
    if h_a is not None:
        conv.put("pair.addendum_coeff", h_a, src)
    shifts = {}
    for name, halves in zip(MEMBERS, parts.members, strict=True):
        x, src = conv.agree(_flanks(model, halves), "addendum_modification_coefficient",
                            f"the profile shift of the {name} (one per member, both flanks)")
        if x is not None:
            conv.put(f"{name}.profile_shift", x, src)
        elif conv.get(f"{name}.tip_diameter") is None and model.value(parts.stages[0], "center_distance") is None:
            conv.default(f"{name}.profile_shift", 0.0, "no addendum_modification_coefficient, tip diameter or "
                                                       "centre distance in the model")
        shifts[name] = x
    h_f, tool_src = conv.agree(tools, "addendum_coefficient_reference_profile", "the basic-rack dedendum of the pair")
    if h_f is not None:
        conv.put("pair.dedendum_coeff", h_f, tool_src)
    rho, src = conv.agree(tools, "tip_radius_factor", "the basic-rack root radius of the pair")
    if rho is not None:
        conv.put("pair.root_radius_coeff", rho, src)
    _root_diameters(conv, parts, m_n, shifts, h_f, tool_src)


def _root_diameters(conv: Conversion, parts: PairParts, m_n: float, shifts: dict, h_f: float | None,
                    tool_src: list[Source]) -> None:
    """Derive (or check) the dedendum from the root diameters d_f = d − 2 m_n (h_fP − x)."""
    model = conv.model
    beta = math.radians(conv.get("pair.helix_angle_deg"))
    derived = []
    for name, halves in zip(MEMBERS, parts.members, strict=True):
        d_f, src = conv.agree(halves, "root_diameter", f"the root diameter of the {name}")
        if d_f is None or shifts[name] is None:
            continue
        d = conv.get(f"{name}.teeth") * m_n / math.cos(beta)
        derived.append(((d - d_f) / (2 * m_n) + shifts[name], src))
    if not derived:
        return
    ref, ref_src = (h_f, tool_src) if h_f is not None else derived[0]
    for value, src in derived:
        if abs(value - ref) > TIP_TOLERANCE:
            other = ref_src[0] if ref_src else src[0]
            raise model.error(src[0][0], "root_diameter",
                              f"gives a dedendum h_fP = {value:.4f} m_n, {other[0].label()} attribute {other[1]} gives "
                              f"{ref:.4f} m_n: the root diameter does not fit the profile shift and basic rack")
    if h_f is None:
        conv.put("pair.dedendum_coeff", derived[0][0], [s for _, src in derived for s in src])


def _stage_values(conv: Conversion, parts: PairParts) -> None:
    """Centre distance, backlash and femgear's stagger of the stage(s)."""
    a, src = conv.agree(parts.stages, "center_distance", "the centre distance of the pair")
    if a is not None:
        conv.put("pair.centre_distance", a, src)
    j_min, s1 = conv.agree(parts.stages, "minimum_normal_backlash", "the backlash of the pair")
    j_max, s2 = conv.agree(parts.stages, "maximum_normal_backlash", "the backlash of the pair")
    given = [j for j in (j_min, j_max) if j is not None]
    if given:       # REXS gives the total normal backlash j_bn; femgear's pair.backlash is half of it
        conv.put("pair.backlash", sum(given) / len(given) / 2, s1 + s2)
    else:
        m_n = conv.get("pair.normal_module")
        a_w = a if a is not None else (conv.get("pinion.teeth") + conv.get("gear.teeth")) * m_n / 2 / math.cos(
            math.radians(conv.get("pair.helix_angle_deg")))
        j_min = 2 / 3 * (0.06e-3 + 0.0005 * a_w + 0.03 * m_n)
        conv.default("pair.backlash", j_min / 2, "no minimum/maximum_normal_backlash on the stage: half the "
                                                 "recommended minimum of ISO/TR 10064-2, j_bn = 2/3 (0.06 mm + "
                                                 "0.0005 a + 0.03 m_n)")
    stagger, src = conv.agree(parts.stages, "custom_femgear_stagger", "the stagger of the helices")
    if stagger is not None:
        conv.put("pair.stagger", stagger, src)
