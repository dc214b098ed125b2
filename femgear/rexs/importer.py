"""REXS file → validated femgear :class:`~femgear.scene.schema.Scene`, through the same conversion
that ``femgear rexs FILE --stage ID -o scene.toml`` writes out.

The scene's own checks (schema ranges, tip diameters and centre distance against the profile
shifts, feasibility of the gear) run on the converted dictionary; their errors are re-issued naming
the REXS component and attribute behind the scene key, and for a consistency error also the other
side (the profile shift behind a tip diameter, both shifts behind a centre distance).
"""

from __future__ import annotations

import os
import re
from collections.abc import Iterable
from pathlib import Path

from femgear.errors import SceneError
from femgear.rexs.convert import Conversion, pair_geometry
from femgear.rexs.model import Model, RexsError
from femgear.rexs.modifications import modifications
from femgear.rexs.ratings import ratings
from femgear.rexs.read import read_model
from femgear.rexs.stages import select_stage
from femgear.rexs.tables import material, members, oil, operating

#: scene keys whose consistency error involves other keys too
OTHER_SIDE = {"pinion.tip_diameter": ("pinion.profile_shift",), "gear.tip_diameter": ("gear.profile_shift",),
              "pair.centre_distance": ("pinion.profile_shift", "gear.profile_shift", "pinion.tip_diameter",
                                       "gear.tip_diameter")}


def convert(model: Model, stage_id: int | None = None) -> Conversion:
    """The scene dictionary of one stage of ``model`` (None: its only pair), with sources and defaults."""
    stage, parts = select_stage(model, stage_id)
    conv = Conversion(model, stage, parts)
    names = [s.name for s in parts.stages if s.name]
    common = os.path.commonprefix(names).strip() if len(names) > 1 else ""   # "marine left", "marine right"
    name = common or stage.name or f"stage {stage.id}"
    name = re.sub(r"[^A-Za-z0-9_ .+-]", "_", name).strip(" .") or f"stage_{stage.id}"
    conv.put("meta.name", name[:100], [])
    conv.put("meta.description", f"REXS {model.version} model {model.source} ({model.application or 'unknown tool'}), "
                                 f"stage {stage.id}", [])
    pair_geometry(conv)
    material(conv)
    members(conv)
    oil(conv)
    operating(conv)
    modifications(conv)
    _roughness(conv)
    ratings(conv)
    return conv


def _roughness(conv: Conversion) -> None:
    values = [conv.agree(halves, "averaged_peak_to_valley_height_flank", "the flank roughness R_z of a member")
              for halves in conv.parts.members]
    if all(v is not None for v, _ in values):
        conv.put("rating.roughness_rz", [v for v, _ in values], [s for _, src in values for s in src])


def read_stage(path: str | Path, stage_id: int | None = None, load_case: int | None = None) -> Conversion:
    """Read a REXS file and convert one stage."""
    return convert(read_model(path, load_case), stage_id)


def validate(conv: Conversion, overrides: Iterable[str] = (), *, warn: bool = True):
    """The validated scene of a conversion; scene errors name the REXS component and attribute."""
    from femgear.scene import scene_from_dict

    try:
        return scene_from_dict(conv.data, overrides, warn=warn)
    except RexsError:
        raise
    except SceneError as exc:
        raise translate(conv, exc) from None


def _where(conv: Conversion, key: str) -> str:
    sources = conv.sources.get(key) or []
    if not sources:
        why = conv.defaults.get(key)
        return f"{key} (not in the model: {why})" if why else key
    comp, attr = sources[0]
    return f"{comp.label()}, attribute {attr}"


def translate(conv: Conversion, exc: SceneError) -> RexsError:
    """``exc`` (naming a scene key) re-issued naming the REXS component and attribute of that key."""
    key = exc.key
    sources = conv.sources.get(key) or []
    others = [k for k in OTHER_SIDE.get(key, ()) if conv.sources.get(k) or k in conv.defaults]
    tail = f" [femgear key {key}"
    if others:
        tail += "; against " + "; ".join(_where(conv, k) for k in others)
    tail += "]"
    if sources:
        comp, attr = sources[0]
        return conv.model.error(comp, attr, exc.message + tail)
    why = conv.defaults.get(key)
    if why is not None:
        return conv.model.error(conv.stage, None, f"{key} (not in the model: {why}): {exc.message}{tail}")
    return conv.model.error(conv.stage, None, f"{key}: {exc.message}{tail}")


def scene_from_rexs(path: str | Path, stage_id: int | None = None, overrides: Iterable[str] = (),
                    load_case: int | None = None, *, warn: bool = True):
    """Read a REXS file and return the validated scene of one stage."""
    return validate(read_stage(path, stage_id, load_case), overrides, warn=warn)
