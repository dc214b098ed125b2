"""``femgear info SCENE``: geometry, contact, ISO 6336-2 rating and mesh power loss of a scene."""

from __future__ import annotations

import argparse

from femgear.cli.common import add_scene_arguments, emit_json


def register(sub) -> None:
    p = sub.add_parser("info", help="geometry, contact, ISO 6336-2 rating and mesh power loss of a scene")
    add_scene_arguments(p)
    p.add_argument("--json", action="store_true", help="print one JSON object as the last line")
    p.set_defaults(func=_info)


def _info(args: argparse.Namespace) -> int:
    from femgear.contact.path import contact_along_path, zone_grid
    from femgear.geometry import GearPair
    from femgear.scene import load_scene
    from femgear.summary import scene_summary

    scene = load_scene(args.scene, args.overrides)
    pair = GearPair.from_scene(scene)
    contact = contact_along_path(scene, pair=pair, u=zone_grid(pair, scene.numerics.path_points))
    summary = scene_summary(scene, pair, contact)
    if args.json:
        emit_json(summary)
    else:
        _print_tree(summary)
    return 0


def _print_tree(d: dict, indent: int = 0) -> None:
    for key, value in d.items():
        if isinstance(value, dict):
            print(" " * indent + f"{key}:")
            _print_tree(value, indent + 2)
        elif isinstance(value, list):
            print(" " * indent + f"{key}: " + ", ".join(f"{v:.6g}" for v in value))
        elif isinstance(value, float):
            print(" " * indent + f"{key}: {value:.6g}")
        else:
            print(" " * indent + f"{key}: {value}")
