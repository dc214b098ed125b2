"""The rating takes K_v from the run's dynamics and K_Hβ, K_Hα from its LTCA, each with its source and ISO's value
beside in results.json; ``rating.load_factors = "iso"`` and a given factor switch back (issue 42 item 6)."""

import json
from pathlib import Path

import numpy as np
import pytest

from femgear.edge.cli import main

ROOT = Path(__file__).resolve().parents[2]
FZG = ROOT / "studies" / "zoo" / "fzg_c14.toml"
INDUSTRIAL = ROOT / "studies" / "zoo" / "industrial.toml"
SHORT = ["--set", "numerics.dynamics_cycles=20", "--set", "numerics.transient_cycles=10"]


def _run(tmp_path, scene, *sets):
    args = [x for s in sets for x in ("--set", s)]
    assert main(["-q", "run", str(scene), "--out", str(tmp_path), "--no-plots", *SHORT, *args]) == 0
    return json.loads((tmp_path / "results.json").read_text())["summary"]


def test_results_carry_the_three_factors_with_their_sources_from_dynamics_and_ltca(tmp_path):
    s = _run(tmp_path, FZG, 'physics.stiffness="ltca"', 'physics.dynamics="lumped"', 'physics.coupling="one-way"')
    lf = s["load_factors"]
    assert lf["K_v"]["source"] == "femgear dynamics" and lf["K_v"]["iso_method"] == "ISO 6336-1 method B"
    assert lf["K_Hbeta"]["source"] == "femgear LTCA" and lf["K_Hbeta"]["iso_method"] == "ISO 6336-1 method C"
    assert lf["K_Halpha"]["source"] == "femgear LTCA" and lf["K_Halpha"]["iso_method"] == "ISO 6336-1 method B"
    for k in ("K_v", "K_Hbeta", "K_Halpha"):
        assert lf[k]["value"] == lf[k]["femgear"] >= 1 and lf[k]["iso"] >= 1
    a = s["dynamics"]["amplitudes"]
    assert lf["K_v"]["value"] == pytest.approx(a["mesh_force.L.max"] / a["mesh_force.L.mean"], rel=1e-12)
    r = s["rating"]                                                   # the pitting rating used them
    assert (r["K_v"], r["K_Hbeta"], r["K_Halpha"]) == (lf["K_v"]["value"], lf["K_Hbeta"]["value"],
                                                       lf["K_Halpha"]["value"])


def test_iso_switch_and_given_factors(tmp_path):
    base = ['physics.dynamics="lumped"', 'physics.coupling="one-way"']
    iso = _run(tmp_path / "iso", FZG, *base, 'rating.load_factors="iso"')["load_factors"]
    assert all(iso[k]["source"].startswith("ISO 6336-1") and iso[k]["value"] == iso[k]["iso"]
               for k in ("K_v", "K_Hbeta", "K_Halpha"))
    given = _run(tmp_path / "given", FZG, *base, "rating.dynamic_factor=1.2")["load_factors"]
    assert given["K_v"]["source"] == "scene" and given["K_v"]["value"] == 1.2
    assert given["K_v"]["femgear"] is not None                         # femgear's beside it all the same


def test_quasi_static_dynamic_factor_is_one():
    """Constant mesh stiffness, no errors, no friction, 20 rpm: the dynamic mesh force is the static one (K_v = 1 to 1e-4), and the
    sweep's K_v rises towards the mesh resonance as ISO's does (Newton on the SDOF mesh: no overload without
    excitation)."""
    from femgear.case import build_case
    from femgear.rate import dynamic_factor_curve, dynamics_K_v
    from femgear.scene import load_scene
    from femgear.system.dynamics.sweep import speed_sweep

    case = build_case(load_scene(INDUSTRIAL, ['physics.stiffness="constant"', 'physics.lubrication="none"']))
    sw = speed_sweep(case, [20.0], cycles=30, measure=10)
    assert dynamics_K_v({k: v[0] for k, v in sw.amplitudes.items()})[0] == pytest.approx(1.0, abs=1e-4)
    case = build_case(load_scene(INDUSTRIAL))
    sw = speed_sweep(case, [2000.0, 16000.0], cycles=40, measure=20)
    kv = dynamic_factor_curve(case, sw.speed_rpm, sw.amplitudes)
    assert kv.femgear.shape == (1, 2) and np.all(np.diff(kv.femgear[0]) > 0) and kv.iso[1] > kv.iso[0]
    assert kv.N == pytest.approx(sw.speed_rpm / kv.n_E1)


def test_sweep_writes_the_dynamic_factor_figure_and_json(tmp_path, capsys):
    rc = main(["-q", "dynamics", str(INDUSTRIAL), "--sweep", "3000:6000:2", "--cycles", "30", "--transient", "15",
               "--out", str(tmp_path), "--json"])
    assert rc == 0
    out = json.loads(capsys.readouterr().out.strip().splitlines()[-1])
    kv = out["dynamic_factor"]
    assert len(kv["iso_method_b"]) == 2 and len(kv["femgear"]) == 1 and kv["resonance_speed_rpm"] > 0
    assert Path(out["files"]["dynamic_factor"]).name == "dynamics_K_v.png" and Path(out["files"]["dynamic_factor"]).exists()


@pytest.mark.parametrize("scene", sorted((ROOT / "studies" / "zoo").glob("*.toml")), ids=lambda p: p.stem)
def test_every_zoo_pair_lists_the_three_factors_with_sources(scene, capsys):
    """``femgear info --json`` of every zoo pair (no dynamics, no LTCA there: ISO's three, each its own ISO value)."""
    assert main(["-q", "info", str(scene), "--json"]) == 0
    lf = json.loads(capsys.readouterr().out.strip().splitlines()[-1])["load_factors"]
    for k, method in (("K_v", "method B"), ("K_Hbeta", "method C"), ("K_Halpha", "method B")):
        assert lf[k]["source"] == f"ISO 6336-1 {method}" and lf[k]["value"] == lf[k]["iso"] >= 1
