"""The cheap part of the zoo matrix (``studies/validation/zoo_matrix.py``): every cell of every zoo scene is either a
valid scene or refused up front with one line naming a key; the force-balance invariant the full matrix
checks holds on the cheapest real run.  The runs of all cells: ``make test-slow`` / the study itself."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from studies.validation import zoo_matrix as zm

ROOT = Path(__file__).resolve().parents[2]
SCENES = zm.scenes()


@pytest.mark.parametrize("name", sorted(SCENES))
def test_every_cell_is_valid_or_refused_in_one_line_naming_a_key(name):
    from femgear.scene.levels import AVAILABLE

    path = SCENES[name]
    cells = zm.cells(path)
    assert "full" in cells and "default" in cells
    assert len(cells) >= 2 + sum(len(v) - 1 for v in AVAILABLE.values()) - 1
    for column, overrides in cells.items():
        row = zm.dry_run(name, path, column, overrides)
        verdict = row["verdict"]
        assert verdict == "valid" or verdict.startswith("refused: "), (column, verdict)
        if verdict != "valid":
            line = verdict.removeprefix("refused: ")
            assert "\n" not in line
            key = line.split(":", 1)[0]
            assert "." in key and " " not in key, (column, line)     # a dotted scene key comes first


def test_the_full_fidelity_of_the_baseline_is_the_papers():
    full = zm.full_fidelity(ROOT / "studies" / "paper_baseline.toml")
    assert 'physics.stiffness="ltca"' in full and 'physics.thermal="fe3d"' in full
    assert 'physics.lubrication="tehl-point"' in full and "modifications.crowning=10e-6" in full


def test_a_wide_lightly_crowned_helix_gets_the_line_tehl_in_its_full_fidelity():
    full = zm.full_fidelity(ROOT / "studies" / "zoo" / "marine.toml")
    assert 'physics.lubrication="tehl"' in full


def test_the_single_helical_industrial_stage_has_a_valid_ltca_cell():
    """Issue 37: a single-helical stiffness=ltca cell is in the matrix (the wind stage's is refused on its bore)."""
    path = SCENES["industrial"]
    cells = zm.cells(path)
    assert zm._load(path).pair.kind == "single-helical"
    for column in ("stiffness=ltca", "full"):
        assert zm.dry_run("industrial", path, column, cells[column])["verdict"] == "valid"


def test_a_coarse_run_passes_the_invariants(tmp_path, monkeypatch):
    """The default cell of the baseline without dynamics, through the matrix's own run and checks."""
    monkeypatch.setattr(zm, "OUT", tmp_path)
    path = ROOT / "studies" / "paper_baseline.toml"
    row = zm.run_cell("paper_baseline", path, "dynamics=none",
                      ['physics.dynamics="none"', 'physics.coupling="one-way"'], True, 300)
    assert row["verdict"] == "ok", row
    hand = zm.hand_figures(path)
    assert hand["force"] > 0 and math.isfinite(hand["film"]) and hand["film"] > 0


def test_cells_are_judged_by_cpu_time_not_by_the_load():
    """A child that sleeps 1 s costs almost no CPU (a loaded machine stretches a refusal's wall time, not its CPU
    time); one that spins 0.5 s costs about 0.5 s; output, exit code and the timeout behave as subprocess.run's."""
    import subprocess
    import sys

    sleep, cpu_sleep = zm.run_timed([sys.executable, "-c", "import time, sys; time.sleep(1); print('a'); "
                                     "sys.exit(2)"], 30)
    assert (sleep.returncode, sleep.stdout.strip()) == (2, "a") and cpu_sleep < 0.5
    _, cpu_spin = zm.run_timed([sys.executable, "-c", "import time\nt = time.process_time()\n"
                                "while time.process_time() - t < 0.5: pass"], 30)
    assert 0.45 < cpu_spin < 3.0
    with pytest.raises(subprocess.TimeoutExpired):
        zm.run_timed([sys.executable, "-c", "import time; time.sleep(10)"], 0.5)
