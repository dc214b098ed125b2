"""A fully commented scene template (``femgear new``), generated from the schema.

Every key of :mod:`femgear.scene.schema` appears with its meaning, unit, type and
default (from :func:`femgear.scene.keys.scene_keys`, never hand-copied).  The keys a
scene must give are set to the values of an example pair of the chosen kind (an
industrial compressor drive, 250 kW at 1480 rpm, m_n 4 mm, 25/83 teeth); every other
key is written commented out at its default, so uncommenting one is a deliberate change
(and a ``physics.preset`` still fills the keys left commented).  The template loads with
:func:`femgear.scene.load.load_scene` as written (``tests/cli/test_new.py`` runs it).
"""

from __future__ import annotations

import json
import textwrap
from typing import Any

from femgear.scene.keys import KeyDoc, TableDoc, scene_keys, scene_tables

KINDS = ("double", "single", "spur")
_KIND_NAMES = {"double": "double-helical", "single": "single-helical", "spur": "spur"}

#: the example pair: values of the keys every kind sets (SI; angles in degrees)
_COMMON: dict[str, Any] = {
    "meta.description": "example pair: compressor drive, 250 kW at 1480 rpm, m_n 4 mm, 25/83 teeth",
    "pair.normal_module": 4.0e-3, "pair.normal_pressure_angle_deg": 20.0, "pair.backlash": 100e-6,
    "pinion.teeth": 25, "pinion.mass": 10.7, "pinion.inertia": 0.0171, "pinion.support_stiffness": 1.0e9,
    "pinion.support_damping": 2000.0, "pinion.bearing_span": 0.25, "pinion.shaft_diameter": 0.065,
    "gear.teeth": 83, "gear.mass": 109.3, "gear.inertia": 2.07, "gear.bore_radius": 0.05,
    "gear.support_stiffness": 1.0e9, "gear.support_damping": 2000.0, "gear.bearing_span": 0.30,
    "gear.shaft_diameter": 0.10,
    "material.youngs_modulus": 206e9, "material.poisson_ratio": 0.3, "material.density": 7850.0,
    "material.specific_heat": 460.0, "material.conductivity": 45.0, "material.thermal_expansion": 1.15e-5,
    "oil.viscosity": 0.0243, "oil.density": 854.0, "oil.specific_heat": 2000.0, "oil.conductivity": 0.13,
    "oil.pressure_viscosity": 2.0e-8, "oil.temperature_viscosity": 0.0386, "oil.reference_temperature": 333.15,
    "operating.driver": "pinion", "operating.speed_rpm": 1480.0, "operating.torque": 1613.0,
    "operating.ambient_temperature": 333.15,
    "physics.stiffness": "pem", "physics.lubrication": "formula", "physics.thermal": "analytic",
    "physics.dynamics": "lumped", "physics.coupling": "bidirectional",
}
_KIND: dict[str, dict[str, Any]] = {
    "double": {"meta.name": "double_helical", "pair.kind": "double-helical", "pair.helix_angle_deg": 28.0,
               "pair.face_width": 0.055, "pair.groove_width": 0.025},
    "single": {"meta.name": "single_helical", "pair.kind": "single-helical", "pair.helix_angle_deg": 15.0,
               "pair.face_width": 0.110, "pinion.axial_stiffness": 5.0e8, "gear.axial_stiffness": 5.0e8,
               "pinion.axial_damping": 1000.0, "gear.axial_damping": 1000.0},
    "spur": {"meta.name": "spur", "pair.kind": "spur", "pair.helix_angle_deg": 0.0, "pair.face_width": 0.110},
}


def example_values(kind: str) -> dict[str, Any]:
    """The dotted keys the template of ``kind`` sets, with their example values."""
    if kind not in KINDS:
        raise ValueError(f"kind must be one of {', '.join(KINDS)} (got {kind!r})")
    return {**_COMMON, **_KIND[kind]}


def toml_value(value: Any) -> str:
    """``value`` as a TOML literal."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, str):
        return json.dumps(value, ensure_ascii=False)
    if isinstance(value, float):
        text = repr(value)
        if "e" not in text and value != 0 and not 1e-3 <= abs(value) < 1e5:
            text = next(t for t in (f"{value:.{n}g}" for n in range(1, 18)) if float(t) == value)  # 5e+08, exact
        return text if "." in text or "e" in text else text + ".0"
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(toml_value(v) for v in value) + "]"
    return repr(value)


def _comment(text: str, width: int = 100) -> list[str]:
    return ["# " + line for line in textwrap.wrap(text, width - 2)]


def _key_lines(k: KeyDoc, values: dict[str, Any], table_optional: bool) -> list[str]:
    unit = "" if k.unit is None else f" [{k.unit}]"
    status = "required" if k.required else ("no default: derived or off, as said above" if k.default is None
                                            else f"default: {toml_value(k.default)}")
    lines = _comment(k.description) + [f"#   ({k.type}{unit}; {status})"]
    if k.key in values:
        lines.append(f"{k.name} = {toml_value(values[k.key])}")
    elif k.default is None or table_optional:
        example = "..." if k.default is None else toml_value(k.default)
        lines.append(f"# {k.name} = {example}")
    else:
        lines.append(f"# {k.name} = {toml_value(k.default)}")
    return lines


def scene_template(kind: str = "double") -> str:
    """The commented template of a ``kind`` pair ("double", "single" or "spur") as TOML text."""
    values = example_values(kind)
    tables: dict[str, TableDoc] = {t.table: t for t in scene_tables()}
    by_table: dict[str, list[KeyDoc]] = {}
    for k in scene_keys():
        by_table.setdefault(k.table, []).append(k)
    out = [f"# femgear scene: a {_KIND_NAMES[kind]} pair (written by `femgear new --kind {kind}` from the scene schema).",
           "# Units are SI (m, N, Pa, kg, s, K); angles in degrees in the keys ending in _deg.",
           "# Active lines are the keys a scene must give (set to an example pair: a compressor drive,",
           "# 250 kW at 1480 rpm, m_n 4 mm, 25/83 teeth) and the example's choices; every other key is",
           "# commented out at its default: uncomment it to change it. Check every active value for YOUR pair.",
           "# Reference of every key: docs/reference/scene-keys.md; walkthrough: docs/guide/own-gear.md.", ""]
    for name, table in tables.items():
        optional = table.optional or any(tables[p].optional for p in _parents(name) if p in tables)
        if not by_table.get(name):
            continue
        out += _comment(table.doc)
        out.append(f"# [{name}]" if optional else f"[{name}]")
        for k in by_table[name]:
            out += _key_lines(k, values, optional)
        out.append("")
    return "\n".join(out)


def _parents(table: str) -> list[str]:
    parts = table.split(".")
    return [".".join(parts[:i]) for i in range(1, len(parts))]
