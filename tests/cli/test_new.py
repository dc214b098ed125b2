"""``femgear new``: the commented template holds every schema key, loads as written and runs (issue 30)."""

from __future__ import annotations

import tomllib

import numpy as np
import pytest

from femgear.case import build_case
from femgear.edge.cli import main
from femgear.pipeline import run_case
from femgear.scene import load_scene
from femgear.scene.keys import scene_keys
from femgear.scene.template import KINDS, example_values, scene_template

#: coarse numerics for a quick run of the example pair
COARSE = ["numerics.path_points=11", "numerics.dynamics_cycles=20.0", "numerics.transient_cycles=5.0",
          "stiffness.n_positions=40"]


@pytest.mark.parametrize("kind", KINDS)
def test_template_has_every_key_and_loads(kind, tmp_path):
    text = scene_template(kind)
    for k in scene_keys():                      # every key appears, active or commented, with its meaning
        assert f"{k.name} = " in text, k.key
        assert k.description.split()[0] in text
    path = tmp_path / "pair.toml"
    assert main(["new", str(path), "--kind", kind]) == 0
    scene = load_scene(path)
    assert scene.pair.kind == {"double": "double-helical", "single": "single-helical", "spur": "spur"}[kind]
    data = tomllib.loads(path.read_text())     # the active values are the example's, nothing else
    active = {f"{t}.{k}" for t, table in data.items() for k in table}
    assert active == set(example_values(kind))


def test_uncommenting_a_default_changes_nothing(tmp_path):
    """Every commented line is the key's default: uncommenting it all gives the same scene."""
    text = scene_template("double")
    lines, previous = [], ""
    for line in text.splitlines():            # uncomment the key lines (after their "(type; default)" line)
        if line.startswith("# [") and line.endswith("]"):
            lines.append(f"[_skip_{len(lines)}]")  # optional tables stay out
        elif previous.startswith("#   (") and line.startswith("# ") and not line.endswith("= ..."):
            lines.append(line[2:])
        else:
            lines.append(line)
        previous = line
    data = tomllib.loads("\n".join(lines))
    data = {t: keys for t, keys in data.items() if not t.startswith("_skip_")}
    full = tmp_path / "full.toml"
    full.write_text(tomllib_dumps(data))
    path = tmp_path / "pair.toml"
    path.write_text(text)
    assert load_scene(full) == load_scene(path)


def tomllib_dumps(data: dict) -> str:
    from femgear.scene.template import toml_value

    out = []
    for table, keys in data.items():
        out.append(f"[{table}]")
        out += [f"{k} = {toml_value(v)}" for k, v in keys.items()]
    return "\n".join(out)


@pytest.mark.parametrize("kind", KINDS)
def test_the_template_runs_coupled(kind, tmp_path):
    path = tmp_path / "pair.toml"
    path.write_text(scene_template(kind))
    result = run_case(build_case(load_scene(path, COARSE)))
    assert result.coupled is not None and result.coupled.converged
    mu = result.tribology.friction_coefficient
    assert np.all(np.isfinite(mu)) and 0 < mu.max() < 0.1
    # the mean dynamic mesh force carries the static normal force (both helices), within 2 %
    force = result.coupled.state.mesh_force.mean(axis=-1).sum()
    assert force == pytest.approx(result.case.operating.normal_force, rel=0.02)


def test_new_refuses_to_overwrite_and_prints_without_file(tmp_path, capsys):
    path = tmp_path / "pair.toml"
    path.write_text("x")
    assert main(["new", str(path)]) == 2
    assert "exists" in capsys.readouterr().err
    assert main(["new", "--kind", "spur"]) == 0
    assert "[pair]" in capsys.readouterr().out
