"""Figures and the closing table: the fixes the review asked for, checked on synthetic data."""

from __future__ import annotations

import os
import stat

import numpy as np
import pytest

from femgear.edge.cli.report import key_figures
from femgear.edge.io.figures import save_figure
from femgear.edge.plot.coupled import plot_convergence, plot_coupled_path
from femgear.edge.plot.dynamics import _smooth_orbit, plot_mesh_force, plot_phase_planes, plot_time_histories
from femgear.system.dynamics.response import Response


def _png(path) -> bool:
    return path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and stat.S_IMODE(os.stat(path).st_mode) == 0o644


def test_phase_plane_interpolation_is_smooth_between_steps():
    """20 steps per period drawn straight are a polygon (error ~1 % of the amplitude); the
    Hermite/spline orbit is within 1e-4 of the exact ellipse."""
    w = 2 * np.pi
    t = np.linspace(0, 3, 61)
    x, v = _smooth_orbit(t, np.sin(w * t), w * np.cos(w * t))
    tf = np.linspace(0, 3, len(x))
    assert np.max(np.abs(x - np.sin(w * tf))) < 1e-4
    assert np.max(np.abs(v - w * np.cos(w * tf))) / w < 2e-3
    straight = np.interp(tf, t, np.sin(w * t))
    assert np.max(np.abs(straight - np.sin(w * tf))) > 0.01


def _response(n: int = 2000, f_m: float = 250.0) -> Response:
    t = np.arange(n) / (40 * f_m)
    d = np.zeros((n, 24))
    d[:, 0], d[:, 1] = 1e-9 * np.sin(2 * np.pi * f_m * t), 1e-7 * np.cos(2 * np.pi * f_m * t)   # x ≪ y
    d[:, 6:12] = d[:, 0:6]
    v = np.gradient(d, t, axis=0)
    force = np.column_stack([2000 + 10 * np.sin(2 * np.pi * f_m * t)] * 2)                      # equal helices
    return Response(t=t, displacement=d, velocity=v, delta=np.zeros((n, 2)), mesh_force=force,
                    bearing_acceleration=np.zeros((n, 4, 3)), mesh_frequency=f_m)


def test_dynamics_figures_are_written(tmp_path):
    res = _response()
    for plot, name in ((plot_time_histories, "t.png"), (plot_mesh_force, "f.png"), (plot_phase_planes, "p.png")):
        assert _png(save_figure(plot(res), tmp_path / name))


def test_coupled_figures_leave_out_what_was_not_computed(tmp_path):
    s = np.linspace(-7e-3, 7e-3, 21)
    w = 8e4 * (1 + 0.2 * np.cos(s / 7e-3))
    full = save_figure(plot_coupled_path(s, w, mu=0.03 + 0 * s, temperature_rise=5 + 0 * s,
                                         thermal_deviation=np.array([s, -s]) * 1e-4, wear=np.abs([s, s]) * 1e-3,
                                         wear_cycles=1e6), tmp_path / "full.png")
    load_only = save_figure(plot_coupled_path(s, w), tmp_path / "load.png")
    assert _png(full) and _png(load_only)
    assert full.stat().st_size > load_only.stat().st_size
    assert _png(save_figure(plot_convergence([0, 1, 2, 3], [None, 6e-3, 3e-6, 3e-9], [None, 6e-5, 7e-8, 5e-11]),
                            tmp_path / "conv.png"))


def test_key_figures_of_a_coupled_summary():
    summary = {
        "coupling": {"mode": "bidirectional", "converged": True, "iterations": 3,
                     "history": {"mesh_force_change": [None, 6.6e-3, 3.7e-6, 3.3e-9]}},
        "stiffness": {"mean_total": 9.97e8, "ripple_total": 0.049},
        "contact": {"pitch": {"hertz_pressure": 5.25e8, "film_central": 7.0e-7}},
        "friction": {"mu_max": 0.0371, "mu_mean": 0.0284, "max_temperature_rise": 11.5},
        "dynamics": {"amplitudes": {"gear.displacement.x": 1.26e-8, "gear.displacement.y": 1.43e-8,
                                    "mesh_force.L.mean": 2283.1, "mesh_force.L.amplitude": 16.8}},
    }
    rows = {q: (v, u) for q, v, u in key_figures(summary, seconds=3.2)}
    assert "converged in 3 passes" in rows["coupling"][0] and "3.3e-09" in rows["coupling"][0]
    assert rows["mesh stiffness, mean (ripple)"] == ("0.997 (4.90 %)", "kN/µm")
    assert rows["Hertz pressure at the pitch point"] == ("0.525", "GPa")
    assert rows["gear amplitude x / y (half peak-to-peak)"] == ("0.0126 / 0.0143", "µm")
    assert rows["wall time"] == ("3.2", "s")
    assert not any("wear" in q or "thermal" in q for q in rows)     # not computed, not shown


def test_key_figures_flag_a_run_that_did_not_converge():
    rows = key_figures({"coupling": {"mode": "bidirectional", "converged": False, "iterations": 30}})
    assert "NOT converged" in rows[0][1]


@pytest.mark.parametrize("key,unit", [("hertz_pressure", "Pa"), ("working_pressure_angle_deg", "deg"),
                                      ("eps_alpha", ""), ("mesh_frequency", "Hz")])
def test_info_units(key, unit):
    from femgear.edge.cli.info import unit_of

    assert unit_of(key) == unit
