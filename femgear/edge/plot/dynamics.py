"""PNG plots of dynamic responses (matplotlib is imported inside the functions only).

Each function takes frozen results and returns a matplotlib figure (:func:`femgear.edge.io.figures.save_figure`
writes it).  Every
figure carries a title saying what it shows, prefixed with the scene name ``name`` when given;
quantities are spelled out on the axes ("dynamic transmission error (DTE)"), spectra say that
they show peak amplitudes.
"""

from __future__ import annotations

import numpy as np

from femgear.edge.plot import pyplot
from femgear.system.dynamics.modal import resonance_marks
from femgear.system.dynamics.response import Response, spectrum


def _last_cycles(res: Response, cycles: float) -> np.ndarray:
    return res.t >= res.t[-1] - cycles / res.mesh_frequency


def _title(name: str, what: str) -> str:
    """``name: what``, on two lines where one would not fit a figure."""
    what = what.strip()
    if not name:
        return what
    return f"{name}: {what}" if len(name) + len(what) < 80 else f"{name}:\n{what}"


#: the x label of the time histories: the window starts at 0
TIME_LABEL = "time t from the start of the window [ms]"


def plot_time_histories(res: Response, cycles: float = 5.0, name: str = ""):
    """Displacement and velocity of pinion and gear centres over the last ``cycles`` mesh periods.

    x and y each get their own panel (own scale): on one axis the smaller one hid under the other.
    """
    plt = pyplot()
    sel = _last_cycles(res, cycles)
    t_ms = (res.t[sel] - res.t[sel][0]) * 1e3
    fig, axes = plt.subplots(4, 2, figsize=(10, 9), sharex=True)
    rows = [("displacement", 0, 1e6, "displacement\nx − mean [µm]"), ("displacement", 1, 1e6, "displacement\ny − mean [µm]"),
            ("velocity", 0, 1e3, "velocity\nẋ − mean [mm/s]"), ("velocity", 1, 1e3, "velocity\nẏ − mean [mm/s]")]
    for col, member in enumerate(("pinion", "gear")):
        for row, (kind, k, scale, label) in enumerate(rows):
            q = res.member(member, kind)[sel, k]
            axes[row, col].plot(t_ms, (q - q.mean()) * scale, color=f"C{k}", lw=1.0)
            axes[row, col].set_ylabel(label)
            axes[row, col].grid(alpha=0.3)
        axes[0, col].set_title(f"{member} centre")
        axes[-1, col].set_xlabel(TIME_LABEL)
    fig.suptitle(_title(name, f"lateral motion of the pinion and gear centres, last {cycles:g} mesh periods"))
    return fig


def plot_mesh_force(res: Response, cycles: float = 5.0, name: str = ""):
    """Mesh force per helix (right dashed over left, so equal curves stay visible) and their difference; a pair with
    one mesh (single-helical, spur: the right helix carries nothing) shows its one force."""
    plt = pyplot()
    sel = _last_cycles(res, cycles)
    t_ms = (res.t[sel] - res.t[sel][0]) * 1e3
    left, right = res.mesh_force[sel, 0], res.mesh_force[sel, 1]
    if not np.any(res.mesh_force[:, 1]):
        fig, ax = plt.subplots(figsize=(8, 4))
        ax.plot(t_ms, left, color="C0", lw=1.5, label="the mesh (one helix)")
        ax.set_ylabel("dynamic mesh force N [N]")
        ax.set_xlabel(TIME_LABEL)
        ax.grid(alpha=0.3)
        ax.legend()
        fig.suptitle(_title(name, f"dynamic mesh force (normal to the flank), last {cycles:g} mesh periods"))
        return fig
    fig, (ax, ax_d) = plt.subplots(2, 1, figsize=(8, 6), sharex=True, gridspec_kw={"height_ratios": [2, 1]})
    ax.plot(t_ms, left, color="C0", lw=2.5, alpha=0.6, label="left helix")
    ax.plot(t_ms, right, color="C3", lw=1.2, ls="--", label="right helix")
    ax.set_ylabel("dynamic mesh force N [N]")
    ax.legend()
    diff = right - left
    ax_d.plot(t_ms, diff, color="k", lw=1.0)
    same = np.max(np.abs(diff)) <= 1e-9 * max(np.max(np.abs(left)), 1.0)
    ax_d.set_ylabel("force difference\nright − left [N]")
    ax_d.set_title("the helices carry equal forces (stagger 0)" if same else "", fontsize=9)
    ax_d.set_xlabel(TIME_LABEL)
    for a in (ax, ax_d):
        a.grid(alpha=0.3)
    fig.suptitle(_title(name, f"dynamic mesh force per helix (normal to the flank), last {cycles:g} mesh periods"))
    return fig


def _smooth_orbit(t: np.ndarray, d: np.ndarray, v: np.ndarray, upsample: int = 8) -> tuple[np.ndarray, np.ndarray]:
    """Displacement by cubic Hermite interpolation (its derivative is the velocity) and velocity by a
    cubic spline, ``upsample`` points per time step: the orbit between the integrator's steps."""
    from scipy.interpolate import CubicHermiteSpline, CubicSpline

    tf = np.linspace(t[0], t[-1], (len(t) - 1) * upsample + 1)
    return CubicHermiteSpline(t, d, v)(tf), CubicSpline(t, v)(tf)


def plot_phase_planes(res: Response, cycles: float = 10.0, name: str = ""):
    """Velocity against displacement (about their means) of pinion and gear, x and y in separate panels,
    over the last ``cycles`` mesh periods, interpolated between the time steps."""
    plt = pyplot()
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
            ax.set_xlabel(f"displacement {ax_name} − mean [µm]")
            ax.locator_params(axis="x", nbins=6)                 # the default crowded its labels into each other
            ax.set_ylabel(f"velocity {ax_name} − mean [mm/s]")
            ax.grid(alpha=0.3)
    fig.suptitle(_title(name, "phase planes (velocity against displacement) of the pinion and gear centres"))
    return fig


def plot_spectra(res: Response, max_order: float = 32.0, name: str = ""):
    """Hanning-windowed single-sided spectra of the DTE and of the gear's left-bearing y acceleration against
    the mesh order: each line's height is the peak amplitude of that harmonic (a sine of amplitude A shows A,
    :func:`femgear.system.dynamics.response.spectrum`)."""
    plt = pyplot()
    dt = float(np.median(np.diff(res.t)))
    specs = [("dynamic transmission error (DTE)\npeak amplitude [µm]", spectrum(res.dte, dt, res.mesh_frequency), 1e6),
             ("gear left-bearing acceleration y\npeak amplitude [m/s²]",
              spectrum(res.bearing_acceleration[:, 2, 1], dt, res.mesh_frequency), 1.0)]
    fig, axes = plt.subplots(len(specs), 1, figsize=(9, 6.4), sharex=True)
    for ax, (label, sp, scale) in zip(axes, specs):
        sel = sp.order <= max_order
        ax.plot(sp.order[sel], sp.amplitude[sel] * scale)
        ax.set_ylabel(label)
        for k in range(1, int(max_order) + 1):
            ax.axvline(k, color="0.8", lw=0.6, zorder=0)
    axes[-1].set_xlabel(f"mesh order f/f_m  (mesh frequency f_m = {res.mesh_frequency:.1f} Hz)")
    fig.suptitle(_title(name, "spectra (Hanning window, peak amplitudes, not RMS)"))
    return fig


def plot_bearing_forces(res: Response, cycles: float = 5.0, max_order: float = 16.0, name: str = ""):
    """Loads of the four bearing stations: the dynamic part (about the mean) of x, y and z over the last
    ``cycles`` mesh periods (top row per member) and their Hanning spectra against the mesh order (bottom), the
    means and peak-to-peak values in the legends."""
    plt = pyplot()
    loads = res.bearings
    sel = _last_cycles(res, cycles)
    t_ms = (res.t[sel] - res.t[sel][0]) * 1e3
    dt = float(np.median(np.diff(res.t)))
    fig, axes = plt.subplots(2, 2, figsize=(11, 7.5))
    for col, member in enumerate(("pinion", "gear")):
        for j in (2 * col, 2 * col + 1):
            station = loads.stations[j]
            for d, axis in enumerate("xyz"):
                if d == 2 and np.max(np.abs(loads.force[:, j, 2])) <= 1e-9 * np.max(np.abs(loads.force[:, j])):
                    continue            # no axial load (double-helical, lumped): round-off only
                f = loads.force[sel, j, d]
                style = dict(color=f"C{d}", ls="-" if j % 2 == 0 else "--", lw=1.0)
                axes[0, col].plot(t_ms, f - loads.mean[j, d], **style,
                                  label=f"{station} {axis}: mean {loads.mean[j, d]:.4g} N, "
                                        f"p-p {loads.peak_to_peak[j, d]:.3g} N")
                sp = spectrum(loads.force[:, j, d], dt, res.mesh_frequency)
                keep = sp.order <= max_order
                axes[1, col].plot(sp.order[keep], sp.amplitude[keep], **style, label=f"{station} {axis}")
        axes[0, col].set_title(f"{member} bearings: load − mean", fontsize=10)
        axes[0, col].set_xlabel(TIME_LABEL)
        axes[0, col].set_ylabel("bearing load − mean [N]")
        axes[0, col].legend(fontsize=6.5)
        axes[1, col].set_xlabel(f"mesh order f/f_m  (f_m = {res.mesh_frequency:.1f} Hz)")
        axes[1, col].set_ylabel("peak amplitude [N]")
        axes[1, col].legend(fontsize=6.5, ncol=2)
        for ax in axes[:, col]:
            ax.grid(alpha=0.3)
    fig.suptitle(_title(name, f"bearing loads (force of the shaft on each bearing; x, y radial, z axial), "
                              f"last {cycles:g} mesh periods and spectra (Hanning, peak amplitudes)"), fontsize=10)
    fig.tight_layout()
    return fig


def plot_sweep(sweep, modal=None, name: str = "", harmonics: int = 4):
    """RMS of the dynamic transmission error against mesh frequency (driver speed on the top axis), with
    the natural frequencies whose mesh strain energy is ≥ 5 % marked where the mesh frequency or one of
    its first ``harmonics`` harmonics meets them (:func:`resonance_marks`); those modes are listed."""
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(8.5, 5.6))
    fm = np.asarray(sweep.mesh_frequency)
    ax.plot(fm, np.asarray(sweep.dte_rms) * 1e6, "o-", ms=3, label="DTE RMS")
    ax.set_xlabel("mesh frequency f_m [Hz]")
    ax.set_ylabel("dynamic transmission error (DTE)\nRMS [µm]")
    ax.grid(alpha=0.3)
    if fm.size and fm[0] > 0:
        ratio = float(sweep.speed_rpm[0]) / float(fm[0])          # rpm per Hz of mesh frequency
        top = ax.secondary_xaxis("top", functions=(lambda f: f * ratio, lambda r: r / ratio))
        top.set_xlabel("driver speed [rpm]")
    if modal is not None:
        _mark_modes(ax, modal, float(fm.min()), float(fm.max()), harmonics)
    fig.suptitle(_title(name, "speed sweep: dynamic transmission error against mesh frequency"), fontsize=10)
    return fig


def _mark_modes(ax, modal, lo: float, hi: float, harmonics: int) -> None:
    """Vertical lines at the resonant mesh frequencies f_n / k and a legend of the modes they belong to."""
    marks = resonance_marks(modal.frequencies, modal.energy["mesh"], lo, hi, harmonics=harmonics)
    modes = sorted({f_n for _, _, f_n in marks})
    energy = dict(zip(np.asarray(modal.frequencies, dtype=float), modal.energy["mesh"]))
    bottom = ax.get_ylim()[0]
    for x, k, f_n in marks:
        color = f"C{1 + modes.index(f_n) % 9}"
        ax.axvline(x, color=color, ls="--" if k == 1 else ":", lw=1.0)
        ax.text(x, bottom, f"{f_n:.0f} Hz" + (f" / {k} " if k > 1 else " "), color=color, va="bottom",
                ha="right", fontsize=7, rotation=90)
    for f_n in modes:
        ax.plot([], [], color=f"C{1 + modes.index(f_n) % 9}", ls="--",
                label=f"natural frequency f_n = {f_n:.0f} Hz ({100 * energy[f_n]:.0f} % of its strain energy in the mesh)")
    if marks:
        ax.plot([], [], " ", label="dashed: f_m = f_n; dotted: f_m = f_n / k, the k-th mesh harmonic meets f_n")
    if not marks:
        ax.plot([], [], " ", label="no natural frequency with ≥ 5 % mesh energy resonates in this range")
    ax.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.14), frameon=False)


def plot_branches(up, down):
    """Kahraman–Singh sweeps: amplitude of up- and down-sweep against Ω."""
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(7, 4))
    ax.plot(up.frequency, up.amplitude, "o-", ms=3, label="sweep up")
    ax.plot(down.frequency, down.amplitude, "s--", ms=3, label="sweep down")
    ax.set_xlabel("excitation frequency over natural frequency Ω = ω/ω_n [-]")
    ax.set_ylabel("amplitude (half peak-to-peak)\nover the backlash b [-]")
    ax.set_title("Kahraman–Singh backlash oscillator: frequency sweeps up and down", fontsize=10)
    ax.grid(alpha=0.3)
    ax.legend()
    return fig
