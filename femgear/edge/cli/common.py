"""Helpers shared by the sub-commands: scene arguments and JSON output."""

from __future__ import annotations

import argparse
import json
from typing import Any

from femgear.edge.io.results import to_plain


def add_scene_arguments(parser: argparse.ArgumentParser) -> None:
    """``SCENE`` plus repeatable ``--set a.b=value`` overrides."""
    parser.add_argument("scene", metavar="SCENE", help="scene file (TOML), or a REXS model with --stage")
    parser.add_argument(
        "--set", dest="overrides", action="append", default=[], metavar="KEY=VALUE",
        help="override a scene key, e.g. --set operating.torque=150 (repeatable)",
    )
    parser.add_argument("--stage", type=int, default=None, metavar="ID",
                        help="with a REXS model as SCENE (.rexs, .rexsj, .rexsz): the id of its cylindrical stage "
                             "(femgear rexs FILE lists them)")


def load_scene_arg(args: argparse.Namespace):
    """The scene of ``SCENE``: a TOML scene file, or one stage of a REXS model (through :mod:`femgear.rexs`,
    the same conversion as ``femgear rexs FILE --stage ID``)."""
    from femgear.rexs import is_rexs_path

    if is_rexs_path(args.scene):
        from femgear.rexs.importer import scene_from_rexs

        return scene_from_rexs(args.scene, args.stage, args.overrides)
    if args.stage is not None:
        from femgear.errors import ArgumentError

        raise ArgumentError("--stage", "only for a REXS model (.rexs, .rexsj, .rexsz) as SCENE")
    from femgear.scene import load_scene

    return load_scene(args.scene, args.overrides)


def load_case_arg(args: argparse.Namespace):
    """The bound :class:`femgear.case.Case` of ``SCENE`` (:func:`femgear.case.build_case`, once), its levels'
    up-front checks passed (:func:`femgear.levels.check_case`); for a REXS model, an error of the binding (the
    gear's feasibility) names the REXS component and attribute."""
    from femgear.case import build_case
    from femgear.levels import check_case
    from femgear.rexs import is_rexs_path

    if not is_rexs_path(args.scene):
        case = build_case(load_scene_arg(args))
        check_case(case)
        return case
    from femgear.rexs.importer import read_stage, validate

    conv = read_stage(args.scene, args.stage)
    return bind_rexs(conv, validate(conv, args.overrides))


def bind_rexs(conv, scene):
    """``build_case(scene)`` of a REXS conversion ``conv`` with its levels' checks, a :class:`SceneError` re-issued
    naming the REXS component and attribute of its key (:func:`femgear.rexs.importer.translate`)."""
    from femgear.case import build_case
    from femgear.errors import SceneError
    from femgear.levels import check_case
    from femgear.rexs.importer import translate

    try:
        case = build_case(scene)
        check_case(case)
        return case
    except SceneError as exc:
        raise translate(conv, exc) from None


def emit_json(payload: dict[str, Any]) -> None:
    """Print ``payload`` as one JSON line (numpy values converted, non-finite -> null)."""
    print(json.dumps(to_plain(payload), separators=(",", ":")))
