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


def emit_json(payload: dict[str, Any]) -> None:
    """Print ``payload`` as one JSON line (numpy values converted, non-finite -> null)."""
    print(json.dumps(to_plain(payload), separators=(",", ":")))
