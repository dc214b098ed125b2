"""PNG plots of dynamic responses (matplotlib is imported inside the functions only).

Each function takes frozen results and returns a matplotlib figure (written by :mod:`femgear.edge.io`).
"""

from __future__ import annotations

import numpy as np

from femgear.system.dynamics.response import Response, spectrum


def _pyplot():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def _last_cycles(res: Response, cycles: float) -> np.ndarray:
    return res.t >= res.t[-1] - cycles / res.mesh_frequency


def plot_time_histories(res: Response, cycles: float = 5.0):
    """Displacement and velocity of pinion and gear centres over the last ``cycles`` mesh periods.

    x and y each get their own panel (own scale): on one axis the smaller one hid under the other.
    """
    plt = _pyplot()
    sel = _last_cycles(res, cycles)
    t_ms = (res.t[sel] - res.t[sel][0]) * 1e3
    fig, axes = plt.subplots(4, 2, figsize=(10, 9), sharex=True)
    rows = [("displacement", 0, 1e6, "x − mean [µm]"), ("displacement", 1, 1e6, "y − mean [µm]"),
            ("velocity", 0, 1e3, "ẋ − mean [mm/s]"), ("velocity", 1, 1e3, "ẏ − mean [mm/s]")]
    for col, member in enumerate(("pinion", "gear")):
        for row, (kind, k, scale, label) in enumerate(rows):
            q = res.member(member, kind)[sel, k]
            axes[row, col].plot(t_ms, (q - q.mean()) * scale, color=f"C{k}", lw=1.0)
            axes[row, col].set_ylabel(label)
            axes[row, col].grid(alpha=0.3)
        axes[0, col].set_title(f"{member} centre")
        axes[-1, col].set_xlabel("t [ms]")
    return fig


def plot_mesh_force(res: Response, cycles: float = 5.0):
    """Mesh force per helix (right dashed over left, so equal curves stay visible) and their difference."""
    plt = _pyplot()
    sel = _last_cycles(res, cycles)
    t_ms = (res.t[sel] - res.t[sel][0]) * 1e3
    left, right = res.mesh_force[sel, 0], res.mesh_force[sel, 1]
    fig, (ax, ax_d) = plt.subplots(2, 1, figsize=(8, 6), sharex=True, gridspec_kw={"height_ratios": [2, 1]})
    ax.plot(t_ms, left, color="C0", lw=2.5, alpha=0.6, label="left helix")
    ax.plot(t_ms, right, color="C3", lw=1.2, ls="--", label="right helix")
    ax.set_ylabel("dynamic mesh force N [N]")
    ax.legend()
    diff = right - left
    ax_d.plot(t_ms, diff, color="k", lw=1.0)
    same = np.max(np.abs(diff)) <= 1e-9 * max(np.max(np.abs(left)), 1.0)
    ax_d.set_ylabel("right − left [N]")
    ax_d.set_title("the helices carry equal forces (stagger 0)" if same else "", fontsize=9)
    ax_d.set_xlabel("t [ms]")
    for a in (ax, ax_d):
        a.grid(alpha=0.3)
    return fig


def _smooth_orbit(t: np.ndarray, d: np.ndarray, v: np.ndarray, upsample: int = 8) -> tuple[np.ndarray, np.ndarray]:
    """Displacement by cubic Hermite interpolation (its derivative is the velocity) and velocity by a
    cubic spline, ``upsample`` points per time step: the orbit between the integrator's steps."""
    from scipy.interpolate import CubicHermiteSpline, CubicSpline

    tf = np.linspace(t[0], t[-1], (len(t) - 1) * upsample + 1)
    return CubicHermiteSpline(t, d, v)(tf), CubicSpline(t, v)(tf)


def plot_phase_planes(res: Response, cycles: float = 10.0):
    """Velocity against displacement (about their means) of pinion and gear, x and y in separate panels,
    over the last ``cycles`` mesh periods, interpolated between the time steps."""
    plt = _pyplot()
    sel = _last_cycles(res, cycles)
    t = res.t[sel]
    fig, axes = plt.subplots(2, 2, figsize=(10, 8))
    for col, member in enumerate(("pinion", "gear")):
        d = res.member(member, "displacement")[sel]
        v = res.member(member, "velocity")[sel]
        for row, ax_name in enumerate("xy"):
            x, xd = _smooth_orbit(t, d[:, row] - d[:, row].mean(), v[:, row] - v[:, row].mean())
            ax = axes[row, col]
            ax.plot(x * 1e6, xd * 1e3, lw=0.8, color=f"C{row}")
            ax.set_title(f"{member}, {ax_name}: phase plane ({cycles:g} mesh periods)", fontsize=10)
            ax.set_xlabel(f"{ax_name} − mean [µm]")
            ax.set_ylabel(f"velocity {ax_name} − mean [mm/s]")
            ax.grid(alpha=0.3)
    return fig


def plot_spectra(res: Response, max_order: float = 32.0):
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
    axes[-1].set_xlabel(f"mesh order f/f_m  (f_m = {res.mesh_frequency:.1f} Hz)")
    return fig


def plot_sweep(sweep, modal=None):
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
    return fig


def plot_branches(up, down):
    """Kahraman–Singh sweeps: amplitude of up- and down-sweep against Ω."""
    plt = _pyplot()
    fig, ax = plt.subplots(figsize=(7, 4))
    ax.plot(up.frequency, up.amplitude, "o-", ms=3, label="sweep up")
    ax.plot(down.frequency, down.amplitude, "s--", ms=3, label="sweep down")
    ax.set_xlabel("Ω = ω/ω_n")
    ax.set_ylabel("amplitude / b")
    ax.legend()
    return fig
