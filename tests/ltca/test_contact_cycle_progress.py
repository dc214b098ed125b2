"""The LTCA contact cycle prints its progress once it has run 10 s, also when its bodies came from the cache
(issue 37, item 9; femgear.perf's clock replaced by one that advances 3 s per reading)."""

from __future__ import annotations

import itertools
import logging
from types import SimpleNamespace

import femgear.perf as perf
from femgear.perf import NOTICE


def test_the_contact_cycle_is_shown(coarse_model, baseline_force, monkeypatch, caplog):
    from femgear.physics.ltca.analysis import mesh_cycle

    ticks = itertools.count(step=3.0)
    monkeypatch.setattr(perf, "time", SimpleNamespace(perf_counter=lambda: next(ticks)))
    with caplog.at_level(logging.INFO, logger="femgear.cost"):
        mesh_cycle(coarse_model, baseline_force, None, n_phases=12, n_line=6)
    shown = [r.getMessage() for r in caplog.records if r.levelno == NOTICE and "LTCA contact cycle" in r.getMessage()]
    assert shown and shown[-1].startswith("LTCA contact cycle (6 points per contact line): 12/12"), shown
