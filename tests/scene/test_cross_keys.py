"""Checks of one key against another live in the scene's validation (issue 37, item 6): ``femgear info`` and
``femgear run`` refuse alike, before anything is computed, with one line naming both keys.

Before, ``numerics.transient_cycles > numerics.dynamics_cycles`` passed ``info`` and ended ``run`` in
"internal error: ValueError" (exit 1) after the quasi-static pass; a bearing span inside the helix centres
and a relief longer than the flank were refused only once the rotor model or the LTCA bodies were built.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from femgear.edge.cli import main

ROOT = Path(__file__).resolve().parents[2]
BASE = ROOT / "studies" / "paper_baseline.toml"

CASES = {
    "transient beyond the simulated periods": (BASE, ["numerics.transient_cycles=120"],
                                               "numerics.transient_cycles", ["numerics.dynamics_cycles", "121"]),
    "no whole recorded period": (BASE, ["numerics.dynamics_cycles=60", "numerics.transient_cycles=59.5"],
                                 "numerics.transient_cycles", ["numerics.dynamics_cycles = 60"]),
    "bearings under the teeth": (BASE, ["pinion.bearing_span=0.015"], "pinion.bearing_span",
                                 ["toothed width is 35 mm", "outside the teeth"]),
    "relief longer than the profile": (BASE, ["modifications.tip_relief=1e-5", "modifications.tip_relief_length=0.05"],
                                       "modifications.tip_relief_length", ["active profile"]),
}


def _cli(argv, capsys) -> tuple[int, str]:
    try:
        rc = main([str(a) for a in argv])
    except SystemExit as exc:
        rc = exc.code
    return rc, capsys.readouterr().err


@pytest.mark.parametrize("case", CASES)
def test_info_and_run_refuse_alike_naming_both_keys(case, capsys, tmp_path):
    scene, overrides, key, words = CASES[case]
    sets = [a for o in overrides for a in ("--set", o)]
    lines = {}
    for command in ("info", "run"):
        extra = ["--out", tmp_path / "run", "--no-plots", "--no-vtk"] if command == "run" else []
        rc, err = _cli([command, scene, *sets, *extra], capsys)
        assert rc == 2, (command, err)
        assert len(err.strip().splitlines()) == 1 and "Traceback" not in err and "internal error" not in err, err
        lines[command] = err.strip()
    assert lines["info"] == lines["run"]
    assert f"error: {key}: " in lines["info"]
    for word in words:
        assert word in lines["info"], f"{word!r} not in {lines['info']}"
    assert not (tmp_path / "run" / "results.json").exists()


def test_a_whole_recorded_period_is_enough(capsys):
    rc, err = _cli(["info", BASE, "--set", "numerics.dynamics_cycles=51", "--set", "numerics.transient_cycles=50",
                    "--json", "-q"], capsys)
    assert rc == 0, err
