"""Sweeps: grid expansion, local pool vs Dask, failing cases, kill-and-resume."""

import csv
import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from femgear.edge.sweep import parse_sweep, run_sweep
from femgear.errors import SceneError
from tests.support import default_sigint

RIG = Path(__file__).resolve().parents[2] / "studies" / "rig15_sweep.toml"


STATIC = '"physics.dynamics" = ["none"]\n"physics.coupling" = ["one-way"]\n'   # quasi-static cases: fast



def write_sweep(tmp_path, body: str, name: str = "t") -> Path:
    base = Path(__file__).resolve().parents[2] / "studies" / "paper_baseline.toml"
    path = tmp_path / f"{name}.toml"
    path.write_text(f'base = "{base}"\nname = "{name}"\n' + body)
    return path


def numeric(rows):
    """Rows without wall-time and worker columns (those differ run to run)."""
    return [{k: v for k, v in r.items() if not k.endswith("seconds") and k != "worker"} for r in rows]


def test_rig_sweep_has_the_15_conditions():
    spec = parse_sweep(RIG)
    assert len(spec.cases) == 15
    assert len({c.case_id for c in spec.cases}) == 15
    assert spec.cases[0].overrides == ("operating.speed_rpm=100.0", "operating.torque=100.0")
    assert parse_sweep(RIG).cases == spec.cases        # ids are stable


@pytest.mark.parametrize("body,key", [("[grid]\n\"a.b\" = 3\n", "grid.a.b"), ("foo = 1\n", "foo"), ("", "grid"),
                                      ("[grid]\n\"a.b\" = [[1]]\n", "grid.a.b"), ("outputs = 3\n[grid]\n\"a\" = [1]\n", "outputs")])
def test_bad_sweep_files_name_the_key(tmp_path, body, key):
    with pytest.raises(SceneError) as info:
        parse_sweep(write_sweep(tmp_path, body))
    assert info.value.key == key


def rig_spec(tmp_path, full: bool):
    """The 15 rig conditions, with the baseline's coupled physics (full) or quasi-static."""
    grid = RIG.read_text().split("[grid]", 1)[1]
    return parse_sweep(write_sweep(tmp_path, "[grid]" + grid + ("" if full else STATIC), "rig15"))


@pytest.mark.slow
@pytest.mark.parametrize("full", [False, True])
def test_local_pool_and_dask_cluster_give_identical_results(tmp_path, full):
    distributed = pytest.importorskip("distributed")
    spec = rig_spec(tmp_path, full)
    local = run_sweep(spec, tmp_path / "local", workers=2, progress=False)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster:
        dask = run_sweep(spec, tmp_path / "dask", scheduler=cluster.scheduler_address, progress=False)
    assert local.failed == dask.failed == 0
    assert numeric(local.rows) == numeric(dask.rows)
    with open(local.table) as fh:
        assert len(list(csv.DictReader(fh))) == 15


def block_case(tmp_path, spec, index: int, out: str = "out") -> str:
    """Put a file where case ``index`` must rename its finished folder: that case fails when it finishes
    (a case folder that cannot be written), a failure only running the case can find."""
    cases = tmp_path / out / spec.name / "cases"
    cases.mkdir(parents=True)
    blocked = spec.cases[index].case_id
    (cases / blocked).write_text("in the way")
    return blocked


def test_a_failing_case_is_reported_and_the_others_complete(tmp_path):
    spec = parse_sweep(write_sweep(tmp_path, '[grid]\n"operating.torque" = [100.0, 150.0, 200.0]\n' + STATIC))
    blocked = block_case(tmp_path, spec, 1)
    result = run_sweep(spec, tmp_path / "out", workers=2, progress=False)
    status = {r["case"]: r for r in result.rows}
    assert [status[c.case_id]["status"] for c in spec.cases] == ["done", "failed", "done"]
    assert "Error" in status[blocked]["error"]
    assert result.failed == 1
    # the failed case leaves no finished folder, only its error record
    cases = tmp_path / "out" / "t" / "cases"
    assert sorted(p.name for p in cases.iterdir() if p.name.endswith(".error.json")) == [blocked + ".error.json"]


@pytest.mark.parametrize("body,key", [
    ('[grid]\n"operating.sped_rpm" = [100.0, 200.0]\n' + STATIC, "grid.operating.sped_rpm"),          # a typo
    ('[grid]\n"operating.torque" = [100.0, 0.0]\n' + STATIC, "grid.operating.torque"),                # range
    ('[grid]\n"operating.speed_rpm" = ["fast"]\n' + STATIC, "grid.operating.speed_rpm"),              # type
    ('[grid]\n"operating.torque" = [100.0]\n' + STATIC + '[[case]]\n"pair.no_such_key" = 1\n',
     "case[0].pair.no_such_key"),
])
def test_bad_cases_are_refused_before_any_case_runs(tmp_path, body, key):
    """Every case's scene is validated first: one SceneError naming the key as the sweep file spells it,
    and nothing is computed (no output folder)."""
    spec = parse_sweep(write_sweep(tmp_path, body))
    with pytest.raises(SceneError) as info:
        run_sweep(spec, tmp_path / "out", workers=1, progress=False)
    assert info.value.key == key
    assert not (tmp_path / "out").exists()


def test_cli_refuses_a_grid_typo_with_one_line_and_exit_2(tmp_path):
    path = write_sweep(tmp_path, '[grid]\n"operating.torque" = [100.0, 150.0]\n"operating.sped_rpm" = [1.0]\n')
    run = subprocess.run([sys.executable, "-m", "femgear", "sweep", str(path), "--out", str(tmp_path / "o")],
                         capture_output=True, text=True)
    assert run.returncode == 2
    assert run.stderr.strip().splitlines() == ["femgear: error: grid.operating.sped_rpm: unknown key (did you "
                                               "mean operating.speed_rpm?) (checked before any case ran)"]
    assert not (tmp_path / "o").exists()


def done_cases(cases: Path) -> list[Path]:
    """``case.json`` of the finished case folders.  A case writes its ``case.json`` inside its hidden temporary
    folder ``.<id>.tmp-*`` and then renames the folder; pathlib's ``*`` matches dot-names too, so a plain
    ``glob("*/case.json")`` also sees a case caught between the two steps (on a loaded machine the window is
    long enough to be hit), which the sweep rightly does not count as finished."""
    return [p for p in cases.glob("*/case.json") if not p.parent.name.startswith(".")] if cases.exists() else []


def test_killed_sweep_resumes_without_recomputing(tmp_path):
    speeds = ", ".join(str(float(s)) for s in range(100, 900, 100))
    path = write_sweep(tmp_path, '[grid]\n"physics.wear" = ["archard"]\n"wear.cycles" = [2e6]\n' + STATIC +
                                 f'"operating.speed_rpm" = [{speeds}]\n')
    out = tmp_path / "out"
    cmd = [sys.executable, "-m", "femgear", "sweep", str(path), "--out", str(out), "--workers", "1",
           "--no-progress", "--json"]
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, start_new_session=True,
                            preexec_fn=default_sigint)
    cases = out / "t" / "cases"
    deadline = time.time() + 600      # ends as soon as two cases are done; a loaded machine may need minutes
    while time.time() < deadline and len(done_cases(cases)) < 2:
        time.sleep(0.05)
    os.killpg(proc.pid, signal.SIGKILL)
    proc.wait()
    finished = {p.parent.name: p.stat().st_mtime_ns for p in done_cases(cases)}
    assert 2 <= len(finished) < 8, "the sweep was not interrupted midway"
    rerun = subprocess.run(cmd, capture_output=True, text=True, check=True)
    summary = json.loads(rerun.stdout.strip().splitlines()[-1])
    assert summary["skipped"] == len(finished) and summary["ran"] == 8 - len(finished)
    assert summary["failed"] == 0
    for name, mtime in finished.items():   # finished cases were not recomputed
        assert (cases / name / "case.json").stat().st_mtime_ns == mtime
    assert len(done_cases(cases)) == 8
    assert not list(cases.glob(".*.tmp-*"))      # partial outputs of the killed case are gone


def _start_slow_sweep(tmp_path, n: int = 6):
    speeds = ", ".join(str(float(s)) for s in range(100, 100 * (n + 1), 100))
    path = write_sweep(tmp_path, '[grid]\n"physics.wear" = ["archard"]\n"wear.cycles" = [2e6]\n' + STATIC +
                                 f'"operating.speed_rpm" = [{speeds}]\n')
    out = tmp_path / "out"
    cmd = [sys.executable, "-m", "femgear", "sweep", str(path), "--out", str(out), "--workers", "1", "--json"]
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, start_new_session=True,
                            preexec_fn=default_sigint)
    cases = out / "t" / "cases"
    deadline = time.time() + 600      # ends as soon as one case is done; a loaded machine may need minutes
    while time.time() < deadline and len(done_cases(cases)) < 1:
        time.sleep(0.05)
    return proc, out / "t"


@pytest.mark.parametrize("how", ["SIGINT to the process group (Ctrl-C)", "SIGTERM to the parent"])
def test_interrupted_sweep_stops_cleanly_with_a_consistent_table(tmp_path, how):
    """Pending cases are cancelled, the running one finishes, results.csv lists exactly the case folders."""
    proc, out = _start_slow_sweep(tmp_path)
    if how.startswith("SIGINT"):
        os.killpg(proc.pid, signal.SIGINT)
    else:
        os.kill(proc.pid, signal.SIGTERM)
    stdout, stderr = proc.communicate(timeout=120)
    assert proc.returncode == 130, stderr
    assert "Traceback" not in stderr and "interrupted" in stderr
    folders = {p.name for p in (out / "cases").iterdir() if p.is_dir()}
    with open(out / "results.csv") as fh:
        listed = {r["case"] for r in csv.DictReader(fh) if r["status"] == "done"}
    assert listed == folders
    assert 1 <= len(folders) < 6, "pending cases were not cancelled"
    assert not list((out / "cases").glob(".*.tmp-*"))          # the running case finished, not abandoned


def test_a_sweep_with_failed_cases_exits_1_and_says_how_many(tmp_path):
    path = write_sweep(tmp_path, '[grid]\n"operating.torque" = [100.0, 150.0]\n' + STATIC)
    block_case(tmp_path, parse_sweep(path), 1, out="o")
    run = subprocess.run([sys.executable, "-m", "femgear", "sweep", str(path), "--out", str(tmp_path / "o"),
                          "--workers", "1"], capture_output=True, text=True)
    assert run.returncode == 1
    assert "1 of 2 cases failed" in run.stderr.strip().splitlines()[-1]
    assert "Traceback" not in run.stderr
