"""Output locations, checked before any computation starts.

:func:`prepare_output_dir` creates a folder and proves it writable (by writing and
removing a probe file), so that a run never computes for minutes and then loses its
results to a permission error. :func:`child_path` keeps a name taken from the scene
(``meta.name``, a sweep case id) inside its output root.
"""

from __future__ import annotations

import os
import tempfile
from pathlib import Path

from femgear.errors import OutputError


def prepare_output_dir(path: str | os.PathLike[str], argument: str = "--out") -> Path:
    """Create ``path`` (and parents) and check that files can be written in it.

    Raises :class:`femgear.errors.OutputError` naming ``argument`` when the folder
    cannot be created (a file is in the way, no permission, read-only file system)
    or a file cannot be written in it.
    """
    folder = Path(path)
    if folder.exists() and not folder.is_dir():
        raise OutputError(argument, str(folder), "it exists and is not a folder")
    try:
        folder.mkdir(parents=True, exist_ok=True)
        fd, probe = tempfile.mkstemp(dir=folder, prefix=".femgear-write-probe-")
        os.close(fd)
        os.unlink(probe)
    except OSError as exc:
        raise OutputError(argument, str(folder), exc.strerror or type(exc).__name__) from None
    return folder


def child_path(root: str | os.PathLike[str], name: str, argument: str) -> Path:
    """``root / name``, refused (naming ``argument``) if it would leave ``root``."""
    base = Path(root).resolve()
    target = (base / name).resolve()
    if target == base or base not in target.parents:
        raise OutputError(argument, str(Path(root) / name), f"{name!r} would leave the output folder {root}")
    return Path(root) / name


__all__ = ["child_path", "prepare_output_dir"]
