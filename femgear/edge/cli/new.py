"""``femgear new [FILE] --kind double|single|spur``: write a fully commented scene template.

Every key of the scene schema with its meaning, unit, type and default
(:func:`femgear.scene.template.scene_template`); the required keys are set to an example
pair of the chosen kind, so the file runs as written (``femgear run FILE``) and is edited
from there.  Without FILE the template goes to stdout.  An existing FILE is not
overwritten unless ``--force`` is given.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from femgear.errors import ArgumentError, OutputError
from femgear.scene.template import KINDS


def register(sub) -> None:
    p = sub.add_parser("new", help="write a commented scene template with every key, its unit and default",
                       description="Write a fully commented scene template: every key of the schema with its "
                                   "meaning, unit and default; the required keys are set to an example pair of "
                                   "the chosen kind (a 250 kW compressor drive), which runs as written.")
    p.add_argument("file", metavar="FILE", nargs="?", default=None,
                   help="scene file to write (TOML); default: print the template to stdout")
    p.add_argument("--kind", choices=KINDS, default="double",
                   help="double-helical (default), single-helical or spur pair")
    p.add_argument("--force", action="store_true", help="overwrite FILE if it exists")
    p.set_defaults(func=_new)


def _new(args: argparse.Namespace) -> int:
    from femgear.edge.io.atomic import write_text_atomic
    from femgear.scene.template import scene_template

    text = scene_template(args.kind)
    if args.file is None:
        sys.stdout.write(text)
        return 0
    path = Path(args.file)
    if path.suffix != ".toml":
        raise ArgumentError("FILE", f"a scene file ends in .toml (got {args.file!r})")
    if path.exists() and not args.force:
        raise ArgumentError("FILE", f"{args.file} exists; give --force to overwrite it")
    try:
        write_text_atomic(path, text)
    except OSError as exc:
        raise OutputError("FILE", str(path), exc.strerror or str(exc)) from exc
    print(f"wrote {path} ({args.kind} pair): edit the active values for your pair, then `femgear run {path}`")
    return 0
