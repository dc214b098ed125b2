"""Property test (hypothesis): scenes generated around the baseline either run, with finite
results, or stop with exit 2 and ONE line naming a scene key (or, for a solver that does not
converge, exit 1 and one line) — never a traceback, never an internal error, never NaN.

Values are the baseline's scaled by 10^±0.5 (often) or 10^±3, plus the values users get wrong: zero,
negatives, inf, nan, strings holding numbers, booleans.  A cheap physics preset keeps
each example fast (``make test``: bounded examples; ``make test-slow``: more, with dynamics).
"""

from __future__ import annotations

import json
import math
import re
import tomllib
from pathlib import Path

import pytest

hypothesis = pytest.importorskip("hypothesis")
from hypothesis import HealthCheck, given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

from femgear.edge.cli import main  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
BASE = ROOT / "studies" / "paper_baseline.toml"
RAW = tomllib.loads(BASE.read_text())
KEYS = ["operating.speed_rpm", "operating.torque", "operating.ambient_temperature", "pair.normal_module",
        "pair.helix_angle_deg", "pair.normal_pressure_angle_deg", "pair.face_width", "pair.backlash",
        "pinion.teeth", "gear.teeth", "pinion.profile_shift", "pinion.mass", "gear.support_stiffness",
        "pinion.eccentricity", "material.youngs_modulus", "material.poisson_ratio", "oil.viscosity",
        "oil.pressure_viscosity", "oil.temperature_viscosity", "friction.coefficient", "errors.profile_error"]
STATIC = ['physics.preset="fast"', 'physics.dynamics="none"', 'physics.coupling="one-way"',
          'physics.wear="none"']
DYNAMIC = ['physics.preset="fast"', 'physics.coupling="one-way"', 'physics.wear="none"',
           "numerics.dynamics_cycles=20.0", "numerics.transient_cycles=10.0"]


#: failures this test found in code outside the CLI (fixed; kept as the tests at the end of this file)
KNOWN: tuple[str, ...] = ()


def _baseline(key: str):
    table, name = key.split(".")
    return RAW.get(table, {}).get(name, {"pinion.profile_shift": 0.0, "pinion.eccentricity": 1e-5,
                                        "friction.coefficient": 0.05, "errors.profile_error": 5e-6}.get(key, 1.0))


def _toml(value) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, str):
        return json.dumps(value)
    if isinstance(value, float):
        return "nan" if math.isnan(value) else ("inf" if value > 0 else "-inf") if math.isinf(value) else repr(value)
    return repr(value)


@st.composite
def overrides(draw):
    keys = draw(st.lists(st.sampled_from(KEYS), min_size=1, max_size=3, unique=True))
    out = []
    for key in keys:
        base = _baseline(key)
        exponent = st.one_of(st.floats(-0.5, 0.5), st.floats(-3, 3))    # mostly near the baseline
        scaled = exponent.map(lambda e, b=base: b * 10.0**e if b else 10.0**e * 1e-4)
        if isinstance(base, int) and not isinstance(base, bool):
            scaled = st.one_of(st.integers(base // 2, 2 * base), st.integers(-5, 4 * base))
        wrong = st.sampled_from([0.0, -1.0, math.inf, -math.inf, math.nan, True, str(base)])
        value = draw(st.one_of(scaled, scaled, scaled, wrong))
        out.append(f"{key}={_toml(value)}")
    return out


def _check(sets: list[str], physics: list[str], tmp_path: Path, capsys) -> None:
    out = tmp_path / "o"
    argv = ["-q", "run", str(BASE), "--out", str(out), "--no-plots", "--no-vtk", "--json"]
    for item in physics + sets:
        argv += ["--set", item]
    rc = main(argv)
    stdout, stderr = capsys.readouterr()
    assert "Traceback" not in stderr
    hypothesis.event(f"exit {rc}")
    if rc == 2:
        lines = stderr.strip().splitlines()
        assert len(lines) == 1, stderr
        named = re.match(r"femgear: error: ([a-z_]+\.[a-z_]+)", lines[0])
        assert named, f"no key named: {lines[0]}"
        return
    if rc == 1 and "internal error" not in stderr:   # a solver that did not converge: one line, exit 1
        assert len(stderr.strip().splitlines()) == 1, stderr
        return
    if rc == 1 and any(known in stderr for known in KNOWN):
        hypothesis.reject()   # found by this test, kept as the strict xfails below until fixed
    assert rc == 0, f"{sets}: exit {rc}: {stderr}"
    payload = json.loads((out / "results.json").read_text())     # json: NaN/inf would be written as null
    for name, values in payload["along_path"].items():
        assert all(isinstance(v, (int, float)) and math.isfinite(v) for v in values), f"{sets}: {name} not finite"
    json.loads(stdout.strip().splitlines()[-1])


@settings(max_examples=25, deadline=None, derandomize=True,
          suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])
@given(sets=overrides())
def test_generated_scenes_run_or_name_a_key(sets, tmp_path, capsys):
    _check(sets, STATIC, tmp_path, capsys)


@pytest.mark.slow
@settings(max_examples=150, deadline=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])
@given(sets=overrides(), dynamic=st.booleans())
def test_generated_scenes_run_or_name_a_key_many(sets, dynamic, tmp_path, capsys):
    """slow: more examples, half of them with the lumped dynamics (driver speed ≥ 100 rpm there: the
    default step resolves the highest mode, so a 1 rpm run simulates ~10⁶ steps — right, but minutes)."""
    if dynamic:
        speeds = [float(v) for k, v in (x.split("=", 1) for x in sets) if k == "operating.speed_rpm"
                  and v not in ("true", "false") and not v.startswith('"')]
        hypothesis.assume(all(not (0 < v < 100.0) for v in speeds))
    _check(sets, DYNAMIC if dynamic else STATIC, tmp_path, capsys)


def test_zero_backlash_closed_by_expansion_names_the_key(tmp_path, capsys):
    argv = ["run", str(BASE), "--out", str(tmp_path), "--no-plots", "--no-vtk", "--set", "pair.backlash=0.0"]
    for item in DYNAMIC:
        argv += ["--set", item]
    rc = main(argv)
    err = capsys.readouterr().err
    assert rc == 2 and "pair.backlash" in err


def test_contact_loss_in_the_coupling_runs(tmp_path, capsys):
    """Found by the property test: a 0.3 mm module at 50 000 rpm (Hertz 5.2 GPa, warned) loses contact."""
    argv = ["run", str(BASE), "--out", str(tmp_path), "--no-plots", "--no-vtk", "--set", "operating.speed_rpm=50000.0",
            "--set", "pair.normal_module=0.0003"]
    for item in DYNAMIC:
        argv += ["--set", item]
    rc = main(argv)
    assert rc == 0, capsys.readouterr().err
