"""Estimates, memory refusal, progress and Ctrl-C of the long stages (issue 26).

The refusal and Ctrl-C cases run the real CLI as a subprocess: what a shell sees (one line on
stderr, exit 2 or 130).  No timing is asserted (the benchmark ``studies/benchmarks/cost.py``
measures how fast the refusal comes).
"""

from __future__ import annotations

import logging
import os
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

import pytest

from femgear.errors import ResourceError
from femgear.perf import NOTICE, Estimate, Progress, announce
from tests.support import default_sigint

ROOT = Path(__file__).resolve().parents[2]
BASE = str(ROOT / "studies" / "paper_baseline.toml")
#: the baseline with its dynamics and coupling off: the stiffness is the first long stage
QUIET = ["--set", 'physics.dynamics="none"', "--set", 'physics.coupling="one-way"', "--set", 'physics.wear="none"']



def test_announce_refuses_over_the_budget_naming_the_key(monkeypatch):
    monkeypatch.setenv("FEMGEAR_MEMORY_GB", "1")
    with pytest.raises(ResourceError, match=r"numerics.body_level: needs about 1.86 GiB.*level 0 fits"):
        announce(Estimate("LTCA gear body", 100_000, 2e9, 30.0), "numerics.body_level", lambda b: "level 0 fits")
    announce(Estimate("LTCA gear body", 100_000, 0.5e9, 30.0), "numerics.body_level")   # fits: no error


def test_estimates_log_by_default_only_when_long(caplog, monkeypatch):
    monkeypatch.setenv("FEMGEAR_MEMORY_GB", "100")
    with caplog.at_level(logging.DEBUG, logger="femgear.cost"):
        announce(Estimate("short stage", 1000, 1e8, 1.0), "x")
        announce(Estimate("long stage", 200_000, 1e9, 60.0), "x")
    levels = {r.getMessage().split(":")[0]: r.levelno for r in caplog.records}
    assert levels == {"short stage": logging.INFO, "long stage": NOTICE}
    assert "200 k DOF" in caplog.records[1].getMessage() and "GiB" in caplog.records[1].getMessage()


def test_progress_lines_after_the_first_seconds(caplog, monkeypatch):
    import femgear.perf as perf

    monkeypatch.setattr(perf, "PROGRESS_SECONDS", 0.0)
    with caplog.at_level(logging.INFO, logger="femgear.cost"):
        p = Progress("unit loads", 3, expected_seconds=30.0)
        for i in (1, 2, 3):
            p(i)
    assert [r.getMessage().split(" (")[0] for r in caplog.records] == [
        "unit loads: 1/3", "unit loads: 2/3", "unit loads: 3/3"]
    assert all(r.levelno == NOTICE for r in caplog.records)


def test_gmsh_leaves_ctrl_c_to_python(baseline_pair):
    """gmsh's initialize() set SIGINT to SIG_DFL for good: Ctrl-C then killed femgear without a word."""
    from femgear.physics.mesh.section import gear_section

    before = signal.getsignal(signal.SIGINT)
    gear_section(baseline_pair, 1, baseline_pair.m_n / 2.5, n_teeth=3)
    assert signal.getsignal(signal.SIGINT) is before


def _env(tmp_path: Path, **extra) -> dict:
    env = {**os.environ, "FEMGEAR_CACHE": str(tmp_path / "cache"), "OPENBLAS_NUM_THREADS": "1", **extra}
    env["PYTHONPATH"] = os.pathsep.join([str(ROOT), env.get("PYTHONPATH", "")])
    return env


def test_ltca_over_the_budget_refuses_in_one_line_naming_the_level_that_fits(tmp_path, baseline_pair):
    """A memory budget between the level-0 and level-1 bodies: exit 2 before any body is built, one line."""
    from femgear.physics.ltca.level import body_estimates

    need = [max(e.memory_bytes for e in body_estimates(baseline_pair, 206e9, 0.3, k, bore_radius=(0.02, 0.02),
                                                       cached=False, order="p2-bending")) for k in (0, 1)]
    budget = 0.5 * (need[0] + need[1])
    run = subprocess.run([sys.executable, "-m", "femgear", "run", BASE, "--out", str(tmp_path / "out"), *QUIET,
                          "--set", 'physics.stiffness="ltca"', "--set", "numerics.body_level=1"],
                         env=_env(tmp_path, FEMGEAR_MEMORY_GB=f"{budget / 1e9:.4f}"), capture_output=True,
                         text=True, timeout=300)
    assert run.returncode == 2, run.stderr
    lines = run.stderr.strip().splitlines()
    assert len(lines) == 1, run.stderr
    assert lines[0].startswith("femgear: error: numerics.body_level: needs about")
    assert "numerics.body_level = 0 fits" in lines[0]
    assert not (tmp_path / "cache").exists() or not any((tmp_path / "cache").iterdir())


def _interrupt_at(tmp_path: Path, marker: str, args: list[str], wait: float = 1.0) -> tuple[int, str]:
    """Run ``femgear -v run BASE args``, send SIGINT ``wait`` s after a stderr line containing ``marker``;
    (exit code, stderr)."""
    proc = subprocess.Popen([sys.executable, "-m", "femgear", "-v", "run", BASE, "--out", str(tmp_path / "out"),
                             *QUIET, *args], env=_env(tmp_path), stderr=subprocess.PIPE, stdout=subprocess.DEVNULL,
                            text=True, preexec_fn=default_sigint)
    lines: list[str] = []
    seen = threading.Event()

    def read():
        for line in proc.stderr:
            lines.append(line)
            if marker in line:
                seen.set()
        seen.set()

    reader = threading.Thread(target=read, daemon=True)
    reader.start()
    try:
        assert seen.wait(600), f"no line with {marker!r}"
        assert proc.poll() is None, "".join(lines)
        time.sleep(wait)
        proc.send_signal(signal.SIGINT)
        rc = proc.wait(600)
    finally:
        if proc.poll() is None:
            proc.kill()
    reader.join(10)
    return rc, "".join(lines)


@pytest.mark.slow
@pytest.mark.parametrize("marker, args", [
    ("LTCA pinion body", ['--set', 'physics.stiffness="ltca"', "--set", "numerics.body_level=0"]),
    ("fe stiffness, pinion", ['--set', 'physics.stiffness="fe"']),
    ("fe3d thermal", ['--set', 'physics.thermal="fe3d"', "--set", "thermal.flank_temperature_rise=20"]),
    ("TEHL line solves", ['--set', 'physics.lubrication="tehl"']),
])
def test_ctrl_c_in_a_long_stage_prints_one_line_and_exits_130(tmp_path, marker, args):
    rc, err = _interrupt_at(tmp_path, marker, args)
    assert rc == 130, err
    assert err.strip().splitlines()[-1] == "femgear: interrupted"
    assert "Traceback" not in err


def test_interruptible_returns_the_value_and_the_error_of_the_child():
    from femgear.errors import SceneError
    from femgear.perf import interruptible

    assert interruptible(divmod, 17, 5) == (3, 2)
    with pytest.raises(SceneError, match="pinion.bore_radius: too thin") as info:
        interruptible(_raise_scene_error)
    assert info.value.key == "pinion.bore_radius"


def _raise_scene_error():
    from femgear.errors import SceneError

    raise SceneError("pinion.bore_radius", "too thin")


def _crash(sig: int):
    import faulthandler

    faulthandler.disable()          # pytest's fault handler would print the child's stack to the log
    os.kill(os.getpid(), sig)


@pytest.mark.parametrize("sig", [signal.SIGSEGV, signal.SIGKILL])
def test_a_child_that_dies_of_a_signal_is_an_out_of_memory_line(sig, capsys, monkeypatch):
    """CHOLMOD out of memory prints its error and crashes the child (SIGSEGV); the kernel's OOM killer sends
    SIGKILL: both reach the CLI as one 'out of memory' line naming the stage (exit 1), not an internal error.
    The forked path is forced: a test worker that ran CHOLMOD in-process earlier is marked unsafe to fork, and
    the crash would then hit the worker itself."""
    import argparse

    import femgear.perf as perf
    from femgear.edge.cli import _dispatch
    from femgear.perf import interruptible

    monkeypatch.setattr(perf, "_FORK_UNSAFE", [])
    monkeypatch.delenv("FEMGEAR_FORK", raising=False)

    with pytest.raises(MemoryError, match="_crash: the child process"):
        interruptible(_crash, sig)
    assert _dispatch(argparse.Namespace(func=lambda args: interruptible(_crash, sig), debug=False)) == 1
    line = capsys.readouterr().err.strip()
    assert line.startswith("femgear: error: out of memory: _crash: the child process") and "\n" not in line
