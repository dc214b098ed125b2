"""PNG plots of dynamic responses (matplotlib is imported inside the functions only).

Each function takes frozen results and a path, writes one PNG and returns the path.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from femgear.dynamics.response import Response, spectrum


def _pyplot():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def _save(fig, path) -> Path:
    from femgear.plot import save_figure

    return save_figure(fig, path)


def plot_time_histories(res: Response, path, cycles: float = 5.0) -> Path:
    """Displacement and velocity of pinion and gear centres in x, y over the last ``cycles`` mesh periods."""
    plt = _pyplot()
    t_end = res.t[-1]
    sel = res.t >= t_end - cycles / res.mesh_frequency
    t_ms = (res.t[sel] - res.t[sel][0]) * 1e3
    fig, axes = plt.subplots(2, 2, figsize=(10, 6), sharex=True)
    for col, member in enumerate(("pinion", "gear")):
        d = res.member(member, "displacement")[sel]
        v = res.member(member, "velocity")[sel]
        for k, ax_name in enumerate("xy"):
            axes[0, col].plot(t_ms, (d[:, k] - d[:, k].mean()) * 1e6, label=ax_name)
            axes[1, col].plot(t_ms, (v[:, k] - v[:, k].mean()) * 1e3, label=ax_name)
        axes[0, col].set_title(f"{member} centre")
        axes[0, col].set_ylabel("displacement − mean [µm]")
        axes[1, col].set_ylabel("velocity − mean [mm/s]")
        axes[1, col].set_xlabel("t [ms]")
        axes[0, col].legend()
    return _save(fig, path)


def plot_mesh_force(res: Response, path, cycles: float = 5.0) -> Path:
    plt = _pyplot()
    sel = res.t >= res.t[-1] - cycles / res.mesh_frequency
    t_ms = (res.t[sel] - res.t[sel][0]) * 1e3
    fig, ax = plt.subplots(figsize=(8, 4))
    for s, side in enumerate(("left", "right")):
        ax.plot(t_ms, res.mesh_force[sel, s], label=f"{side} helix")
    ax.set_xlabel("t [ms]")
    ax.set_ylabel("dynamic mesh force N [N]")
    ax.legend()
    return _save(fig, path)


def plot_phase_planes(res: Response, path) -> Path:
    """Velocity against displacement (about their means) of pinion and gear in x and y."""
    plt = _pyplot()
    fig, axes = plt.subplots(1, 2, figsize=(10, 4.5))
    for col, member in enumerate(("pinion", "gear")):
        d = res.member(member, "displacement")
        v = res.member(member, "velocity")
        for k, ax_name in enumerate("xy"):
            axes[col].plot((d[:, k] - d[:, k].mean()) * 1e6, (v[:, k] - v[:, k].mean()) * 1e3, lw=0.6, label=ax_name)
        axes[col].set_title(f"{member}: phase plane")
        axes[col].set_xlabel("displacement [µm]")
        axes[col].set_ylabel("velocity [mm/s]")
        axes[col].legend()
    return _save(fig, path)


def plot_spectra(res: Response, path, max_order: float = 32.0) -> Path:
    """Hanning spectra of the DTE and of the gear's y acceleration at a bearing, with mesh orders."""
    plt = _pyplot()
    dt = float(np.median(np.diff(res.t)))
    specs = [("DTE [µm]", spectrum(res.dte, dt, res.mesh_frequency), 1e6),
             ("gear bearing acceleration y [m/s²]", spectrum(res.bearing_acceleration[:, 2, 1], dt, res.mesh_frequency), 1.0)]
    fig, axes = plt.subplots(len(specs), 1, figsize=(9, 6), sharex=True)
    for ax, (label, sp, scale) in zip(axes, specs):
        sel = sp.order <= max_order
        ax.plot(sp.order[sel], sp.amplitude[sel] * scale)
        ax.set_ylabel(label)
        for k in range(1, int(max_order) + 1):
            ax.axvline(k, color="0.8", lw=0.6, zorder=0)
    axes[-1].set_xlabel("mesh order f/f_m  (f_m = %.1f Hz)" % res.mesh_frequency)
    return _save(fig, path)


def plot_sweep(sweep, path, modal=None) -> Path:
    """DTE RMS against mesh frequency, with the natural frequencies (mesh energy ≥ 5 %) marked."""
    plt = _pyplot()
    fig, ax = plt.subplots(figsize=(8, 4))
    ax.plot(sweep.mesh_frequency, sweep.dte_rms * 1e6, "o-", ms=3)
    if modal is not None:
        for f, e in zip(modal.frequencies, modal.energy["mesh"]):
            if f > 0 and e >= 0.05 and sweep.mesh_frequency.min() <= f <= sweep.mesh_frequency.max():
                ax.axvline(f, color="C3", ls="--", lw=0.8)
                ax.text(f, ax.get_ylim()[1] * 0.95, f" {f:.0f} Hz", color="C3", va="top", fontsize=8)
    ax.set_xlabel("mesh frequency [Hz]")
    ax.set_ylabel("DTE RMS [µm]")
    return _save(fig, path)


def plot_branches(up, down, path) -> Path:
    """Kahraman–Singh sweeps: amplitude of up- and down-sweep against Ω."""
    plt = _pyplot()
    fig, ax = plt.subplots(figsize=(7, 4))
    ax.plot(up.frequency, up.amplitude, "o-", ms=3, label="sweep up")
    ax.plot(down.frequency, down.amplitude, "s--", ms=3, label="sweep down")
    ax.set_xlabel("Ω = ω/ω_n")
    ax.set_ylabel("amplitude / b")
    ax.legend()
    return _save(fig, path)
