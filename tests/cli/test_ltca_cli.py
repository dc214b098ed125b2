"""``femgear ltca`` and the loaded TE in ``femgear run`` with ``stiffness = "ltca"`` (issue 31).

The slow cases run the level-1 member bodies of the baseline (compliance 23–36 s cold, then read from the disk
cache ``out/cache/ltca`` or ``$FEMGEAR_CACHE``)."""

from __future__ import annotations

import json
import math
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest

from tests.cli.test_bad_input import cli

ROOT = Path(__file__).resolve().parents[2]
BASE = str(ROOT / "studies" / "paper_baseline.toml")
RELIEF = ["--set", "modifications.tip_relief=10e-6", "--set", "modifications.tip_relief_length=2.5e-3"]


@pytest.mark.parametrize("args, key", [
    (["--torques", ""], "--torques"), (["--torques", ","], "--torques"), (["--torques", "100,-5"], "--torques"),
    (["--torques", "0"], "--torques"), (["--torques", "abc"], "--torques"), (["--torques", "1e6"], "--torques"),
    (["--torques", "nan"], "--torques"), (["--harris", "--harris-range", "300,100"], "--harris-range"),
    (["--harmonics", "40"], "--harmonics"), (["--phases", "2"], "--phases"),
])
def test_bad_torques_and_options_end_in_one_line_naming_the_key(args, key, capsys, tmp_path):
    """Refused before any FE work: exit 2, one line on stderr naming the argument."""
    rc, out, err = cli(["ltca", BASE, "--out", str(tmp_path / "o"), *args], capsys)
    lines = err.strip().splitlines()
    assert rc == 2 and len(lines) == 1 and key in lines[0] and "Traceback" not in err, err
    assert not (tmp_path / "o" / "results.json").exists()


@pytest.mark.slow
def test_ltca_tool_on_the_baseline_with_a_tip_relief_at_three_torques(tmp_path, capsys):
    """Tip relief 10 µm over 2.5 mm, 100/200/300 N m (level-1 bodies, 32 phases; ≈ 25 s cached): TE curves,
    harmonics, load maps and one ParaView set per torque are written; results.json's TE p-p and harmonics equal
    ``LTCAResult.lte_peak_to_peak``/``harmonics`` (what studies/ltca/ltca_study.py prints) to 1e-9."""
    from femgear.physics.geometry import GearPair
    from femgear.physics.ltca.analysis import body_options, build_model, mesh_cycle, normal_force
    from femgear.scene import load_scene

    out = tmp_path / "ltca"
    rc, stdout, err = cli(["-q", "ltca", BASE, *RELIEF, "--torques", "100,200,300", "--phases", "32",
                           "--out", str(out), "--json"], capsys)
    assert rc == 0, err
    summary = json.loads(stdout.strip().splitlines()[-1])
    for name in ("te_curves.png", "te_harmonics.png", "results.json", *(f"load_T{t}Nm.png" for t in (100, 200, 300)),
                 *(f"ltca_maps_T{t}Nm.pvd" for t in (100, 200, 300))):
        assert (out / name).is_file(), name
    data = json.loads((out / "results.json").read_text())
    assert data["units"]["lte_peak_to_peak"] == "m" and len(data["curves"]) == 3
    scene = load_scene(BASE, ["modifications.tip_relief=10e-6", "modifications.tip_relief_length=2.5e-3"])
    pair = GearPair.from_scene(scene)
    body = body_options(scene)
    model = build_model(pair, 210e9, 0.3, stagger=body.pop("stagger"), **body)
    for row in summary["per_torque"]:
        r = mesh_cycle(model, normal_force(pair, row["torque"]), scene.modifications, n_phases=32)
        assert row["lte_peak_to_peak"] == pytest.approx(r.lte_peak_to_peak(), rel=1e-9)
        np.testing.assert_allclose(row["lte_harmonics"], r.harmonics(5), rtol=0, atol=1e-9 * r.lte_peak_to_peak())
        assert row["load_balance_error"] < 1e-9 and row["nlte_peak_to_peak"] >= 0
    pvd = out / "ltca_maps_T200Nm.pvd"
    parts = [d.get("name") for d in ET.parse(pvd).getroot().iter("DataSet")]
    assert parts == ["pinion", "gear"]


@pytest.mark.slow
def test_a_modification_that_opens_a_helix_at_the_design_load_is_refused(tmp_path, capsys):
    rc, _, err = cli(["ltca", BASE, "--set", "modifications.helix_slope_deviation_right=2e-4", "--phases", "16",
                      "--out", str(tmp_path)], capsys)
    lines = err.strip().splitlines()
    assert rc == 2 and len(lines) == 1 and "modifications.helix_slope_deviation_right" in lines[0], err
    assert "right helix loses contact" in lines[0]


@pytest.mark.slow
def test_main_job_results_json_shows_the_loaded_te_for_ltca(tmp_path, capsys):
    """``femgear run`` with ``stiffness = "ltca"`` (quasi-static): results.json's summary and the key figures carry
    the loaded TE p-p of the level's cycle; ``ltca_pressure.vtu`` holds both members."""
    import meshio

    out = tmp_path / "run"
    args = ["run", BASE, "--out", str(out), "--no-plots"]
    for o in ('physics.stiffness="ltca"', 'physics.dynamics="none"', 'physics.coupling="one-way"',
              'physics.lubrication="constant"', 'physics.thermal="none"', 'physics.wear="none"'):
        args += ["--set", o]
    rc, stdout, err = cli(args, capsys)
    assert rc == 0, err
    assert "loaded TE p-p (LTCA, normal)" in stdout
    te = json.loads((out / "results.json").read_text())["summary"]["transmission_error"]
    assert 0 < te["lte_peak_to_peak"] < 5e-6 and len(te["lte_harmonics"]) == 5
    assert te["load_balance_error"] < 1e-6 and te["nlte_peak_to_peak"] == 0.0
    m = meshio.read(out / "ltca_pressure.vtu")
    assert set(np.unique(m.point_data["member"])) == {1, 2}
    assert math.isfinite(te["max_pressure"]) and te["max_pressure"] > 1e8
