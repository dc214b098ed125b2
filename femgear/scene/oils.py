"""``oil.name``: a named oil of the library fills every ``[oil]`` key the scene does not give.

The library (:mod:`femgear.physics.lubrication.library`, listed by ``femgear oils``) evaluates the oil at
the table's reference temperature: ``oil.reference_temperature`` when given, else the supply temperature
``operating.ambient_temperature`` (its default when absent), so that the filled viscosity is the data
sheet's ASTM D341 line exactly where the contact is fed.  Keys given in the scene (or by ``--set``) win.
The provenance of every oil key (the library's source, the scene's own value, or femgear's default) is
:func:`oil_provenance`; groups without a published source are logged and written to results.json.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

from femgear.errors import SceneError
from femgear.physics.lubrication.library import LIBRARY, library_oil, oil_table

#: the ``[oil]`` keys of each data group of a library oil
GROUP_KEYS = {"viscosity": ("viscosity", "temperature_viscosity"), "density": ("density", "thermal_expansion"),
              "pressure_viscosity": ("pressure_viscosity",), "thermal": ("specific_heat", "conductivity"),
              "traction": ("eyring_stress", "limiting_shear_coeff")}


def fill_named_oil(raw: Mapping[str, Any]) -> dict[str, Any]:
    """``raw`` (a scene dictionary) with the keys of its named oil filled in; unchanged without ``oil.name``."""
    oil = raw.get("oil")
    if not isinstance(oil, Mapping) or "name" not in oil:
        return dict(raw)
    name = oil["name"]
    if not isinstance(name, str):
        raise SceneError("oil.name", f"must be the name of a library oil (got {name!r}); femgear oils lists them")
    try:
        entry = library_oil(name)
    except KeyError as exc:
        raise SceneError("oil.name", str(exc.args[0])) from None
    t_ref = oil.get("reference_temperature")
    if t_ref is None:
        op = raw.get("operating")
        t_ref = op.get("ambient_temperature", 313.0) if isinstance(op, Mapping) else 313.0
    if not isinstance(t_ref, int | float) or isinstance(t_ref, bool) or not 200.0 < t_ref < 600.0:
        t_ref = 313.15          # a temperature no oil has (°C typed as K): filled at 40 °C so that the schema and
        #                         the input ranges reach the temperature key and name it
    table = oil_table(entry, float(t_ref))
    return {**raw, "oil": {**table, **oil}}


def oil_provenance(oil) -> dict[str, Any]:
    """Where each data group of the ``[oil]`` table ``oil`` (a validated :class:`femgear.scene.schema.Oil`) comes
    from: ``name`` (None: the scene's own oil), ``sources`` {group: text or None} and ``unsourced`` (the groups
    resting on no published source: a library group without one, or femgear's default Eyring stress where the
    scene's own oil does not give it).  A key counts as the scene's own where it differs from the library's
    value (the fill gives every key)."""
    entry = LIBRARY.get(oil.name) if oil.name else None
    table = oil_table(entry, oil.reference_temperature) if entry is not None else {}
    given = oil.model_fields_set
    sources: dict[str, str | None] = {}
    for group, keys in GROUP_KEYS.items():
        own = [k for k in keys if k in given and not (table and math.isclose(getattr(oil, k), table[k], rel_tol=1e-9))]
        if group == "traction" and "eyring_stress" not in own:
            sources[group] = entry.sources.get(group) if entry is not None else None
        elif own or entry is None:
            sources[group] = "the scene's own values"
        else:
            sources[group] = entry.sources.get(group)
    return {"name": oil.name, "sources": sources, "unsourced": [g for g, v in sources.items() if v is None]}


def unsourced_warning(oil) -> str | None:
    """The log line naming the oil data that rest on no published source (None when all are sourced)."""
    prov = oil_provenance(oil)
    missing = prov["unsourced"]
    if not missing:
        return None
    who = f'the library oil "{prov["name"]}"' if prov["name"] else "the scene's oil"
    what = ", ".join(missing)
    if missing == ["traction"] and not prov["name"]:
        what = "traction (oil.eyring_stress, oil.limiting_shear_coeff: femgear's defaults τ0 = 5 MPa, Λ = 0)"
    return (f"oil.eyring_stress: {who} has no published source for its {what} data; μ and the contact "
            "temperature rest on them (results.json summary.oil.unsourced)")
