"""Figures of the LTCA tool: TE curves, TE harmonics, the Harris map, the load over the flank at the worst phase."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from femgear.edge.plot import pyplot
from femgear.physics.ltca.maps import LoadMaps
from femgear.physics.ltca.te import HarrisMap, TEAnalysis


def plot_te_curves(analyses: Sequence[TEAnalysis], title: str = ""):
    """Loaded TE over one mesh period per torque: both helices together (solid), each helix alone (dashed,
    dotted) and the unloaded TE (thin grey), along the normal line of action [µm]."""
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(7.5, 4.5))
    for k, a in enumerate(analyses):
        c = f"C{k % 10}"
        ph = np.append(a.phase, 1.0)
        loop = lambda y: np.append(y, y[0]) * 1e6  # noqa: E731
        mesh = "both helices" if a.n_helices == 2 else "the helix"
        ax.plot(ph, loop(a.lte), "-", color=c, lw=1.8, label=f"{a.torque:g} N m: {mesh} "
                f"(peak-to-peak {a.peak_to_peak * 1e6:.3f} µm)")
        if a.lte_left is not None:
            ax.plot(ph, loop(a.lte_left), "--", color=c, lw=1.0, label="  left helix alone")
            ax.plot(ph, loop(a.lte_right), ":", color=c, lw=1.2, label="  right helix alone")
        ax.plot(ph, loop(a.nlte), "-", color="0.6", lw=0.8)
    ax.plot([], [], "-", color="0.6", lw=0.8, label="unloaded transmission error")
    ax.set_xlabel("mesh phase [base pitches]")
    ax.set_ylabel("transmission error (TE) along the\nnormal line of action [µm]")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, ncol=2 if len(analyses) > 2 else 1)
    ax.set_title(title or "loaded transmission error (TE), loaded tooth contact analysis (LTCA)", fontsize=10)
    return fig


def plot_harmonics(analyses: Sequence[TEAnalysis], title: str = ""):
    """Loaded TE amplitudes at the mesh orders, grouped bars per torque [µm]."""
    plt = pyplot()
    n = analyses[0].harmonics.size
    width = 0.8 / len(analyses)
    fig, ax = plt.subplots(figsize=(7, 4))
    orders = np.arange(1, n + 1)
    for k, a in enumerate(analyses):
        x = orders - 0.4 + (k + 0.5) * width
        ax.bar(x, a.harmonics * 1e6, width, label=f"{a.torque:g} N m")
        if a.harmonics_refined is not None:
            ax.plot(x, a.harmonics_refined * 1e6, "k_", ms=8)
    if analyses[0].harmonics_refined is not None:
        ax.plot([], [], "k_", ms=8, label="2× points per line")
    ax.set_xticks(orders)
    ax.set_xlabel("mesh order (harmonic of the mesh frequency)")
    ax.set_ylabel("loaded transmission error (TE)\npeak amplitude per harmonic [µm]")
    ax.grid(alpha=0.3, axis="y")
    ax.legend(fontsize=8)
    ax.set_title(title or "harmonics of the loaded transmission error (TE), LTCA", fontsize=10)
    return fig


def plot_harris(h: HarrisMap, title: str = ""):
    """Harris map: loaded TE peak-to-peak against torque, with the modification and unmodified [µm]."""
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(6.5, 4.2))
    ax.plot(h.torque, h.peak_to_peak * 1e6, "o-", label="with the scene's modification")
    ax.plot(h.torque, h.peak_to_peak_unmodified * 1e6, "s--", label="unmodified")
    ax.axvline(h.design_torque, color="k", lw=0.8, ls=":", label="design torque")
    ax.set_xlabel("driver torque [N m]")
    ax.set_ylabel("loaded transmission error (TE)\npeak-to-peak [µm]")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    ax.set_title(title or "Harris map: loaded transmission error against torque (LTCA)", fontsize=10)
    return fig


def plot_load_distribution(maps: LoadMaps, title: str = "", name: str = ""):
    """Load per unit length over the pinion's flank of each helix at the phase of the largest pressure
    (roll distance ρ₁ against face coordinate ζ) [N/mm]; loaded edge nodes marked (edge contact)."""
    plt = pyplot()
    m = maps.members[0].fields
    n_h = m["w_worst"].size // (maps.rho.size * maps.zeta.size)       # 1: single-helical or spur
    shape = (n_h, maps.rho.size, maps.zeta.size)
    w = m["w_worst"].reshape(shape) / 1e3
    edge = m["edge_contact"].reshape(shape).astype(bool) & (w > 0)
    fig, axes = plt.subplots(1, n_h, figsize=(5 + 5 * (n_h - 1), 4), sharey=True, squeeze=False)
    axes = axes[0]
    vmax = max(float(w.max()), 1e-12)
    for h, ax in enumerate(axes):
        pc = ax.pcolormesh(maps.zeta * 1e3, maps.rho * 1e3, w[h], shading="nearest", cmap="viridis", vmin=0, vmax=vmax)
        i, k = np.nonzero(edge[h])
        ax.plot(maps.zeta[k] * 1e3, maps.rho[i] * 1e3, "rx", ms=4, label="edge contact" if i.size else None)
        ax.set_xlabel("face coordinate ζ [mm] (groove / apex end at right)" if n_h == 2 else "face coordinate ζ [mm]")
        ax.set_title(("left", "right")[h] + " helix" if n_h == 2 else "the helix")
        if i.size:
            ax.legend(fontsize=7, loc="upper left")
    axes[0].set_ylabel("pinion roll distance ρ₁ [mm] (tip at top)")
    fig.colorbar(pc, ax=axes[-1], label="load per length [N/mm]")
    default = (f"load over the pinion flank at phase {maps.worst_phase:.3f} (largest pressure), "
               f"{maps.torque:g} N m")
    fig.suptitle(title or (f"{name}: {default}" if name else default))
    return fig


__all__ = ["plot_harmonics", "plot_harris", "plot_load_distribution", "plot_te_curves"]
