"""Helpers shared by the sub-commands: scene arguments and JSON output."""

from __future__ import annotations

import argparse
import json
from typing import Any

from femgear.io.results import to_plain


def add_scene_arguments(parser: argparse.ArgumentParser) -> None:
    """``SCENE`` plus repeatable ``--set a.b=value`` overrides."""
    parser.add_argument("scene", metavar="SCENE", help="scene file (TOML)")
    parser.add_argument(
        "--set", dest="overrides", action="append", default=[], metavar="KEY=VALUE",
        help="override a scene key, e.g. --set operating.torque=150 (repeatable)",
    )


def emit_json(payload: dict[str, Any]) -> None:
    """Print ``payload`` as one JSON line (numpy values converted, non-finite -> null)."""
    print(json.dumps(to_plain(payload), separators=(",", ":")))
