"""The LTCA's disk cache is written atomically by every writer, also when two write the same entry at once."""

from __future__ import annotations

from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest

from femgear.physics.ltca.compliance import save_cache


def test_concurrent_writers_of_one_entry_leave_one_whole_file(tmp_path):
    """Eight writers of the same entry (two sweep workers building the same body): each writes its own temporary
    file and renames it, so the entry is always one writer's whole file and no temporary file is left.  With one
    shared temporary name the writers wrote into and renamed away each other's file."""
    path = tmp_path / "cache" / "member1-abc.npz"
    big = np.arange(200_000, dtype=float)

    def write(k: int) -> None:
        save_cache(path, bulk=big + k, k=np.array(k))

    with ThreadPoolExecutor(8) as pool:
        list(pool.map(write, range(8)))
    with np.load(path) as data:
        k = int(data["k"])
        assert np.array_equal(data["bulk"], big + k)
    assert [p.name for p in path.parent.iterdir()] == [path.name]


def test_a_failed_write_leaves_no_temporary_file(tmp_path):
    path = tmp_path / "member2-abc.npz"

    class Unsavable:
        def __array__(self, dtype=None, copy=None):
            raise RuntimeError("disk full")

    with pytest.raises(RuntimeError, match="disk full"):
        save_cache(path, bad=Unsavable())
    assert list(tmp_path.iterdir()) == []
