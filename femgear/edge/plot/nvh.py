"""PNG plots of whine against speed: the order sweep, the run-up waterfall and cuts, the Kahraman–Singh branches.

Each function takes frozen results and returns a matplotlib figure (saved by
:func:`femgear.edge.io.figures.save_figure`); amplitudes are single-sided peak amplitudes of the lines.
"""

from __future__ import annotations

import numpy as np

from femgear.edge.plot import pyplot
from femgear.edge.plot.dynamics import _title
from femgear.system.dynamics.modal import resonance_marks


def _radial(bearing: np.ndarray) -> np.ndarray:
    """(…, 4, 3, K) station loads → (…, K) the largest radial amplitude √(|F_x|² + |F_y|²) over the stations."""
    return np.sqrt(bearing[..., 0, :] ** 2 + bearing[..., 1, :] ** 2).max(axis=-2)


def _speed_marks(ax, modal, sweep) -> None:
    """Dotted lines at the speeds where mesh order k meets a mode with ≥ 5 % mesh strain energy."""
    if modal is None:
        return
    rpm_per_hz = float(sweep.speed_rpm[0]) / float(sweep.mesh_frequency[0])
    lo, hi = float(sweep.mesh_frequency.min()), float(sweep.mesh_frequency.max())
    for f_m, k, f_n in resonance_marks(modal.frequencies, modal.energy["mesh"], lo, hi, harmonics=len(sweep.orders)):
        ax.axvline(f_m * rpm_per_hz, color="0.5", ls=":", lw=0.8)
        ax.text(f_m * rpm_per_hz, ax.get_ylim()[1], f" {f_n:.0f} Hz / {k}", rotation=90, va="top", fontsize=6,
                color="0.4")


def plot_order_sweep(sweep, modal=None, name: str = ""):
    """Mesh-order amplitudes of the mesh force (left helix; right dashed) and of the largest radial bearing load
    against speed; speeds the time integration answered are marked ×; resonances of modes with ≥ 5 % mesh strain
    energy dotted."""
    plt = pyplot()
    fig, (ax, axb) = plt.subplots(2, 1, figsize=(9, 7.5), sharex=True)
    rpm = np.asarray(sweep.speed_rpm)
    timed = np.array([m == "time" for m in sweep.method])
    for j, k in enumerate(sweep.orders):
        c = f"C{j}"
        ax.semilogy(rpm, sweep.mesh_force[:, 0, j], "-", color=c, lw=1.2, label=f"mesh order {k:g}")
        if not np.allclose(sweep.mesh_force[:, 0, j], sweep.mesh_force[:, 1, j]):
            ax.semilogy(rpm, sweep.mesh_force[:, 1, j], "--", color=c, lw=0.8)
        axb.semilogy(rpm, _radial(sweep.bearing_force)[:, j], "-", color=c, lw=1.2)
        if timed.any():
            ax.semilogy(rpm[timed], sweep.mesh_force[timed, 0, j], "x", color=c, ms=4)
            axb.semilogy(rpm[timed], _radial(sweep.bearing_force)[timed, j], "x", color=c, ms=4)
    ax.set_ylabel("dynamic mesh force, left helix\namplitude per order [N]")
    axb.set_ylabel("largest radial bearing load\namplitude per order [N]")
    axb.set_xlabel("driver speed [rpm]")
    for a in (ax, axb):
        a.grid(alpha=0.3, which="both")
        _speed_marks(a, modal, sweep)
    how = "harmonic balance" + (f"; × time integration ({int(timed.sum())} speeds)" if timed.any() else "")
    ax.legend(fontsize=7, ncol=3, title=how, title_fontsize=7)
    fig.suptitle(_title(name, "whine against speed: mesh-order amplitudes of the mesh and bearing forces"), fontsize=10)
    return fig


def plot_runup(run, omap, steady=None, name: str = "", what: str = "dynamic mesh force, left helix", unit: str = "N"):
    """Run-up: colour map of the order amplitudes (mesh orders) against speed, and the mesh-order cuts, with the
    stepped steady state (harmonic balance at the blocks' speeds, ``steady`` (blocks, K)) as circles."""
    plt = pyplot()
    fig, (ax, axc) = plt.subplots(2, 1, figsize=(9, 8), sharex=True, gridspec_kw={"height_ratios": [3, 2]})
    amp = omap.amplitude if omap.amplitude.ndim == 2 else omap.amplitude[:, :, 0]
    floor = max(float(amp.max()) * 1e-4, 1e-30)
    mesh = ax.pcolormesh(omap.speed, omap.orders / run.teeth, 20 * np.log10(np.maximum(amp, floor) / floor).T,
                         shading="nearest", cmap="viridis")
    fig.colorbar(mesh, ax=ax, label=f"amplitude [dB re {floor:.3g} {unit}]")
    ax.set_ylabel("mesh order f/f_m [-]\n(pinion order / z₁)")
    cuts = omap.cuts if omap.cuts.ndim == 2 else omap.cuts[:, :, 0]
    for j, k in enumerate(omap.mesh_orders):
        axc.semilogy(omap.speed, cuts[:, j], "-", color=f"C{j}", label=f"mesh order {k:g} (run-up)")
        if steady is not None:
            axc.semilogy(omap.speed, steady[:, j], "o", color=f"C{j}", mfc="none", ms=4)
    if steady is not None:
        axc.plot([], [], "o", color="0.3", mfc="none", label="steady state at each speed (harmonic balance)")
    axc.set_ylabel(f"{what}\nmesh-order amplitude [{unit}]")
    axc.set_xlabel("driver speed [rpm]")
    axc.grid(alpha=0.3, which="both")
    axc.legend(fontsize=7, ncol=2)
    span = f"{run.speed[0]:.0f} → {run.speed[-1]:.0f} rpm in {run.ramp_end - run.settle_time:g} s"
    fig.suptitle(_title(name, f"run-up {span}: {what}, order-tracked ({omap.revolutions} revolutions a block)"),
                 fontsize=10)
    return fig


def plot_ks_continuation(up, down, hb):
    """Kahraman–Singh: the swept amplitudes (markers) on the harmonic-balance branch (stable solid, unstable dashed),
    folds marked."""
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(7.5, 4.5))
    f, a, s = hb.frequency, hb.amplitude, hb.stable
    for i in range(f.size - 1):
        ax.plot(f[i:i + 2], a[i:i + 2], "-" if s[i] and s[i + 1] else "--", color="k", lw=1.2 if s[i] else 0.9)
    ax.plot([], [], "k-", label="harmonic balance, stable")
    ax.plot([], [], "k--", label="harmonic balance, unstable")
    ax.plot(up.frequency, up.amplitude, "o", ms=4, color="C0", mfc="none", label="time integration, sweep up")
    ax.plot(down.frequency, down.amplitude, "s", ms=3, color="C3", label="time integration, sweep down")
    for w in hb.folds:
        ax.axvline(w, color="0.6", ls=":", lw=0.8)
    ax.set_xlabel("excitation frequency over natural frequency Ω = ω/ω_n [-]")
    ax.set_ylabel("amplitude (half peak-to-peak)\nover the backlash b [-]")
    ax.set_title("Kahraman–Singh backlash oscillator: continuation through the folds and the swept jumps", fontsize=10)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    return fig
