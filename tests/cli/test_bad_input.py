"""The bad-input matrix of issue 17: every expected failure ends in ONE line on stderr that
names the key or argument, exit 2 (input) or 1 (solver), no traceback, nothing lost.

Each case runs the real CLI entry point (:func:`femgear.edge.cli.main`) in-process; a few run
as subprocesses to check what a shell sees.
"""

from __future__ import annotations

import errno
import json
import os
import stat
import subprocess
import sys
import time
from pathlib import Path

import pytest

from femgear.edge.cli import main

ROOT = Path(__file__).resolve().parents[2]
BASE = str(ROOT / "studies" / "paper_baseline.toml")
#: a cheap scene: quasi-static pass with the fast preset (≈ 0.3 s)
CHEAP = ["--set", 'physics.preset="fast"', "--set", 'physics.dynamics="none"', "--set", 'physics.coupling="one-way"']


def cli(argv: list[str], capsys) -> tuple[int, str, str]:
    """Run ``femgear argv``; (exit code, stdout, stderr). argparse errors exit through SystemExit."""
    try:
        rc = main(argv)
    except SystemExit as exc:
        rc = exc.code
    out, err = capsys.readouterr()
    return rc, out, err


def assert_one_line(err: str, *names: str) -> str:
    lines = err.strip().splitlines()
    assert len(lines) == 1, f"expected one line, got:\n{err}"
    assert "Traceback" not in err
    for name in names:
        assert name in lines[0], f"{name!r} not named in: {lines[0]}"
    return lines[0]


def _binary(tmp_path: Path) -> str:
    path = tmp_path / "scene.bin"
    path.write_bytes(bytes(range(256)) * 4)
    return str(path)


INPUT_ERRORS = [
    # issue 38: the oil library and the one roughness description
    (["info", BASE, "--set", 'oil.name="vg100"'], "oil.name"),
    (["info", BASE, "--set", "roughness.ra=[0.0, 0.4e-6]"], "roughness.ra"),
    (["info", BASE, "--set", "roughness.ra=[0.4, 0.4]"], "roughness.ra"),
    (["info", BASE, "--set", "roughness.ra=[0.4e-6, 0.4e-6]", "--set", "roughness.rq=[0.2e-6, 0.2e-6]"],
     "roughness.rq"),
    (["info", BASE, "--set", 'roughness.state="worn"'], "roughness.state"),
    (["info", BASE, "--set", "roughness.run_in_factor=0.7"], "roughness.run_in_factor"),
    (["info", BASE, "--set", 'roughness.state="run-in"', "--set", "roughness.run_in_factor=1.4"],
     "roughness.run_in_factor"),
    (["info", BASE, "--set", 'roughness.contact="hertz"'], "roughness.contact"),
    (["info", BASE, "--set", 'roughness.fluid_film="gap"'], "roughness.fluid_film"),
    # the cases of issue 17
    (["info", BASE, "--set", "operating.torque=inf"], "operating.torque"),
    (["info", BASE, "--set", "pair.normal_module=inf"], "pair.normal_module"),
    (["info", BASE, "--set", "operating.speed_rpm=1e6"], "operating.speed_rpm"),
    (["info", "{folder}"], "is a folder"),
    (["info", "{binary}"], "not a text file"),
    (["ehl", "point", "--M", "-1", "--L", "10"], "--M"),
    (["ehl", "line", "--M", "10", "--L", "10", "--level", "-1"], "--level"),
    (["info", BASE, "--set", 'pinion.teeth="31"'], "pinion.teeth"),
    (["info", BASE, "--set", "operating.speed_rpm=true"], "operating.speed_rpm"),
    (["run", BASE, "--set", 'meta.name="../x"'], "meta.name"),
    # more
    (["info", BASE, "--set", "operating.torque=nan"], "operating.torque"),
    (["info", BASE, "--set", "operating.torque=-inf"], "operating.torque"),
    (["info", BASE, "--set", "pinion.teeth=31.0"], "pinion.teeth"),
    (["info", BASE, "--set", "pinion.mass=[1, 2]"], "pinion.mass"),
    (["info", BASE, "--set", "oil.viscosty=0.1"], "oil.viscosty"),
    (["info", BASE, "--set", "operating.torque"], "operating.torque"),
    (["info", BASE, "--set", "pair.normal_module.x=1"], "pair.normal_module"),
    (["info", BASE, "--set", 'physics.lubrication="magic"'], "physics.lubrication"),
    (["info", BASE, "--set", 'meta.name="a/b"'], "meta.name"),
    (["info", "{missing}"], "not found"),
    (["info", "{empty}"], "pair"),
    (["ehl", "point", "--M", "10", "--L", "nan"], "--L"),
    (["ehl", "point", "--M", "inf", "--L", "10"], "--M"),
    (["ehl", "point", "--M", "10", "--L", "10", "--ellipticity", "0"], "--ellipticity"),
    (["ehl", "point", "--M", "10", "--L", "10", "--method", "multigrid"], "--method"),
    (["ehl", "point", "--M", "10", "--L", "10", "--level", "0"], "--level"),
    (["ehl", "point", "--M", "ten", "--L", "10"], "--M"),
    (["ehl", "line", "--M", "10", "--L", "10", "--level", "1000"], "--level"),
    (["ehl", "line", "--M", "10", "--L", "10", "--out", "{file}"], "--out"),
    (["sweep", str(ROOT / "studies" / "rig15_sweep.toml"), "--workers", "0"], "--workers"),
    (["sweep", "{folder}"], "is a folder"),
    (["dynamics", BASE, "--dt", "-1e-6"], "--dt"),
    (["dynamics", BASE, "--cycles", "inf"], "--cycles"),
    (["dynamics", BASE, "--transient", "200"], "--transient"),
    (["dynamics", BASE, "--sweep", "100:x:3"], "--sweep"),
    (["dynamics", BASE, "--sweep", "500:100:3"], "--sweep"),
    (["dynamics", BASE, "--sweep", "0:1000:5"], "--sweep"),                  # a sweep over 0 rpm
    (["dynamics", BASE, "--sweep", "500:600:2", "--harmonics", "1"], "--harmonics"),
    (["dynamics", BASE, "--runup", "1000:500:2"], "--runup"),                # end speed below the start speed
    (["dynamics", BASE, "--runup", "500:500:2"], "--runup"),
    (["dynamics", BASE, "--runup", "500:1000:0"], "--runup"),                # zero duration
    (["dynamics", BASE, "--runup", "0:1000:2"], "--runup"),
    (["dynamics", BASE, "--runup", "500:1000"], "--runup"),
    (["dynamics", BASE, "--runup", "500:1e6:2"], "--runup"),                 # above the pair's burst speed
    (["dynamics", BASE, "--runup", "500:600:1", "--revolutions", "0"], "--revolutions"),
    (["dynamics", BASE, "--runup", "500:600:0.01"], "--runup"),             # shorter than one tracking block
    (["dynamics", BASE, "--sweep", "500:600:2", "--runup", "500:600:1"], "--runup"),
    (["dynamics", BASE, "--level", "rigid"], "--level"),
    (["run", BASE, "--out", "{file}/sub"], "--out"),
    (["nonsense"], "nonsense"),
]


@pytest.mark.parametrize("argv,name", INPUT_ERRORS, ids=[" ".join(a[:1] + a[2:])[:60] for a, _ in INPUT_ERRORS])
def test_bad_input_ends_in_one_line_naming_it_exit_2(argv, name, tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)       # anything written by mistake lands here, and is checked
    (tmp_path / "empty.toml").write_text("")
    (tmp_path / "a_file").write_text("x")
    subs = {"{folder}": str(ROOT / "studies"), "{binary}": _binary(tmp_path), "{missing}": "nope.toml",
            "{empty}": "empty.toml", "{file}": str(tmp_path / "a_file")}
    argv = [next((a.replace(k, v) for k, v in subs.items() if k in a), a) for a in argv]
    rc, out, err = cli(argv, capsys)
    assert rc == 2
    assert_one_line(err, name)
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(["empty.toml", "a_file", "scene.bin"])


def test_level_40_is_refused_with_a_memory_estimate_before_allocating(capsys):
    t0 = time.perf_counter()
    rc, _, err = cli(["ehl", "line", "--M", "10", "--L", "10", "--level", "40"], capsys)
    line = assert_one_line(err, "--level", "GiB", "budget")
    assert rc == 2 and time.perf_counter() - t0 < 2.0, line


def test_level_estimate_follows_the_budget(capsys, monkeypatch):
    """The budget is FEMGEAR_MEMORY_GB when set; the message names the finest level that fits."""
    monkeypatch.setenv("FEMGEAR_MEMORY_GB", "0.5")
    rc, _, err = cli(["ehl", "point", "--M", "10", "--L", "10", "--level", "4"], capsys)
    assert rc == 2 and "finest level that fits is 3" in assert_one_line(err, "--level")


def _never(*args, **kwargs):
    raise AssertionError("the computation started before the output folder was checked")


@pytest.mark.parametrize("command", [["run", BASE], ["dynamics", BASE], ["ehl", "line", "--M", "10", "--L", "10"]])
def test_unwritable_out_is_refused_before_any_computation(command, tmp_path, capsys, monkeypatch):
    import femgear.edge.run
    import femgear.system.dynamics

    monkeypatch.setattr(femgear.edge.run, "run_case", _never)
    monkeypatch.setattr(femgear.system.dynamics, "run_dynamics", _never)
    monkeypatch.setitem(sys.modules, "femgear.physics.ehl.fe.line", None)   # the EHL solver is not even imported
    blocker = tmp_path / "file"
    blocker.write_text("")
    for out in (str(blocker / "sub"), "/proc/femgear-cannot-write"):
        rc, _, err = cli(command + ["--out", out], capsys)
        assert rc == 2
        assert_one_line(err, "--out", out)


def test_full_disk_leaves_no_corrupt_file(tmp_path, capsys, monkeypatch):
    """A writer that raises ENOSPC: the previous results.json stays intact, no temporary files, one line."""
    out = tmp_path / "run"
    assert cli(["run", BASE, *CHEAP, "--out", str(out), "--no-plots", "--no-vtk", "-q"], capsys)[0] == 0
    before = (out / "results.json").read_bytes()

    def full_disk(fd):
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))

    monkeypatch.setattr(os, "fsync", full_disk)
    rc, _, err = cli(["run", BASE, *CHEAP, "--set", "operating.torque=150", "--out", str(out), "--no-vtk"], capsys)
    assert rc == 2
    assert_one_line(err, "No space left on device")
    assert (out / "results.json").read_bytes() == before
    json.loads(before)
    assert not [p.name for p in out.iterdir() if p.name.startswith(".")]


def test_meta_name_cannot_write_outside_out(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    for name in ('"../x"', '"/tmp/x"', '".hidden"', '"a/../../x"'):
        rc, _, err = cli(["run", BASE, *CHEAP, "--set", f"meta.name={name}"], capsys)
        assert rc == 2
        assert_one_line(err, "meta.name")
    assert list(tmp_path.iterdir()) == []


def test_solver_failure_exits_1_in_one_line(tmp_path, capsys, monkeypatch):
    import femgear.edge.run
    from femgear.errors import ConvergenceError

    def diverge(*args, **kwargs):
        raise ConvergenceError("coupling", "no convergence in 30 iterations", {"mesh_force_change": [0.1, 0.2]})

    monkeypatch.setattr(femgear.edge.run, "run_case", diverge)
    rc, _, err = cli(["run", BASE, "--out", str(tmp_path)], capsys)
    assert rc == 1
    assert_one_line(err, "coupling", "mesh_force_change=0.2")
    with pytest.raises(ConvergenceError):   # --debug: the traceback is shown (the exception propagates)
        main(["--debug", "run", BASE, "--out", str(tmp_path)])


def test_unexpected_errors_are_one_line_too(tmp_path, capsys, monkeypatch):
    import femgear.edge.run

    monkeypatch.setattr(femgear.edge.run, "run_case", lambda *a, **k: 1 / 0)
    rc, _, err = cli(["run", BASE, "--out", str(tmp_path)], capsys)
    assert rc == 1
    assert "--debug" in assert_one_line(err, "ZeroDivisionError")


@pytest.mark.parametrize("override,key", [("pinion.eccentricity=1e-3", "pinion.eccentricity"),
                                          ("operating.torque=20000.0", "operating.torque"),
                                          ("operating.ambient_temperature=450.0", "operating.ambient_temperature")])
def test_implausible_but_valid_inputs_run_with_a_warning(override, key, capsys):
    rc, out, err = cli(["info", BASE, "--set", override], capsys)
    assert rc == 0 and "eps_alpha" in out
    assert key in assert_one_line(err, "warning")
    rc, _, err = cli(["-q", "info", BASE, "--set", override], capsys)
    assert rc == 0 and err == ""


def test_version_and_verbosity(tmp_path, capsys):
    rc, out, _ = cli(["--version"], capsys)
    assert rc == 0 and out.startswith("femgear ")
    rc, _, err = cli(["run", BASE, "--out", str(tmp_path), "--no-plots", "--no-vtk", "-v",
                      "--set", 'physics.preset="fast"'], capsys)
    assert rc == 0 and "coupling pass 1" in err


def test_results_files_have_mode_0644(tmp_path, capsys):
    old = os.umask(0o077)
    try:
        rc, _, _ = cli(["run", BASE, *CHEAP, "--out", str(tmp_path / "r"), "-q"], capsys)
    finally:
        os.umask(old)
    assert rc == 0
    files = [p for p in (tmp_path / "r").rglob("*") if p.is_file()]
    assert len(files) >= 4
    assert {stat.S_IMODE(p.stat().st_mode) for p in files} == {0o644}


def test_a_shell_sees_one_line_and_the_exit_code(tmp_path):
    run = subprocess.run([sys.executable, "-m", "femgear", "info", BASE, "--set", "operating.torque=inf"],
                         capture_output=True, text=True)
    assert run.returncode == 2 and run.stdout == ""
    assert_one_line(run.stderr, "operating.torque", "finite")
    run = subprocess.run([sys.executable, "-m", "femgear", "ehl", "point", "--M"], capture_output=True, text=True)
    assert run.returncode == 2
    assert_one_line(run.stderr, "--M")


# --- issue 25 item 6: unit slips, checked in engineering terms before any computing ---------------------------

MARINE = str(ROOT / "studies" / "zoo" / "marine.toml")
#: the slips of issue 25 (and their kin): each refused on the key typed, with the likely unit
UNIT_SLIPS = [("pair.normal_module=6", "pair.normal_module", "6 mm"),
              ("pair.face_width=120", "pair.face_width", "120 mm"),
              ("oil.pressure_viscosity=20", "oil.pressure_viscosity", "GPa⁻¹"),
              ("oil.viscosity=39.7", "oil.viscosity", "cSt"),
              ("gear.eccentricity=1.0", "gear.eccentricity", "µm"),
              ("operating.speed_rpm=1e-6", "operating.speed_rpm", "pitch-line speed"),
              ("operating.torque=2e7", "operating.torque", "σ_H0"),
              ("operating.ambient_temperature=40.0", "operating.ambient_temperature", "°C")]


@pytest.mark.parametrize("command", ["info", "run"])
@pytest.mark.parametrize("scene", [BASE, MARINE], ids=["baseline", "marine"])
@pytest.mark.parametrize("override,key,unit", UNIT_SLIPS, ids=[s[1] for s in UNIT_SLIPS])
def test_unit_slips_exit_2_naming_the_key_before_any_computing(command, scene, override, key, unit, tmp_path, capsys):
    argv = [command, scene, "--set", override] + (["--out", str(tmp_path / "o")] if command == "run" else [])
    t0 = time.perf_counter()
    rc, out, err = cli(argv, capsys)
    elapsed = time.perf_counter() - t0
    assert rc == 2 and out == ""
    line = assert_one_line(err, key, unit)
    assert line.startswith(f"femgear: error: {key}:")
    assert elapsed < 2.0, f"{elapsed:.2f} s: the refusal must come before any computing"
    assert not (tmp_path / "o").exists() or not any((tmp_path / "o").iterdir())


@pytest.mark.parametrize("scene", [BASE, MARINE], ids=["baseline", "marine"])
@pytest.mark.parametrize("override,key", [("oil.pressure_viscosity=3e-9", "oil.pressure_viscosity"),
                                          ("operating.speed_rpm=2.0", "operating.speed_rpm"),
                                          ("oil.viscosity=2.0", "oil.viscosity")])
def test_unusual_but_possible_inputs_warn_in_one_line_and_run(scene, override, key, capsys):
    rc, out, err = cli(["info", scene, "--set", override], capsys)
    assert rc == 0 and "eps_alpha" in out
    assert key in assert_one_line(err, "warning")


@pytest.mark.parametrize("sweep", ["1e-6:500:3", "100:1e6:3"])
def test_a_dynamics_sweep_outside_the_speed_range_names_sweep(sweep, capsys):
    t0 = time.perf_counter()
    rc, out, err = cli(["dynamics", BASE, "--sweep", sweep], capsys)
    assert rc == 2 and "rpm" in assert_one_line(err, "--sweep")
    assert time.perf_counter() - t0 < 2.0


def test_an_unusual_input_warns_once_in_a_run_too(tmp_path, capsys):
    rc, _, err = cli(["run", BASE, *CHEAP, "--set", "oil.pressure_viscosity=3e-9", "--out", str(tmp_path / "r"),
                      "--no-plots", "--no-vtk"], capsys)
    assert rc == 0
    assert "oil.pressure_viscosity" in assert_one_line(err, "warning")
