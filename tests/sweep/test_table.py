"""The sweep's table and summary figure: a numeric column per swept key, numeric order, summary.png,
and case folders that a Dask worker started elsewhere still finds."""

import csv
import os
from pathlib import Path

import pytest

from femgear.edge.sweep import parse_sweep, run_sweep
from femgear.edge.sweep.figure import choose_outputs
from femgear.edge.sweep.table import table_rows
from femgear.errors import ArgumentError

BASE = Path(__file__).resolve().parents[2] / "studies" / "paper_baseline.toml"
STATIC = '"physics.dynamics" = ["none"]\n"physics.coupling" = ["one-way"]\n'


def sweep_file(tmp_path, body: str, name: str = "t") -> Path:
    path = tmp_path / f"{name}.toml"
    path.write_text(f'base = "{BASE}"\nname = "{name}"\n' + body)
    return path


def test_rows_get_a_column_per_key_and_sort_numerically_not_as_strings(tmp_path):
    """1000 after 200 (as strings "1000" < "200"); strings keep the order of the file; [[case]] keys
    that the grid lacks come last."""
    spec = parse_sweep(sweep_file(tmp_path, '[grid]\n"operating.speed_rpm" = [1000.0, 200.0, 50.0]\n'
                                            '"physics.lubrication" = ["formula", "constant"]\n'
                                            '[[case]]\n"operating.torque" = 120.0\n'))
    rows = table_rows(spec, [{"case": c.case_id, "status": "done"} for c in reversed(spec.cases)])
    assert [r["operating.speed_rpm"] for r in rows] == [50.0, 50.0, 200.0, 200.0, 1000.0, 1000.0, None]
    assert [r["physics.lubrication"] for r in rows[:2]] == ["formula", "constant"]
    assert rows[-1]["operating.torque"] == 120.0 and rows[0]["operating.torque"] is None
    assert spec.keys == ("operating.speed_rpm", "physics.lubrication", "operating.torque")


def test_sweep_table_has_numeric_key_columns_and_a_summary_figure(tmp_path):
    path = sweep_file(tmp_path, '[grid]\n"operating.torque" = [200.0, 100.0, 150.0]\n' + STATIC)
    result = run_sweep(parse_sweep(path), tmp_path / "out", workers=2, progress=False)
    with open(result.table, newline="") as fh:
        reader = csv.DictReader(fh)
        header, rows = reader.fieldnames, list(reader)
    assert header[:5] == ["case", "status", "operating.torque", "physics.dynamics", "physics.coupling"]
    assert [float(r["operating.torque"]) for r in rows] == [100.0, 150.0, 200.0]
    pressure = [float(r["contact.pitch.hertz_pressure"]) for r in rows]
    assert pressure == sorted(pressure) and pressure[0] < pressure[-1]      # p_H grows with torque (√T)
    assert result.summary == tmp_path / "out" / "t" / "summary.png"
    assert result.summary.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    # a misspelt output is refused before anything is recomputed, with the closest column names
    with pytest.raises(ArgumentError) as info:
        run_sweep(parse_sweep(path), tmp_path / "out", progress=False, outputs=["friction.mu_maen"],
                  outputs_argument="--outputs")
    assert info.value.argument == "--outputs" and "friction.mu_mean" in str(info.value)


def test_outputs_are_chosen_from_the_sweep_file_or_the_defaults(tmp_path):
    spec = parse_sweep(sweep_file(tmp_path, 'outputs = ["friction.mu_max"]\n[grid]\n"operating.torque" = [1.0]\n'))
    assert spec.outputs == ("friction.mu_max",)
    rows = [{"case": "a", "status": "done", "friction.mu_max": 0.04, "film.minimum": 3e-7, "physics.stiffness": "pem"},
            {"case": "b", "status": "failed"}]
    assert choose_outputs(spec, rows) == ("film.minimum",)                 # the defaults the cases have
    assert choose_outputs(spec, rows, spec.outputs) == ("friction.mu_max",)
    with pytest.raises(ArgumentError, match="physics.stiffness"):
        choose_outputs(spec, rows, ["physics.stiffness"])                  # not a number


def test_dask_workers_started_elsewhere_get_absolute_case_folders(tmp_path, monkeypatch):
    """Workers started in folder A; the sweep runs from folder B with a relative --out.  By default the
    cases land in B/out (absolute paths); with relative paths the workers cannot find B's folders and the
    sweep says so, naming --scheduler, before any case runs."""
    distributed = pytest.importorskip("distributed")
    a, b = tmp_path / "a", tmp_path / "b"
    a.mkdir()
    b.mkdir()
    spec = parse_sweep(sweep_file(tmp_path, '[grid]\n"operating.torque" = [100.0, 150.0]\n' + STATIC))
    monkeypatch.chdir(a)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster:
        monkeypatch.chdir(b)
        with pytest.raises(ArgumentError) as info:
            run_sweep(spec, "out", scheduler=cluster.scheduler_address, progress=False, relative_paths=True)
        assert info.value.argument == "--scheduler" and str(a) in str(info.value)
        result = run_sweep(spec, "out", scheduler=cluster.scheduler_address, progress=False)
    assert result.failed == 0
    assert result.table == b / "out" / "t" / "results.csv"
    assert sorted(p.name for p in (b / "out" / "t" / "cases").iterdir()) == sorted(c.case_id for c in spec.cases)
    assert not (a / "out").exists()
    assert os.getcwd() == str(b)
