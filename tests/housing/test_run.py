"""The housing layer through ``femgear run``: a scene without a housing runs exactly as before, the two housing
forms write their files, and bad housing input ends in one line naming the key or the file, exit 2."""

import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from tests.io.test_summary_schema import conforms

ROOT = Path(__file__).resolve().parents[2]
#: the tree the housing layer was built on (the bearing forces it reads, cherry-picked from the NVH work)
BEFORE = "c777cbb"
QUICK = ['physics.coupling="one-way"', "numerics.path_points=21", "numerics.dynamics_cycles=30",
         "numerics.transient_cycles=15"]


def _femgear(args, cwd, pythonpath=ROOT, check=True):
    env = {**os.environ, "PYTHONPATH": str(pythonpath)}
    r = subprocess.run([sys.executable, "-m", "femgear", *args], cwd=cwd, env=env, capture_output=True, text=True,
                       timeout=900)
    if check and r.returncode != 0:
        raise AssertionError(r.stderr)
    return r


def _cli(argv, capsys, cwd, monkeypatch):
    """``femgear argv`` in-process in ``cwd``: (exit code, stderr)."""
    from femgear.edge.cli import main

    monkeypatch.chdir(cwd)
    try:
        rc = main(argv)
    except SystemExit as exc:
        rc = exc.code
    return rc, capsys.readouterr().err


def _sets(overrides):
    return [a for o in overrides for a in ("--set", o)]


def _without_times(x):
    if isinstance(x, dict):
        return {k: _without_times(v) for k, v in x.items() if "seconds" not in k}
    if isinstance(x, list):
        return [_without_times(v) for v in x]
    return x


def _contains(old, new, path="results"):
    """Every key and value of ``old`` is in ``new``, bit for bit (new keys allowed)."""
    if isinstance(old, dict):
        assert isinstance(new, dict), path
        for k, v in old.items():
            assert k in new, f"{path}.{k} missing"
            _contains(v, new[k], f"{path}.{k}")
    elif isinstance(old, list):
        assert isinstance(new, list) and len(old) == len(new), path
        for i, (a, b) in enumerate(zip(old, new)):
            _contains(a, b, f"{path}[{i}]")
    else:
        assert old == new, f"{path}: {old!r} != {new!r}"


@pytest.mark.slow
def test_scene_without_housing_is_bit_identical_to_the_tree_before(tmp_path):
    """results.json of the baseline (coupled dynamics, quick resolution) from the tree before the housing layer
    (``git archive c777cbb``) and from this one: every value equal bit for bit, apart from wall times and the keys
    the housing layer adds."""
    git = subprocess.run(["git", "-C", str(ROOT), "cat-file", "-e", f"{BEFORE}^{{commit}}"], capture_output=True)
    if git.returncode != 0:
        pytest.skip(f"commit {BEFORE} is not in this clone's history")
    old_tree = tmp_path / "before"
    old_tree.mkdir()
    archive = subprocess.run(["git", "-C", str(ROOT), "archive", BEFORE, "femgear"], capture_output=True, check=True)
    subprocess.run(["tar", "-x", "-C", str(old_tree)], input=archive.stdout, check=True)
    scene = ROOT / "studies" / "paper_baseline.toml"
    args = ["run", str(scene), "--out", "run", "--no-plots", "--no-vtk", "-q", *_sets(QUICK)]
    for name, tree in (("old", old_tree), ("new", ROOT)):
        (tmp_path / name).mkdir()
        _femgear(args, tmp_path / name, tree)
    old, new = (_without_times(json.loads((tmp_path / n / "run" / "results.json").read_text())) for n in ("old", "new"))
    _contains(old, new)
    assert "housing" not in new["summary"]


def _housing(**keys):
    lines = ["[housing]"] + [f"{k} = {json.dumps(v)}" for k, v in keys.items()]
    return "\n".join(lines) + "\n"


def _scene(tmp_path, housing: str) -> Path:
    p = tmp_path / "scene.toml"
    p.write_text((ROOT / "studies" / "paper_baseline.toml").read_text() + "\n" + housing)
    return p


def _csv(path, frequencies, sensors=("S1",), seat_block=False, scale=1e-8):
    """A synthetic receptance set: each sensor and (optionally) every seat responds to every seat force through one
    damped mode at 2 kHz."""
    from femgear.physics.housing.frf import SEAT_DOFS

    rows = ["frequency,output,input,real,imag"]
    outputs = list(sensors) + (list(SEAT_DOFS) if seat_block else [])
    for f in frequencies:
        r = f / 2000.0
        h = scale / (1 - r**2 + 0.1j * r)
        for o in outputs:
            for i in SEAT_DOFS:
                v = h * (2.0 if o == i else 0.5)
                rows.append(f"{f},{o},{i},{v.real},{v.imag}")
    path.write_text("\n".join(rows) + "\n")
    return path


@pytest.mark.slow
def test_fe_housing_run_writes_its_files(tmp_path):
    scene = _scene(tmp_path, _housing(model="fe", mesh_size=0.03, modes=12, speed_points=5, orders=3,
                                      check_reduction=True))
    _femgear(["run", str(scene), "--out", "run", "-q", "--no-plots", *_sets(QUICK)], tmp_path)
    out = tmp_path / "run"
    summary = json.loads((out / "results.json").read_text())["summary"]
    conforms(summary)
    h = summary["housing"]
    assert h["coupling"] == "craig-bampton" and h["operating"]["source"] == "time integration"
    assert len(h["operating"]["sensor_acceleration"]) == 3 and len(h["sensors"]) == 4
    assert h["natural_frequencies"][0] < h["rigid_natural_frequencies"][0]
    assert "reduction_check" in h and np.isfinite(h["operating"]["sound_power_level_total"])
    for f in ("housing.json", "housing.npz", "housing_ods.pvd"):
        assert (out / f).is_file() and f.split(".")[0] in " ".join(summary["outputs"])


def test_frf_housing_receiver_and_lm_fbs(tmp_path, capsys, monkeypatch):
    """A CSV FRF set: a receiver without the seat block, LM-FBS with it; a static case runs the sweep alone."""
    f = np.linspace(20.0, 6000.0, 300)
    for block, coupling in ((False, "receiver"), (True, "lm-fbs")):
        csv = _csv(tmp_path / f"frf_{block}.csv", f, seat_block=block)
        scene = _scene(tmp_path, _housing(model="frf", frf_file=csv.name, frf_kind="receptance", speed_points=4,
                                          orders=2))
        out = f"run_{block}"
        rc, err = _cli(["run", str(scene), "--out", out, "-q", "--no-plots", "--no-vtk", *_sets(QUICK),
                        "--set", 'physics.dynamics="none"', "--set", 'physics.preset="fast"'], capsys, tmp_path,
                       monkeypatch)
        assert rc == 0, err
        summary = json.loads((tmp_path / out / "results.json").read_text())["summary"]
        conforms(summary)                                            # every key in the result schema, with its kind
        h = summary["housing"]
        assert h["coupling"] == coupling and h["operating"]["source"] == "linear"
        assert h["sensors"] == ["S1"] and max(max(a) for a in h["operating"]["sensor_acceleration"]) > 0


@pytest.mark.parametrize("case, key", [
    ("uff-dofs", "h.uff"), ("frf-frequencies", "frf.csv"), ("mesh-misses-seats", "housing.end_position"),
    ("too-many-modes", "housing.modes")])
def test_bad_housing_input_is_one_line_exit_2(tmp_path, capsys, monkeypatch, case, key):
    """A UFF file whose DOFs do not match the bearing seats, an FRF with non-increasing frequencies, a housing mesh
    that does not touch the bearing seats, a retained-mode count above the mesh's DOF: one line naming the key or
    the file, exit code 2."""
    if case == "uff-dofs":
        import pyuff

        fr = np.linspace(100.0, 1000.0, 5)
        pyuff.UFF(str(tmp_path / "h.uff")).write_sets([pyuff.prepare_58(
            binary=0, id1="FRF", func_type=4, rsp_node=101, rsp_dir=2, ref_node=9, ref_dir=2, ord_data_type=6,
            abscissa_spec_data_type=18, ordinate_spec_data_type=8, orddenom_spec_data_type=13,
            data=np.ones(5, complex), x=fr, abscissa_min=fr[0], abscissa_inc=fr[1] - fr[0])], mode="overwrite")
        housing = _housing(model="frf", frf_file="h.uff", seat_nodes=[1, 2, 3, 4])
    elif case == "frf-frequencies":
        _csv(tmp_path / "frf.csv", np.array([100.0, 300.0, 200.0]))
        housing = _housing(model="frf", frf_file="frf.csv", frf_kind="receptance")
    elif case == "mesh-misses-seats":
        housing = _housing(model="fe", end_position=0.08, mesh_size=0.03, modes=4)
    else:
        housing = _housing(model="fe", mesh_size=0.04, elements="p1", modes=100000)
    rc, err = _cli(["run", str(_scene(tmp_path, housing)), "--out", "run", "--no-plots", "--no-vtk", *_sets(QUICK),
                    "--set", 'physics.dynamics="none"'], capsys, tmp_path, monkeypatch)
    assert rc == 2, err
    lines = [ln for ln in err.strip().splitlines() if ln.strip()]
    assert len(lines) == 1 and key in lines[0], err
