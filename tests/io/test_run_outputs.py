"""One writer: every file a run writes is listed in results.json (``summary.outputs``) and every listed file
exists; the μ figures carry the level that produced them, and the power loss integrates the run's own μ."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[2]
BASE = ROOT / "studies" / "paper_baseline.toml"


@pytest.fixture(scope="module")
def baseline(tmp_path_factory):
    """The paper's baseline (fast preset) written by ``femgear run`` with figures and ParaView output."""
    from femgear.edge.cli import main

    out = tmp_path_factory.mktemp("outputs") / "run"
    assert main(["-q", "run", str(BASE), "--out", str(out), "--set", 'physics.preset="fast"']) == 0
    return out, json.loads((out / "results.json").read_text())


def test_every_file_written_is_listed_and_every_listed_file_exists(baseline):
    out, d = baseline
    on_disk = {p.resolve() for p in out.rglob("*") if p.is_file()}
    listed = {Path(v).resolve() for v in d["summary"]["outputs"].values()}
    assert on_disk == listed, (sorted(map(str, on_disk - listed)), sorted(map(str, listed - on_disk)))
    kinds = {p.suffix for p in listed}
    assert {".json", ".npz", ".png", ".pvd", ".vtu"} <= kinds      # JSON, NPZ, figures and ParaView all there
    assert not any(p.name.startswith(".") for p in on_disk)        # no temporary file left


def test_mu_fields_are_labelled_with_their_level(baseline):
    """One μ per meaning: μ(u) of the run's lubrication level along the path; the flash temperature and the power loss
    use it and say so; the dynamics carries a table factor, not a second μ; ISO's μ_m is the standard's (``method``)."""
    _, d = baseline
    s = d["summary"]
    level = d["scene"]["physics"]["lubrication"]
    assert s["friction"]["level"] == level
    assert s["power_loss"]["friction_level"] == level and s["flash_temperature"]["friction_level"] == level
    assert "friction_coefficient" not in s["dynamics"] and "friction_factor" in s["dynamics"]
    assert s["scuffing"]["method"].startswith("ISO/TS 6336-20")

    def blocks(node, path=""):
        if isinstance(node, dict):
            yield path, node
            for k, v in node.items():
                yield from blocks(v, f"{path}.{k}")

    for path, block in blocks(s):
        mu_keys = [k for k in block if k.startswith("mu_") or k.endswith("_mu") or "friction_coefficient" in k]
        if mu_keys and not path.startswith(".coupling"):
            assert {"level", "friction_level", "method"} & set(block), f"{path}: {mu_keys} without a level"


def test_power_loss_integrates_the_runs_own_mu(baseline):
    """The loss's μ(u) is the run's (the coupled μ at the dynamic load), not a formula μ at the static load:
    on the helical pair's path grid its mean is the friction block's mean to rounding."""
    _, d = baseline
    s = d["summary"]
    mu = np.asarray(d["along_path"]["friction_coefficient"], float)
    assert s["power_loss"]["mean_friction_coefficient"] == pytest.approx(float(np.mean(mu)), rel=1e-12)
    assert s["power_loss"]["mean_friction_coefficient"] == pytest.approx(s["friction"]["mu_mean"], rel=1e-12)


def test_json_summary_of_the_cli_lists_the_same_files(baseline, tmp_path, capsys):
    """``--json`` prints results.json's summary (outputs included), written by the one writer."""
    from femgear.edge.cli import main

    out = tmp_path / "j"
    assert main(["-q", "run", str(BASE), "--out", str(out), "--no-vtk", "--no-plots", "--json",
                 "--set", 'physics.preset="fast"', "--set", 'physics.dynamics="none"',
                 "--set", 'physics.coupling="one-way"']) == 0
    printed = json.loads(capsys.readouterr().out.strip().splitlines()[-1])
    written = json.loads((out / "results.json").read_text())["summary"]
    assert printed["outputs"] == written["outputs"]
    assert {Path(v).name for v in printed["outputs"].values()} == {p.name for p in out.iterdir()}


def test_the_writer_computes_nothing(tmp_path, monkeypatch):
    """write_run only reads the RunResult: the driver's rating, contact figures (flash temperature, power loss),
    body sections, LTCA maps and the lubrication solvers all raise while it writes every file."""
    from femgear.case import build_case
    from femgear.edge.io.run import write_run
    from femgear.pipeline import run_case
    from femgear.scene import load_scene

    scene = load_scene(BASE, ['physics.preset="fast"', 'physics.dynamics="none"', 'physics.coupling="one-way"'])
    result = run_case(build_case(scene))
    assert result.figures is not None and result.figures.friction_level == scene.physics.lubrication

    def boom(*a, **k):
        raise AssertionError("the writer computed something")

    for name in ("femgear.rate.rate_case", "femgear.rate.contact_figures", "femgear.rate.power_loss",
                 "femgear.rate.pitting_of", "femgear.stages.body_sections", "femgear.stages.ltca_maps",
                 "femgear.physics.body.thermal.gear_thermo_elastic", "femgear.physics.ltca.maps.load_maps",
                 "femgear.levels.lubrication.lubrication_solver", "femgear.levels.contact.contact_pass",
                 "femgear.physics.contact.path.contact_along_path", "femgear.case.build_case"):
        monkeypatch.setattr(name, boom)
    summary, files = write_run(result, tmp_path, plots=True, vtk=True)
    assert summary["power_loss"]["mean_loss"] == result.figures.power_loss.mean_loss
    assert {p.resolve() for p in tmp_path.rglob("*") if p.is_file()} == {p.resolve() for p in files.values()}
