"""Progress for every stage over about 10 s, cached or not (issue 37, item 9): the coupling passes and the wear
integration print NOTICE lines (shown without -v) once they have run 10 s; before, with cached bodies, they (and
the LTCA contact cycle: tests/ltca/test_contact_cycle_progress.py) printed nothing for minutes.

The clock of femgear.perf is replaced by one that advances 3 s (6 s) per reading, so the test takes no time.
"""

from __future__ import annotations

import itertools
import logging
from pathlib import Path
from types import SimpleNamespace

import pytest

import femgear.perf as perf
from femgear.perf import NOTICE, Progress

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture
def slow_clock(monkeypatch):
    ticks = itertools.count(step=3.0)
    monkeypatch.setattr(perf, "time", SimpleNamespace(perf_counter=lambda: next(ticks)))


@pytest.fixture
def slower_clock(monkeypatch):
    """6 s per reading: a coupling loop reads it once per pass."""
    ticks = itertools.count(step=6.0)
    monkeypatch.setattr(perf, "time", SimpleNamespace(perf_counter=lambda: next(ticks)))


def _notices(caplog, stage: str) -> list[str]:
    return [r.getMessage() for r in caplog.records if r.levelno == NOTICE and r.getMessage().startswith(stage)]


def test_a_stage_expected_short_is_shown_once_it_has_run_ten_seconds(slow_clock, caplog):
    with caplog.at_level(logging.INFO, logger="femgear.cost"):
        p = Progress("cached stage", 20, expected_seconds=0.5)
        for i in range(1, 21):
            p(i)
    records = [r for r in caplog.records if r.getMessage().startswith("cached stage")]
    shown = [r for r in records if r.levelno == NOTICE]
    assert records[0].levelno == logging.INFO and shown                         # INFO first, NOTICE after 10 s
    assert all(float(r.getMessage().split("(")[-1].split()[0]) >= perf.LONG_STAGE_SECONDS for r in shown)
    assert shown[-1].getMessage().startswith("cached stage: 20/20")            # and the end
    assert len(shown) <= 2 + 3 * 20 / perf.LONG_STAGE_SECONDS                 # at most one per 10 s


def test_the_coupling_passes_are_shown(slower_clock, caplog):
    from femgear.case import build_case
    from femgear.scene import load_scene
    from femgear.system.coupling import CouplingSetup, run_coupled

    scene = load_scene(ROOT / "studies" / "paper_baseline.toml", [
        'physics.dynamics="lumped"', "numerics.dynamics_cycles=30", "numerics.transient_cycles=10",
        'physics.thermal="analytic"', 'physics.coupling="bidirectional"'])
    with caplog.at_level(logging.INFO, logger="femgear.cost"):
        run_coupled(CouplingSetup.from_case(build_case(scene, warn=False), n_phase=64), tol_force=1e-3, tol_mu=1e-3,
                    max_iter=6)
    lines = _notices(caplog, "coupling of scene 'paper_baseline'")
    assert lines and any("done in" in line and "mesh-force change" in line for line in lines), lines


def test_the_wear_integration_is_shown(slow_clock, caplog):
    from femgear.case import build_case
    from femgear.levels.wear import static_setup
    from femgear.physics.wear import run_wear
    from femgear.scene import load_scene

    case = build_case(load_scene(ROOT / "studies" / "zoo" / "fzg_c14.toml"), warn=False)
    with caplog.at_level(logging.INFO, logger="femgear.cost"):
        run_wear(static_setup(case), 3e6)
    lines = _notices(caplog, "Archard wear to 3e+06 cycles")
    assert lines and "largest depth" in lines[-1]
