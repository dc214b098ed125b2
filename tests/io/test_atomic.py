"""Atomic writes: a complete file or none, mode 0644, old content kept on failure."""

from __future__ import annotations

import os
import stat

import pytest

from femgear.edge.io.atomic import atomic_write, write_bytes_atomic, write_text_atomic


def _mode(path):
    return stat.S_IMODE(os.stat(path).st_mode)


def test_text_and_bytes_written_with_mode_0644(tmp_path):
    old = os.umask(0o077)
    try:
        t = write_text_atomic(tmp_path / "a" / "x.txt", "hello")
        b = write_bytes_atomic(tmp_path / "y.bin", b"\x00\x01")
    finally:
        os.umask(old)
    assert t.read_text() == "hello" and b.read_bytes() == b"\x00\x01"
    assert _mode(t) == 0o644 and _mode(b) == 0o644


def test_writer_that_raises_leaves_old_file_and_no_temporary(tmp_path):
    """A full disk (simulated: the writer raises OSError ENOSPC) never leaves a corrupt file."""
    target = tmp_path / "results.json"
    write_text_atomic(target, '{"ok": 1}')
    with pytest.raises(OSError, match="No space"):
        with atomic_write(target) as fh:
            fh.write('{"partial": ')
            raise OSError(28, "No space left on device")
    assert target.read_text() == '{"ok": 1}'
    assert sorted(p.name for p in tmp_path.iterdir()) == ["results.json"]


def test_failure_on_new_file_leaves_nothing(tmp_path):
    target = tmp_path / "new.txt"
    with pytest.raises(KeyboardInterrupt):
        with atomic_write(target) as fh:
            fh.write("half")
            raise KeyboardInterrupt
    assert list(tmp_path.iterdir()) == []


def test_bad_mode_refused(tmp_path):
    with pytest.raises(ValueError, match="mode"):
        with atomic_write(tmp_path / "x", "a"):
            pass
