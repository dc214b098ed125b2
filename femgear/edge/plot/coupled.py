"""Figures of the coupled results: the fields along the path and the convergence history."""

from __future__ import annotations

import numpy as np

from femgear.edge.plot import pyplot


def plot_coupled_path(s: np.ndarray, load_per_length: np.ndarray,
                      mu: np.ndarray | None = None, temperature_rise: np.ndarray | None = None,
                      thermal_deviation: np.ndarray | None = None, wear: np.ndarray | None = None,
                      wear_cycles: float = 0.0, title: str = ""):
    """Load per length, μ and ΔT, thermal deviation and wear of both members against the path position.

    ``thermal_deviation`` and ``wear`` are (2, n) arrays (pinion, gear) [m]; None leaves a panel out.
    """
    plt = pyplot()
    panels = [("load", True), ("friction", mu is not None), ("thermal", thermal_deviation is not None),
              ("wear", wear is not None)]
    panels = [name for name, on in panels if on]
    fig, axes = plt.subplots(len(panels), 1, figsize=(7, 2.4 * len(panels) + 0.6), sharex=True, squeeze=False)
    s_mm = np.asarray(s) * 1e3
    for ax, name in zip(axes[:, 0], panels):
        if name == "load":
            ax.plot(s_mm, np.asarray(load_per_length) / 1e3, "k-")
            ax.set_ylabel("load per length w' [N/mm]")
        elif name == "friction":
            ax.plot(s_mm, mu, "C0-")
            ax.set_ylabel("friction coefficient μ [-]", color="C0")
            if temperature_rise is not None:
                twin = ax.twinx()
                twin.plot(s_mm, temperature_rise, "C3--")
                twin.set_ylabel("contact temperature rise ΔT [K]", color="C3")
        elif name == "thermal":
            _members(ax, s_mm, thermal_deviation, "thermal flank\ndeviation ζ_T [µm]")
        else:
            _members(ax, s_mm, wear, f"wear depth [µm]\nafter {wear_cycles:g} cycles")
        ax.axvline(0, color="0.6", lw=0.8, ls=":")
        ax.grid(alpha=0.3)
    axes[-1, 0].set_xlabel("distance from the pitch point along the line of action [mm]")
    if title:
        fig.suptitle(title)
    return fig


def _members(ax, s_mm, values, label) -> None:
    values = np.asarray(values)
    ax.plot(s_mm, values[0] * 1e6, "C0-", lw=2.0, alpha=0.7, label="pinion")
    ax.plot(s_mm, values[1] * 1e6, "C1--", lw=1.2, label="gear")
    ax.set_ylabel(label)
    ax.legend(fontsize=8)


def plot_convergence(iteration, mesh_force_change, mu_change, tol: float = 1e-6, title: str = ""):
    """Change of the dynamic mesh force (relative) and of μ (absolute) per coupling pass, log scale."""
    plt = pyplot()
    from matplotlib.ticker import MaxNLocator

    fig, ax = plt.subplots(figsize=(6, 4))
    for values, style, label in ((mesh_force_change, "o-", "dynamic mesh force (relative change)"),
                                 (mu_change, "s--", "friction coefficient μ (absolute change)")):
        pts = [(i, v) for i, v in zip(iteration, values) if v is not None and v > 0]
        if pts:
            ax.semilogy(*zip(*pts), style, label=label)
    ax.axhline(tol, color="0.5", ls=":", label=f"tolerance {tol:g}")
    ax.set_xlabel("coupling pass")
    ax.xaxis.set_major_locator(MaxNLocator(integer=True))       # passes are whole numbers (was 1.25, 1.5, ...)
    ax.set_ylabel("change from the previous pass")
    ax.legend()
    ax.grid(alpha=0.3, which="both")
    if title:
        ax.set_title(title)
    return fig


__all__ = ["plot_convergence", "plot_coupled_path"]
