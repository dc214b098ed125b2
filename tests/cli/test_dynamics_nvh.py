"""The whine options of ``femgear dynamics``: the JSON last line, the files, the default method of --sweep."""

import json

import numpy as np

from tests.cli.test_bad_input import BASE, cli


def test_sweep_defaults_to_harmonic_balance_and_prints_its_json(tmp_path, capsys):
    rc, out, err = cli(["dynamics", BASE, "--sweep", "400:1600:4", "--json", "--out", str(tmp_path)], capsys)
    assert rc == 0
    data = json.loads(out.strip().splitlines()[-1])
    assert data["method"] == ["harmonic"] * 4 and data["warnings"] == []
    assert len(data["mesh_force_orders"]) == 4 and len(data["mesh_force_orders"][0][0]) == 6
    assert len(data["bearing_force_orders"][0]) == 4
    for key in ("json", "npz", "sweep", "orders"):
        assert (tmp_path / data["files"][key].rsplit("/", 1)[-1]).exists()
    rc, out, _ = cli(["dynamics", BASE, "--sweep", "400:400:1", "--sweep-method", "time", "--json", "--no-plots",
                      "--out", str(tmp_path)], capsys)
    assert rc == 0 and json.loads(out.strip().splitlines()[-1])["method"] == ["time"]


def test_runup_writes_its_files_and_json(tmp_path, capsys):
    rc, out, err = cli(["dynamics", BASE, "--runup", "1000:1100:0.3", "--json", "--out", str(tmp_path)], capsys)
    assert rc == 0, err
    data = json.loads(out.strip().splitlines()[-1])
    assert data["start_rpm"] == 1000.0 and abs(data["end_rpm"] - 1100.0) < 1e-6
    cuts, steady = data["cuts"]["mesh_force"], data["steady_mesh_force_orders"]
    assert len(cuts) == len(data["block_speed_rpm"]) >= 1
    assert abs(cuts[0][0][0] / steady[0][0] - 1) < 0.05
    assert {"json", "npz", "runup", "runup_bearing"} <= set(data["files"])


def test_kahraman_singh_prints_the_folds(tmp_path, capsys):
    rc, out, _ = cli(["dynamics", BASE, "--kahraman-singh", "--json", "--out", str(tmp_path)], capsys)
    data = json.loads(out.strip().splitlines()[-1])
    assert rc == 0 and len(data["hb_folds"]) == 2 and (tmp_path / "kahraman_singh_hb.png").exists()
    gap = np.array(data["amplitude_down"]) - np.array(data["amplitude_up"])   # the jump between the branches
    assert gap.max() > 0.05
