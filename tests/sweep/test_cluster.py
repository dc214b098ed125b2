"""The cluster guide (docs/guide/sweeps.md) followed on this machine: `dask scheduler`, two `dask worker`
processes, `femgear sweep --scheduler`, through studies/dask_local_cluster.sh, which runs those steps."""

import csv
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
SCRIPT = ROOT / "studies" / "dask_local_cluster.sh"


@pytest.mark.slow
def test_the_cluster_guide_runs_a_sweep_on_a_scheduler_and_two_workers(tmp_path):
    pytest.importorskip("distributed")
    dask = Path(sys.executable).parent / "dask"
    if not dask.exists():
        dask = shutil.which("dask")
    if dask is None:
        pytest.skip("no dask command (pip install 'femgear[cluster]')")
    shared = tmp_path / "project"            # the shared folder: the same path for every process
    shared.mkdir()
    shutil.copy(ROOT / "studies" / "paper_baseline.toml", shared)
    (shared / "small.toml").write_text(
        'base = "paper_baseline.toml"\nname = "small"\noutputs = ["contact.pitch.hertz_pressure"]\n[grid]\n'
        '"operating.torque" = [100.0, 200.0]\n"operating.speed_rpm" = [200.0, 400.0]\n'
        '"physics.dynamics" = ["none"]\n"physics.coupling" = ["one-way"]\n')
    env = {**os.environ, "DASK": str(dask), "FEMGEAR": f"{sys.executable} -m femgear", "LOGS": str(tmp_path / "logs"),
           "PYTHONPATH": os.pathsep.join([str(ROOT), os.environ.get("PYTHONPATH", "")])}
    run = subprocess.run(["bash", str(SCRIPT), "small.toml", "--no-progress", "--json"], cwd=shared, env=env,
                         capture_output=True, text=True, timeout=600)
    assert run.returncode == 0, run.stderr[-3000:]
    assert "2 workers registered" in run.stderr
    out = shared / "out" / "sweeps" / "small"
    with open(out / "results.csv", newline="") as fh:
        rows = list(csv.DictReader(fh))
    assert [r["status"] for r in rows] == ["done"] * 4
    assert [(float(r["operating.torque"]), float(r["operating.speed_rpm"])) for r in rows] == [
        (100.0, 200.0), (100.0, 400.0), (200.0, 200.0), (200.0, 400.0)]
    assert len({r["worker"] for r in rows}) == 2          # both workers ran cases
    assert (out / "summary.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    scheduler_log = (tmp_path / "logs" / "scheduler.log").read_text()
    assert scheduler_log.count("Register worker") == 2
