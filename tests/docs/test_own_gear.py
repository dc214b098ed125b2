"""The "Your own gear" walkthrough, followed literally (docs/guide/own-gear.md, issue 30).

The page's commands and TOML blocks are read from the page itself: the template of
``femgear new`` with the page's edits must be the example scene ``docs/examples/fan_drive.toml``,
which then loads, passes ``femgear info`` and runs (coarse numerics), from the CLI and from the
example script.
"""

from __future__ import annotations

import importlib.util
import json
import re
import shlex
import tomllib
from pathlib import Path

import numpy as np

from femgear.edge.cli import main
from femgear.scene import load_scene, scene_from_dict

ROOT = Path(__file__).resolve().parents[2]
PAGE = ROOT / "docs" / "guide" / "own-gear.md"
EXAMPLE = ROOT / "docs" / "examples" / "fan_drive.toml"
COARSE = ["--set", "numerics.dynamics_cycles=20.0", "--set", "numerics.transient_cycles=5.0",
          "--set", "numerics.path_points=11", "--set", "stiffness.n_positions=40"]


def blocks(language: str) -> list[str]:
    return re.findall(rf"```{language}\n(.*?)```", PAGE.read_text(encoding="utf-8"), flags=re.S)


def page_commands() -> list[list[str]]:
    """The ``femgear ...`` commands of the page's sh blocks, in order."""
    return [shlex.split(line) for b in blocks("sh") for line in b.splitlines() if line.startswith("femgear ")]


def test_the_page_edits_turn_the_template_into_the_example(tmp_path):
    new = page_commands()[0]
    assert new[:2] == ["femgear", "new"] and new[2] == "fan_drive.toml"
    path = tmp_path / new[2]
    assert main([*new[1:2], str(path), *new[3:]]) == 0
    data = tomllib.loads(path.read_text())
    for block in blocks("toml"):                        # paste each block's values over its table
        for table, keys in tomllib.loads(block).items():
            data.setdefault(table, {}).update(keys)
    assert scene_from_dict(data, warn=False) == load_scene(EXAMPLE)


def test_info_gives_the_figures_the_page_quotes(capsys):
    info = next(c for c in page_commands() if c[1] == "info")
    assert info[2] == "fan_drive.toml"
    assert main(["info", str(EXAMPLE), "--json"]) == 0
    d = json.loads(capsys.readouterr().out.strip().splitlines()[-1])
    text = " ".join(PAGE.read_text(encoding="utf-8").split())
    quoted = {f"`eps_alpha` {d['geometry']['eps_alpha']:.2f}", f"`eps_beta` {d['geometry']['eps_beta']:.2f}",
              f"({d['contact']['pitch']['hertz_pressure'] / 1e9:.2f} GPa)",
              f"h_c {d['contact']['pitch']['film_central'] * 1e6:.2f} µm",
              "S_H {:.2f} / {:.2f}".format(*d["safety_factors"]["S_H"]),
              f"({d['power_loss']['mean_loss']:.0f} W", f"η = {d['power_loss']['efficiency'] * 100:.2f} %"}
    assert all(q in text for q in quoted), [q for q in quoted if q not in text]


def test_run_as_the_page_says(tmp_path):
    run = next(c for c in page_commands() if c[1] == "run")
    assert run[2] == "fan_drive.toml"
    out_dir = tmp_path / "fan_drive"
    assert main(["run", str(EXAMPLE), "--out", str(out_dir), *COARSE, *run[3:]]) == 0
    assert (out_dir / "results.json").is_file() and (out_dir / "flanks.pvd").is_file()
    assert (out_dir / "dynamics.pvd").is_file()


def test_the_python_example_runs():
    spec = importlib.util.spec_from_file_location("fan_drive_example", ROOT / "docs" / "examples" / "fan_drive.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    figures = module.main(["--coarse"])
    assert 1e8 < figures["mesh stiffness, mean [N/m]"] < 1e10
    assert 0 < figures["friction coefficient, max along the path [-]"] < 0.1
    assert np.isfinite(figures["contact temperature rise, max [K]"])
