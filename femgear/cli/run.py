"""``femgear run SCENE``: run a scene and write its outputs."""

from __future__ import annotations

import argparse
from pathlib import Path

from femgear.cli.common import add_scene_arguments, emit_json


def register(sub) -> None:
    p = sub.add_parser("run", help="run what the scene's [physics] asks and write results")
    add_scene_arguments(p)
    p.add_argument("--out", type=Path, default=None, help="output folder (default: out/<meta.name>)")
    p.add_argument("--no-plots", action="store_true", help="skip PNG figures")
    p.add_argument("--json", action="store_true", help="print one JSON summary as the last line")
    p.set_defaults(func=_run)


def _run(args: argparse.Namespace) -> int:
    from femgear.pipeline import run_scene
    from femgear.scene import load_scene

    scene = load_scene(args.scene, args.overrides)
    out = args.out or Path("out") / scene.meta.name
    result = run_scene(scene, out, plots=not args.no_plots)
    if args.json:
        emit_json(result.summary)
    else:
        for name, path in result.files.items():
            print(f"{name}: {path}")
    return 0
