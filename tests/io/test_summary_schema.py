"""The result schema (femgear.edge.io.summary_schema) against real summaries, both ways, and the sweep's check of
its ``outputs`` against it before the first case (issue 37, item 6: a sweep once ran all its cases and then exited
2 on ``safety_factors.S_H``, a pair, not a column)."""

from __future__ import annotations

import csv
import subprocess
import sys
from pathlib import Path

import pytest

from femgear.case import build_case
from femgear.edge.io import summary_schema as schema
from femgear.edge.io.run import run_summary
from femgear.pipeline import run_case
from femgear.rate import scene_info
from femgear.scene import load_scene
from femgear.summary import scene_summary

ROOT = Path(__file__).resolve().parents[2]
ZOO = sorted((ROOT / "studies" / "zoo").glob("*.toml"))
BASE = ROOT / "studies" / "paper_baseline.toml"
FAST = ['physics.dynamics="lumped"', "numerics.dynamics_cycles=40", "numerics.transient_cycles=20"]


def kind_of_value(value) -> str:
    if isinstance(value, bool):
        return schema.FLAG
    if isinstance(value, (int, float)):
        return schema.NUMBER
    if isinstance(value, str):
        return schema.TEXT
    if isinstance(value, dict):
        return schema.TABLE
    if isinstance(value, (list, tuple)) and len(value) == 2 and all(isinstance(v, (int, float)) for v in value):
        return "pair-or-list"
    return schema.LIST


def leaves(d: dict, prefix: str = ""):
    """(key, value) of every leaf; a ``table`` of the schema is one leaf."""
    for key, value in d.items():
        name = f"{prefix}{key}"
        known = schema.kind_of(name)
        if isinstance(value, dict) and not (known and known[1] == schema.TABLE):
            yield from leaves(value, name + ".")
        else:
            yield name, value


def conforms(summary: dict) -> set[str]:
    """Assert every leaf is in the schema with its kind; return the keys seen."""
    seen = set()
    for key, value in leaves(summary):
        known = schema.kind_of(key)
        assert known is not None, f"summary key {key} is not in the result schema"
        _, kind, optional = known
        seen.add(key)
        if value is None:
            assert optional, f"{key} is None but the schema does not allow it"
            continue
        got = kind_of_value(value)
        if got == "pair-or-list":
            assert kind in (schema.PAIR, schema.LIST), f"{key}: a pair, the schema says {kind}"
        else:
            assert got == kind, f"{key}: {got}, the schema says {kind}"
    return seen


@pytest.fixture(scope="module")
def info_summaries():
    out = {}
    for path in ZOO:
        info = scene_info(build_case(load_scene(path), warn=False))
        out[path.stem] = scene_summary(info.case, info.contact, info.figures, ratings=info.rating)
    return out


def test_every_zoo_scenes_info_summary_is_in_the_schema_and_every_info_key_appears(info_summaries):
    seen = set().union(*(conforms(s) for s in info_summaries.values()))
    info_sections = ("scene", "geometry", "contact", "rating", "stiffness_iso6336", "flash_temperature",
                     "safety_factors", "bending", "scuffing", "micropitting", "power_loss", "inlet_heating")
    expected = {k for name in info_sections for k, (_, optional) in schema.SECTIONS[name].keys.items()
                if "*" not in k and not optional and not k.startswith("bending.femgear")}   # fillet_fe: off in the zoo
    assert expected <= seen, sorted(expected - seen)


@pytest.mark.parametrize("overrides", [
    ['physics.dynamics="none"', 'physics.coupling="one-way"', 'physics.thermal="analytic"', 'physics.wear="archard"',
     "wear.cycles=1e4", "thermal.flank_temperature_rise=20"],
    FAST + ['physics.thermal="analytic"', 'physics.wear="archard"', "wear.cycles=1e4", 'physics.coupling="bidirectional"'],
], ids=["static", "coupled"])
def test_a_runs_summary_is_in_the_schema(overrides):
    result = run_case(build_case(load_scene(BASE, overrides), warn=False))
    summary = run_summary(result)
    seen = conforms(summary)
    for section in ("physics", "stiffness", "friction", "thermal", "wear", "film"):
        assert any(k.startswith(section + ".") for k in seen), section
    assert ("dynamics" in summary) == (result.coupled is not None)


FILM_KEYS = {"ehl-line": {"film.error_estimate_max"},
             "tehl": {"film.error_estimate_max", "film.central_isothermal_pitch", "film.thermal_loading_max",
                      "film.phi_tehl_pitch", "film.phi_murch_wilson_pitch", "film.phi_gupta_pitch",
                      "film.flash_tehl_max", "film.flash_blok_max", "film.temperature_error_estimate_max"}}


@pytest.mark.parametrize("level", list(FILM_KEYS))
def test_the_numerical_films_figures_are_in_the_schema(level):
    """The ``ehl-line`` film's error estimate and the thermal films' figures (issue 43 item 6)."""
    scene = load_scene(BASE, [f'physics.lubrication="{level}"', 'physics.dynamics="none"',
                              'physics.coupling="one-way"', "numerics.path_points=5"])
    seen = conforms(run_summary(run_case(build_case(scene, warn=False))))
    assert FILM_KEYS[level] <= seen, sorted(FILM_KEYS[level] - seen)


def test_sections_say_when_a_case_has_them():
    static = load_scene(BASE, ['physics.dynamics="none"', 'physics.coupling="one-way"'])
    assert not schema.SECTIONS["dynamics"].present(static) and schema.SECTIONS["dynamics"].present(load_scene(BASE))
    assert schema.kind_of("dynamics.amplitudes.gear.velocity.y")[1] == schema.NUMBER
    assert schema.kind_of("safety_factors.S_H")[1] == schema.PAIR and schema.kind_of("no.such") is None


def _sweep(tmp_path: Path, outputs: str, grid: str = '"operating.torque" = [150.0, 200.0]') -> Path:
    path = tmp_path / "s.toml"
    path.write_text(f'base = "{BASE}"\nname = "s"\noutputs = {outputs}\n[grid]\n{grid}\n', encoding="utf-8")
    return path


def _run(path: Path, tmp_path: Path, *extra: str):
    return subprocess.run([sys.executable, "-m", "femgear", "sweep", str(path), "--out", str(tmp_path / "o"),
                           "--workers", "1", "--no-progress", *extra], capture_output=True, text=True)


@pytest.mark.parametrize("outputs, words", [
    ('["safety_factors.S_H"]', ["outputs: 'safety_factors.S_H' is a pair", "safety_factors.S_H.0",
                                "safety_factors.S_H.1"]),
    ('["dynamics.amplitudes.dte_rms"]', ["written only with a dynamics level", "no case of this sweep"]),
    ('["friction.mu_maen"]', ["no key of a run's results", "did you mean friction.mu_mean"]),
    ('["geometry.kind"]', ["is text in results.json"]),
])
def test_sweep_outputs_are_refused_before_the_first_case(outputs, words, tmp_path):
    path = _sweep(tmp_path, outputs, '"operating.torque" = [150.0, 200.0]\n"physics.dynamics" = ["none"]\n'
                                     '"physics.coupling" = ["one-way"]')
    run = _run(path, tmp_path)
    assert run.returncode == 2, run.stderr
    lines = run.stderr.strip().splitlines()
    assert len(lines) == 1 and "checked before any case ran" in lines[0], run.stderr
    for word in words:
        assert word in lines[0], lines[0]
    assert not (tmp_path / "o" / "s" / "cases").exists()


def test_the_command_line_outputs_are_checked_too(tmp_path):
    run = _run(_sweep(tmp_path, '[]'), tmp_path, "--outputs", "safety_factors.S_F")
    assert run.returncode == 2 and "--outputs: 'safety_factors.S_F' is a pair" in run.stderr


def test_a_pairs_halves_are_columns_of_the_table(tmp_path):
    path = _sweep(tmp_path, '["safety_factors.S_H.0", "safety_factors.S_F.1"]',
                  '"operating.torque" = [200.0]\n"physics.dynamics" = ["none"]\n"physics.coupling" = ["one-way"]\n'
                  '"physics.preset" = ["fast"]')
    run = _run(path, tmp_path)
    assert run.returncode == 0, run.stderr
    with open(tmp_path / "o" / "s" / "results.csv", encoding="utf-8") as fh:
        row = next(csv.DictReader(fh))
    assert float(row["safety_factors.S_H.0"]) > 1 and float(row["safety_factors.S_H.1"]) > 1
    assert (tmp_path / "o" / "s" / "summary.png").exists()
