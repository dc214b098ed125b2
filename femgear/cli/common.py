"""Helpers shared by the sub-commands: scene arguments and JSON output."""

from __future__ import annotations

import argparse
import json
import math
from typing import Any

import numpy as np


def add_scene_arguments(parser: argparse.ArgumentParser) -> None:
    """``SCENE`` plus repeatable ``--set a.b=value`` overrides."""
    parser.add_argument("scene", metavar="SCENE", help="scene file (TOML)")
    parser.add_argument(
        "--set", dest="overrides", action="append", default=[], metavar="KEY=VALUE",
        help="override a scene key, e.g. --set operating.torque=150 (repeatable)",
    )


def _plain(obj: Any) -> Any:
    if isinstance(obj, dict):
        return {str(k): _plain(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [_plain(v) for v in obj]
    if isinstance(obj, np.ndarray):
        return _plain(obj.tolist())
    if isinstance(obj, np.generic):
        return _plain(obj.item())
    if isinstance(obj, float) and not math.isfinite(obj):
        return None
    return obj


def emit_json(payload: dict[str, Any]) -> None:
    """Print ``payload`` as one JSON line (numpy values converted, non-finite -> null)."""
    print(json.dumps(_plain(payload), separators=(",", ":")))
