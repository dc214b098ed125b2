"""Writing results: plain JSON, atomically."""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any

import numpy as np

from femgear.edge.io.atomic import write_text_atomic


def to_plain(obj: Any) -> Any:
    """Convert numpy arrays/scalars (recursively) to JSON types; non-finite floats -> None."""
    if isinstance(obj, dict):
        return {str(k): to_plain(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [to_plain(v) for v in obj]
    if isinstance(obj, np.ndarray):
        return to_plain(obj.tolist())
    if isinstance(obj, np.generic):
        return to_plain(obj.item())
    if isinstance(obj, float) and not math.isfinite(obj):
        return None
    return obj


def write_json(path: str | Path, payload: dict[str, Any]) -> Path:
    """Write ``payload`` to ``path`` atomically (temporary file, fsync, rename; mode 0644)."""
    text = json.dumps(to_plain(payload), indent=1, allow_nan=False)
    return write_text_atomic(path, text + "\n")
