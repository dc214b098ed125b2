"""The CLI contract: one JSON object as the last stdout line; user errors as one line, exit 2."""

import json
import os
import subprocess
import sys

import pytest

from femgear.edge.cli import main


def test_info_json_last_line(baseline_path, capsys):
    assert main(["info", str(baseline_path), "--json"]) == 0
    out = json.loads(capsys.readouterr().out.strip().splitlines()[-1])
    g, c = out["geometry"], out["contact"]
    for key in ("eps_alpha", "eps_beta", "centre_distance", "base_radius", "mesh_frequency"):
        assert key in g
    assert g["mesh_frequency"] == pytest.approx(31 * 500 / 60)
    assert 3e8 < c["pitch"]["hertz_pressure"] < 1e9
    assert 1e-7 < c["pitch"]["film_central"] < 5e-6


def test_run_writes_results_and_png(baseline_path, tmp_path, capsys):
    assert main(["run", str(baseline_path), "--out", str(tmp_path), "--json"]) == 0
    summary = json.loads(capsys.readouterr().out.strip().splitlines()[-1])
    results = json.loads((tmp_path / "results.json").read_text())
    assert results["summary"]["scene"] == "paper_baseline"
    assert len(results["along_path"]["hertz_pressure"]) >= 41
    assert (tmp_path / "contact_path.png").stat().st_size > 10_000
    assert summary["outputs"]["results"].endswith("results.json")


@pytest.mark.parametrize(
    "override,key",
    [("pair.normal_module=-0.003", "pair.normal_module"), ("pair.addendum_coeff=0.5", "pair.addendum_coeff"),
     ("pinion.teeth=\"x\"", "pinion.teeth")],
)
def test_user_errors_are_one_line_without_traceback(baseline_path, override, key):
    proc = subprocess.run(
        [sys.executable, "-m", "femgear.edge.cli", "info", str(baseline_path), "--set", override],
        capture_output=True, text=True, env={**os.environ, "PYTHONWARNINGS": "ignore"},
    )
    assert proc.returncode == 2
    lines = proc.stderr.strip().splitlines()
    assert len(lines) == 1 and key in lines[0] and "Traceback" not in proc.stderr


def test_missing_scene_file(tmp_path, capsys):
    assert main(["info", str(tmp_path / "missing.toml")]) == 2
    assert "not found" in capsys.readouterr().err
