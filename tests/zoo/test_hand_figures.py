"""The zoo of real gears (issue 25 item 2): every scene's hand-checked figures match ``femgear info``.

Each ``studies/zoo/*.toml`` ends in a comment block of ``# hand: KEY = VALUE ± TOL  (source)`` lines,
written by ``tests/zoo/hand_figures.py`` from the standards and papers without femgear.  Here

- femgear's ``info --json`` (with ISO's uniform load along the lines, ``physics.stiffness = "iso6336"``,
  μ = ``friction.coefficient``, ``physics.lubrication = "constant"``, and the load factors K_v, K_Hβ, K_Hα
  set to 1: the ratings' own factors have their tests in ``tests/rating/test_load_factors.py``) matches every figure within
  the relative tolerance stated beside it;
- the block is the independent script's current output (so it cannot go stale);
- the zoo spans what issue 25 asks (module 2–12 mm, ε_β 0–4, 100–15 000 rpm, 1 kW–20 MW, the kinds
  of gear named there), and its copies of the shipped scenes hold the same data.
"""

from __future__ import annotations

import importlib.util
import json
import math
import re
import tomllib
from pathlib import Path

import pytest

from femgear.edge.cli import main

ROOT = Path(__file__).resolve().parents[2]
_SPEC = importlib.util.spec_from_file_location("zoo_hand_figures", Path(__file__).with_name("hand_figures.py"))
hand_figures = importlib.util.module_from_spec(_SPEC)
_SPEC.loader.exec_module(hand_figures)
ZOO = sorted((ROOT / "studies" / "zoo").glob("*.toml"))
HAND = re.compile(r"^# hand: (\S+) = (\S+) ± (\S+)\s+\((.*)\)\s*$")
CONDITIONS = ["--set", 'physics.stiffness="iso6336"', "--set", 'physics.lubrication="constant"',
              # the load factors the hand figures take (K_v = K_Hβ = K_Hα = 1, unless the scene gives them)
              *(x for key in ("dynamic_factor", "face_load_factor", "transverse_load_factor")
                for x in ("--set", f"rating.{key}=1.0"))]


def stated(path: Path) -> list[tuple[str, float, float, str]]:
    """The ``# hand:`` figures of a scene file."""
    out = []
    for line in path.read_text().splitlines():
        m = HAND.match(line)
        if m:
            out.append((m.group(1), float(m.group(2)), float(m.group(3)), m.group(4)))
    return out


def lookup(summary: dict, key: str) -> float:
    node = summary
    for part in key.split("."):
        node = node[int(part)] if isinstance(node, list) else node[part]
    return float(node)


def info_json(path: Path, capsys) -> dict:
    rc = main(["-q", "info", str(path), "--json", *CONDITIONS])
    out = capsys.readouterr().out
    assert rc == 0
    return json.loads(out.strip().splitlines()[-1])


@pytest.mark.parametrize("path", ZOO, ids=lambda p: p.stem)
def test_hand_figures_match_femgear_info(path, capsys):
    figures = stated(path)
    assert len(figures) >= 20, "every zoo scene carries its hand-checked figures"
    summary = info_json(path, capsys)
    bad = []
    for key, value, tol, source in figures:
        got = lookup(summary, key)
        ok = abs(got - value) <= tol * abs(value) if value != 0 else abs(got) <= tol
        if not ok:
            bad.append(f"{key}: femgear {got:.7g}, hand {value:.7g} ± {tol:g} ({source})")
    assert not bad, "\n".join(bad)


@pytest.mark.parametrize("path", ZOO, ids=lambda p: p.stem)
def test_the_block_is_the_independent_scripts_output(path):
    """The printed figures are what tests/zoo/hand_figures.py computes now (7 digits)."""
    now = {key: value for key, value, _, _ in hand_figures.figures(path)}
    block = stated(path)
    assert [k for k, *_ in block] == list(now)
    for key, value, _, _ in block:
        assert value == pytest.approx(now[key], rel=1e-6, abs=1e-12), key


def test_blok_constant_is_the_jaeger_band_integral():
    """2√2 I_max/π^1.5 = 1.1115 (Blok's 1.11): the script integrates it rather than quoting it."""
    assert hand_figures.blok_constant() == pytest.approx(1.1115, abs=2e-4)


def test_iso6336_stiffness_of_the_iso_tr_example():
    """The script's ISO 6336-1 method B against ISO/TR 6336-30 example 1 (c'_th 17.85584, c' 12.37047
    N/(mm µm); notes/gear_methods.md §4): m_n 8, z 17/103, x 0.145/0, β 15.8°, b 100 mm, rack D."""
    scene = {"pair": {"normal_module": 8e-3, "helix_angle_deg": 15.8, "face_width": 0.1, "kind": "single-helical",
                      "basic_rack": "D"},
             "pinion": {"teeth": 17, "profile_shift": 0.145}, "gear": {"teeth": 103, "profile_shift": 0.0},
             "material": {"youngs_modulus": 206e9}}
    P = hand_figures.Pair(scene)
    c_th, c_p, _, _ = hand_figures.c_prime(P, scene, line_load=1e6)
    assert c_th == pytest.approx(17.85584, rel=1e-5) and c_p == pytest.approx(12.37047, rel=1e-5)


def test_the_zoo_spans_what_issue_25_asks():
    rows = []
    for path in ZOO:
        s = tomllib.loads(path.read_text())
        P = hand_figures.Pair(s)
        op = s["operating"]
        ratio = P.z2 / P.z1
        n1 = op["speed_rpm"] if op.get("driver", "pinion") == "pinion" else op["speed_rpm"] * ratio
        T1 = op["torque"] if op.get("driver", "pinion") == "pinion" else op["torque"] / ratio
        rows.append(dict(name=path.stem, kind=P.kind, m=P.mn, eb=P.eb, n1=n1, P=T1 * n1 * math.pi / 30,
                         T=op["torque"], v=math.pi * P.d1 * n1 / 60, b=P.b))
    by = {r["name"]: r for r in rows}
    assert {"automotive_spur", "fzg_a", "fzg_c14", "paper_baseline", "marine", "turbo", "wind"} <= set(by)
    assert by["automotive_spur"]["kind"] == "spur"
    assert by["marine"]["kind"] == "double-helical" and 2.5 <= by["marine"]["eb"] <= 3.5
    assert by["marine"]["b"] >= 0.1 and by["marine"]["P"] >= 1e6
    assert by["turbo"]["kind"] == "double-helical" and by["turbo"]["v"] >= 100 and by["turbo"]["n1"] >= 10000
    assert by["wind"]["kind"] == "single-helical" and by["wind"]["m"] >= 10e-3 and by["wind"]["T"] >= 1e6
    assert min(r["m"] for r in rows) <= 2e-3 and max(r["m"] for r in rows) >= 12e-3
    assert min(r["eb"] for r in rows) == 0 and max(r["eb"] for r in rows) >= 3.9
    assert min(r["n1"] for r in rows) <= 105 and max(r["n1"] for r in rows) >= 14000
    assert min(r["P"] for r in rows) <= 1.2e3 and max(r["P"] for r in rows) >= 19.9e6


@pytest.mark.parametrize("name", ["paper_baseline", "fzg_c14"])
def test_zoo_copies_hold_the_shipped_scenes_data(name):
    zoo = tomllib.loads((ROOT / "studies" / "zoo" / f"{name}.toml").read_text())
    shipped = tomllib.loads((ROOT / "studies" / f"{name}.toml").read_text())
    assert zoo == shipped
