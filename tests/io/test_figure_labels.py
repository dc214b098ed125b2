"""Figures that stand alone: titles with the scene name, spelled-out quantities, peak amplitudes said and
checked, natural frequencies marked where the speed sweep meets them; CLI level choices from the levels."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

from femgear.edge.plot import dynamics as dplot
from femgear.system.dynamics.modal import resonance_marks
from femgear.system.dynamics.response import Response, spectrum


@pytest.fixture
def figures():
    """The figures a test draws (the plot functions return them), closed afterwards."""
    import matplotlib.pyplot as plt

    kept = []
    yield kept
    for fig in kept:
        plt.close(fig)


def texts(fig) -> str:
    """Every title, suptitle and axis label of a figure, one string."""
    out = [fig._suptitle.get_text() if fig._suptitle else ""]
    for ax in fig.axes:
        out += [ax.get_title(), ax.get_xlabel(), ax.get_ylabel()]
    return "\n".join(out)


def response(n: int = 4000, f_m: float = 250.0) -> Response:
    t = np.arange(n) / (40 * f_m)
    d = np.zeros((n, 24))
    d[:, 1] = 1e-7 * np.cos(2 * np.pi * f_m * t)
    d[:, 7] = d[:, 1]
    delta = np.column_stack([1e-6 + 2e-7 * np.sin(2 * np.pi * f_m * t)] * 2)
    return Response(t=t, displacement=d, velocity=np.gradient(d, t, axis=0), delta=delta,
                    mesh_force=np.full((n, 2), 2000.0), bearing_acceleration=np.zeros((n, 4, 3)), mesh_frequency=f_m)


def test_spectrum_heights_are_peak_amplitudes():
    """A sine of amplitude A on a frequency line shows A (not A/√2, the RMS): what the figure's label says."""
    dt, n, f = 1e-4, 4000, 250.0                                  # 100 periods: f on a line
    t = np.arange(n) * dt
    sp = spectrum(0.3 + 2.5 * np.sin(2 * np.pi * f * t), dt, mesh_frequency=f)
    i = int(np.argmin(np.abs(sp.frequency - f)))
    assert sp.amplitude[i] == pytest.approx(2.5, rel=1e-6)      # the symmetric Hanning window: 6e-9 off
    assert sp.order[i] == pytest.approx(1.0)


def test_dynamics_figures_carry_the_scene_name_and_spelled_out_quantities(figures):
    res = response()
    for plot in (dplot.plot_time_histories, dplot.plot_mesh_force, dplot.plot_phase_planes, dplot.plot_spectra):
        figures.append(plot(res, name="marine (lumped, pem stiffness)"))
    assert len(figures) == 4
    for fig in figures:
        assert texts(fig).count("marine (lumped, pem stiffness):") == 1
    spectra = texts(figures[3])
    assert "dynamic transmission error (DTE)" in spectra
    assert all("peak amplitude" in ax.get_ylabel() for ax in figures[3].axes) and "not RMS" in spectra
    assert "displacement\nx − mean [µm]" in texts(figures[0])


def test_resonances_are_where_a_mesh_harmonic_meets_a_natural_frequency():
    """k f_m = f_n: the 8321 Hz mode resonates at f_m = 2080 Hz (k = 4) and 2774 Hz (k = 3), not 4160 Hz (out of
    range); a mode with 1 % mesh energy and the rigid mode are not marked."""
    marks = resonance_marks([0.0, 2851.0, 4000.0, 8321.0], [0.0, 0.15, 0.01, 0.84], 250.0, 3100.0)
    assert [(round(x), k) for x, k, _ in marks] == [(713, 4), (950, 3), (1426, 2), (2080, 4), (2774, 3), (2851, 1)]


def test_speed_sweep_marks_the_natural_frequencies_it_promises(figures):
    fm = np.linspace(258.0, 3100.0, 12)
    sweep = SimpleNamespace(mesh_frequency=fm, speed_rpm=fm * 500 / 258.0, dte_rms=1e-7 * (1 + 0 * fm))
    modal = SimpleNamespace(frequencies=np.array([0.0, 2851.0, 8321.0]), energy={"mesh": np.array([0.0, 0.15, 0.84])})
    figures.append(dplot.plot_sweep(sweep, modal, name="marine"))
    ax = figures[0].axes[0]
    vertical = sorted(round(line.get_xdata()[0]) for line in ax.get_lines() if len(set(line.get_xdata())) == 1
                      and len(line.get_xdata()) == 2)
    assert vertical == [713, 950, 1426, 2080, 2774, 2851]
    legend = "\n".join(t.get_text() for t in ax.get_legend().get_texts())
    assert "2851 Hz" in legend and "8321 Hz" in legend
    assert "marine: " in texts(figures[0]) and "dynamic transmission error (DTE)" in texts(figures[0])


def test_dynamics_cli_offers_the_stiffness_levels_of_the_scene():
    """``femgear dynamics --stiffness`` takes its choices from the one table of level names (ltca included)."""
    from femgear.edge.cli import build_parser
    from femgear.scene.levels import AVAILABLE, LEVELS

    parser = build_parser()
    sub = next(a for a in parser._actions if a.dest == "command").choices["dynamics"]
    options = {a.dest: a for a in sub._actions}
    usable = [lv for lv in LEVELS["stiffness"] if lv in AVAILABLE["stiffness"]]
    assert "ltca" in usable
    assert list(options["stiffness"].choices) == usable + ["contact-line"]
    assert all(lv in options["stiffness"].help for lv in usable)
    assert list(options["level"].choices) == [lv for lv in LEVELS["dynamics"] if lv != "none"]
