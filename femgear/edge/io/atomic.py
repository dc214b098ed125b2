"""Atomic file writing: a file on disk is either the complete new content or absent.

Every writer goes through :func:`atomic_write`: the content is written to a
temporary file in the *same folder* (so that the final rename never crosses a
file system), flushed and ``fsync``-ed, given mode 0644, and only then renamed
onto the target with :func:`os.replace` (atomic on POSIX). If anything fails
(a full disk, a writer that raises, Ctrl-C), the temporary file is removed and
an existing target is left untouched.

Usage::

    with atomic_write(path, "w") as fh:
        fh.write(text)
    write_text_atomic(path, text)
    write_bytes_atomic(path, data)
"""

from __future__ import annotations

import contextlib
import os
import tempfile
from collections.abc import Iterator
from pathlib import Path
from typing import IO, Any

FILE_MODE = 0o644


def _fsync_dir(folder: Path) -> None:
    """Flush the directory entry (the rename) to disk; a no-op where unsupported."""
    try:
        fd = os.open(folder, os.O_RDONLY)
    except OSError:
        return
    try:
        os.fsync(fd)
    except OSError:
        pass
    finally:
        os.close(fd)


@contextlib.contextmanager
def atomic_write(
    path: str | os.PathLike[str], mode: str = "w", *, encoding: str | None = "utf-8"
) -> Iterator[IO[Any]]:
    """Open a temporary file next to ``path``; on clean exit rename it onto ``path``.

    ``mode`` is ``"w"`` (text, ``encoding`` used) or ``"wb"`` (bytes). The parent
    folder is created if needed. The final file has mode 0644 whatever the umask.
    """
    if mode not in ("w", "wb"):
        raise ValueError(f"atomic_write: mode must be 'w' or 'wb', got {mode!r}")
    target = Path(path)
    target.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp_name = tempfile.mkstemp(dir=target.parent, prefix=f".{target.name}.", suffix=".tmp")
    tmp = Path(tmp_name)
    try:
        kwargs = {"encoding": encoding} if mode == "w" else {}
        with os.fdopen(fd, mode, **kwargs) as fh:
            yield fh
            fh.flush()
            os.fsync(fh.fileno())
        os.chmod(tmp, FILE_MODE)
        os.replace(tmp, target)
    except BaseException:
        tmp.unlink(missing_ok=True)
        raise
    _fsync_dir(target.parent)


def write_text_atomic(path: str | os.PathLike[str], text: str, *, encoding: str = "utf-8") -> Path:
    """Write ``text`` to ``path`` atomically (mode 0644); return the path."""
    with atomic_write(path, "w", encoding=encoding) as fh:
        fh.write(text)
    return Path(path)


def write_bytes_atomic(path: str | os.PathLike[str], data: bytes) -> Path:
    """Write ``data`` to ``path`` atomically (mode 0644); return the path."""
    with atomic_write(path, "wb") as fh:
        fh.write(data)
    return Path(path)


__all__ = ["FILE_MODE", "atomic_write", "write_bytes_atomic", "write_text_atomic"]
