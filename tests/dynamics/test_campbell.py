"""Tier 2/3: the Campbell diagram — zero-speed modes, gyroscopic whirl, the torsional critical speed, the sweep's
peaks at the listed critical speeds, the command line."""

import json
import math
from pathlib import Path

import numpy as np
import pytest

from femgear.case import build_case
from femgear.scene import load_scene
from femgear.system.dynamics import build_model
from femgear.system.dynamics.campbell import campbell, gyroscopic_matrix
from femgear.system.dynamics.mesh import StiffnessTable
from femgear.system.dynamics.modal import modal_analysis
from femgear.system.dynamics.sweep import peak_frequency, speed_sweep
from tests.cli.test_bad_input import assert_one_line, cli

ROOT = Path(__file__).resolve().parents[2]
BASE = ROOT / "studies" / "paper_baseline.toml"
ZOO = ROOT / "studies" / "zoo"


@pytest.mark.parametrize("path, level", [(BASE, "lumped"), (BASE, "timoshenko"), (ZOO / "wind.toml", "timoshenko")])
def test_zero_speed_frequencies_are_the_modes(path, level):
    """At 0 rpm the diagram's frequencies equal ``femgear dynamics --modes`` (modal_analysis), mode for mode."""
    m = build_model(build_case(load_scene(path)), level)
    d = campbell(m, [0.0, 100.0, 200.0])
    modes = modal_analysis(m).frequencies
    assert np.allclose(d.frequency[0], modes[modes > 1e-3 * modes.max()], rtol=1e-9)
    assert np.all(d.mac > 0.9)                            # tracked: each mode is itself at the next speed


def test_gyroscopic_whirl_of_a_tilting_pinion():
    """The baseline pinion almost uncoupled from the gear (mesh stiffness 1 N/m): its tilt mode on the two
    bearings splits into forward and backward whirl, I_d ω² ∓ I_p Ω ω − k_θ = 0, so ω_f ω_b = k_θ/I_d and
    ω_f − ω_b = I_p Ω/I_d (a rigid rotor; k_θ = k span²/4 from the two bearings k/2 at ±span/2)."""
    case = build_case(load_scene(BASE))
    m = build_model(case, "lumped", stiffness=StiffnessTable(np.array([1.0]), np.array([1.0])), friction=0.0)
    mem, b = case.scene.pinion, case.pair.b
    half = 0.5 * b                                        # helix centres at ±(b + groove)/2, groove 0
    Id = mem.inertia / 2 + 2 * (mem.mass / 2) * (b**2 / 12 + half**2)
    Ip, k_theta = mem.inertia, mem.support_stiffness * mem.bearing_span**2 / 4
    rpm = 30000.0
    d = campbell(m, [0.0, rpm / 2, rpm])
    omega = 2 * math.pi * rpm / 60
    w0 = math.sqrt(k_theta / Id)
    tilt = np.flatnonzero(np.isclose(d.frequency[0] * 2 * math.pi, w0, rtol=1e-6))
    assert tilt.size == 2                                  # θx and θy at rest
    wf, wb = sorted(d.frequency[-1, tilt] * 2 * math.pi, reverse=True)
    assert wf * wb == pytest.approx(k_theta / Id, rel=1e-6)
    assert wf - wb == pytest.approx(Ip * omega / Id, rel=1e-6)
    G = gyroscopic_matrix(m, rpm)
    assert np.allclose(G, -G.T) and G[3, 4] == pytest.approx(Ip * omega, rel=1e-12)


def test_torsional_critical_speed_is_60_fn_over_z():
    """A spur pair on rigid bearings (1e13 N/m): its mesh mode is the torsional one, f_n = √(k̄ (r_b1²/I1 +
    r_b2²/I2))/2π, and the listed mesh-order-1 critical speed is n = 60 f_n / z1 to 0.5 %."""
    stiff = [f"{m}.{k}=1e13" for m in ("pinion", "gear") for k in ("support_stiffness", "axial_stiffness")]
    case = build_case(load_scene(ZOO / "automotive_spur.toml", stiff))
    m = build_model(case, "lumped", stiffness="constant", friction=0.0)
    p, g, pair = case.scene.pinion, case.scene.gear, case.pair
    k = m.stiffness.mean[0]
    f_n = math.sqrt(k * (pair.rb1**2 / p.inertia + pair.rb2**2 / g.inertia)) / (2 * math.pi)
    n_hand = 60 * f_n / pair.z1
    d = campbell(m, np.linspace(0.5 * n_hand, 1.5 * n_hand, 11), mesh_orders=(1,), shaft_orders=())
    crit = [c for c in d.critical if c["order"] == "mesh order 1"]
    assert len(crit) == 1 and crit[0]["energy"]["mesh_L"] > 0.99
    assert crit[0]["speed_rpm"] == pytest.approx(n_hand, rel=5e-3)


def test_speed_sweep_peaks_within_one_step_of_the_critical_speed():
    """The time-domain sweep (DTE RMS, contact-line TVMS with one profile-error harmonic) peaks within one sweep
    step of the mesh-order-1 critical speed the diagram lists for the first mode with mesh strain energy."""
    scene = load_scene(BASE, ["errors.profile_error=1e-6", "errors.profile_error_orders=1"])
    kw = dict(level="lumped", stiffness="contact-line", friction=0.0)
    model = build_model(build_case(scene), **kw)
    d0 = campbell(model, [0.0, 1.0], mesh_orders=(1,), shaft_orders=())
    f1 = d0.frequency[0][d0.mesh_energy[0] > 0.1][0]
    rpm = np.linspace(0.85, 1.15, 13) * f1 * 60 / scene.pinion.teeth
    d = campbell(model, rpm, mesh_orders=(1,), shaft_orders=())
    crit = [c["speed_rpm"] for c in d.critical if c["order"] == "mesh order 1"]
    sw = speed_sweep(build_case(scene), rpm, cycles=80, measure=30, method="rk4", steps_per_cycle=40, **kw)
    peak = peak_frequency(sw.speed_rpm, sw.dte_rms)
    step = rpm[1] - rpm[0]
    assert min(abs(peak - c) for c in crit) <= step, (peak, crit)


def test_campbell_command_writes_png_and_json(tmp_path, capsys):
    out = tmp_path / "c"
    rc, stdout, _ = cli(["dynamics", str(BASE), "--campbell", "0:9000:31", "--out", str(out), "--json"], capsys)
    assert rc == 0
    summary = json.loads(stdout.strip().splitlines()[-1])
    assert (out / "campbell.png").stat().st_size > 10_000 and (out / "campbell.json").exists()
    assert len(summary["speed_rpm"]) == 31 and summary["modes"][0]["frequency_hz"][0] > 1000
    assert {"mesh_L", "mesh_R", "bearing_gear_R", "shafts"} <= set(summary["modes"][0]["energy"])
    crit = summary["critical_speeds"]
    assert crit and all(c["energy"]["mesh_L"] + c["energy"]["mesh_R"] >= 0.05 for c in crit)
    assert {o["label"] for o in summary["orders"]} >= {"mesh order 4", "gear shaft order 2"}


@pytest.mark.parametrize("args, name", [
    (["--campbell", "100:50"], "--campbell"),            # RPM1 < RPM0
    (["--campbell", "0:0"], "--campbell"),               # a sweep over 0 rpm
    (["--campbell", "-10:100"], "--campbell"),
    (["--campbell", "0:100:1"], "--campbell"),
    (["--campbell", "0:3000", "--orders", "1,-2"], "--orders"),
    (["--campbell", "0:3000", "--shaft-orders", "0"], "--shaft-orders"),
    (["--campbell", "0:3000", "--sweep", "100:200:3"], "--campbell"),
    (["--campbell", "0:1e9"], "--campbell"),             # above the rim's burst speed
    (["--sweep", "1000:2000:3", "--orders", "-1"], "--orders"),      # negative, and outside a Campbell run
    (["--sweep", "1000:2000:3", "--orders", "2"], "--orders"),       # would be ignored by the sweep
    (["--runup", "800:900:1", "--shaft-orders", "1"], "--shaft-orders"),
])
def test_bad_campbell_arguments_are_one_line(args, name, tmp_path, capsys):
    out = tmp_path / "never"
    rc, _, err = cli(["dynamics", str(BASE), *args, "--out", str(out)], capsys)
    assert rc == 2
    assert_one_line(err, name)
    assert not out.exists()
