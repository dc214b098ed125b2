"""Plots along the path of contact."""

from __future__ import annotations

from femgear.edge.plot import pyplot
from femgear.physics.contact.path import ContactPath


def _finish(fig, axes, title: str):
    """Mark the pitch point, add a grid and the title; returns the figure."""
    for ax in axes:
        ax.axvline(0, color="0.6", lw=0.8, ls=":")
        ax.grid(alpha=0.3)
    if title:
        fig.suptitle(title)
    return fig


def plot_contact_path(result: ContactPath, title: str = ""):
    """Hertz pressure, film thickness and sliding speed against the position on the path."""
    plt = pyplot()

    s_mm = result.kin.s * 1e3
    fig, axes = plt.subplots(3, 1, figsize=(6.5, 7.5), sharex=True)
    axes[0].plot(s_mm, result.hertz_pressure / 1e9, "k-")
    axes[0].set_ylabel("Hertz pressure p_H [GPa]")
    axes[1].plot(s_mm, result.film_central * 1e6, "b-", label="h_c, Moes (1992)")
    axes[1].plot(s_mm, result.film_central_dt * 1e6, "b--", label="h_c, Dowson–Toyoda")
    axes[1].plot(s_mm, result.film_minimum * 1e6, "r-", label="h_min, Dowson–Higginson")
    axes[1].set_ylabel("film thickness [µm]")
    axes[1].legend(fontsize=8)
    axes[2].plot(s_mm, result.kin.vs, "g-", label="sliding v1 − v2")
    axes[2].plot(s_mm, result.kin.ue, "m--", label="entrainment (v1 + v2)/2")
    axes[2].axhline(0, color="0.6", lw=0.8)
    axes[2].set_ylabel("speed [m/s]")
    axes[2].set_xlabel("distance from the pitch point along the line of action [mm]")
    axes[2].legend(fontsize=8)
    return _finish(fig, axes, title)


def plot_friction_path(s, mu, temperature_rise, title: str = ""):
    """Friction coefficient and maximum contact temperature rise along the path."""
    plt = pyplot()

    fig, axes = plt.subplots(2, 1, figsize=(6.5, 5.5), sharex=True)
    axes[0].plot(s * 1e3, mu, "k-")
    axes[0].set_ylabel("friction coefficient μ [-]")
    axes[1].plot(s * 1e3, temperature_rise, "r-")
    axes[1].set_ylabel("max oil temperature rise [K]")
    axes[1].set_xlabel("distance from the pitch point along the line of action [mm]")
    return _finish(fig, axes, title)
