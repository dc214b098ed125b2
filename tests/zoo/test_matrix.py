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


def test_a_wide_lightly_crowned_helix_gets_the_point_tehl_with_its_hand_over_in_its_full_fidelity():
    """The marine pair's 2 x 120 mm helices are too slender for the point solver (R_x/R_y ≈ 4e-4): tehl-point binds
    and hands those contacts over to face slices of line TEHL (it used to be refused, and the cell fell back to tehl)."""
    full = zm.full_fidelity(ROOT / "studies" / "zoo" / "marine.toml")
    assert 'physics.lubrication="tehl-point"' in full


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


def test_a_crowned_point_cell_is_held_against_blok_flash_of_its_ellipse():
    """The small spur pair's full cell adds a 10 µm crowning to a 20 mm face: its point contacts run at about 2.8x
    the line pressure, and the hand flash must be the ellipse's (it was the line contact's, a FAIL by physics).
    Checked against the Jaeger band integral of the centre line's semi-elliptic heat source."""
    import numpy as np

    from femgear.case import build_case
    from femgear.levels.contact import contact_pass, reduced_modulus_of
    from femgear.physics.contact.crowning import crowned_contact
    from femgear.physics.contact.hertz import hertz_line, hertz_point
    from femgear.physics.lubrication.flash import band_flash_temperature

    path = SCENES["small_spur"]
    full = zm.full_fidelity(path)
    assert "modifications.crowning=10e-6" in full
    assert zm.hand_figures(path, full)["flash"] > 2 * zm.hand_figures(path)["flash"]
    case = build_case(zm._load(path, ["modifications.crowning=10e-6"]))
    w = contact_pass(case).line_load
    scale = zm._point_flash_scale(case, w)
    i = case.path.R.size // 4
    k, E = case.path, reduced_modulus_of(case)
    line = hertz_line(w[i], k.R[i], E)
    Rx, Ry = crowned_contact(case.pair, (10e-6, 10e-6)).radii(k.R[i])
    point = hertz_point(crowned_contact(case.pair, (10e-6, 10e-6)).load(w[i]), Rx, Ry, E)
    x = np.linspace(-1, 1, 801)[:-1] + 1 / 800
    v1, v2 = k.ue[i] * (1 + k.srr[i] / 2), k.ue[i] * (1 - k.srr[i] / 2)

    def peak(p, half):
        return band_flash_temperature(abs(v1 - v2) * p * np.sqrt(1 - x**2), half, v1, v2, 1.0, 1.0).max()

    assert scale[i] == pytest.approx(peak(point.max_pressure, point.a) / peak(line.max_pressure, line.half_width),
                                     rel=1e-3)
