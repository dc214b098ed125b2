"""The rating figures: along the path of contact, ISO's contact temperature and λ beside femgear's own; K_v against
speed, femgear's dynamics beside ISO 6336-1 method B."""

from __future__ import annotations

import numpy as np

from femgear.edge.plot import pyplot
from femgear.edge.plot.path import _finish
from femgear.physics.rating.load_factors import DynamicFactorCurve
from femgear.physics.rating.suite import PairRating


def plot_rating_path(rating: PairRating, u_pitch: float, title: str = ""):
    """Top: ISO/TS 6336-20 contact temperature θ_B = θ_M + θ_fl, the scuffing temperature θ_S and femgear's
    contact temperature; bottom: ISO/TS 6336-22 λ_GF,Y with λ_GFP and femgear's λ = h_min/R_a (°C, mm from C)."""
    plt = pyplot()

    sc, mp, own = rating.scuffing, rating.micropitting, rating.own
    s_iso = (sc.path.u - u_pitch) * 1e3
    fig, axes = plt.subplots(2, 1, figsize=(6.5, 6.5), sharex=True)
    ax = axes[0]
    ax.plot(s_iso, sc.contact_temperature - 273.15, "r-", label=f"ISO/TS 6336-20 θ_B (S_B = {sc.S_B:.2f})")
    ax.axhline(sc.theta_S - 273.15, color="r", ls="--", lw=1, label=f"θ_S (FZG stage {sc.fzg_stage:g})")
    ax.axhline(sc.theta_int - 273.15, color="m", ls="-.", lw=1, label=f"θ_int (S_intS = {sc.S_intS:.2f})")
    if own is not None and own.temperature is not None:
        ax.plot((own.u - u_pitch) * 1e3, own.temperature - 273.15, "k-",
                label=f"femgear ({own.temperature_level})")
    ax.set_ylabel("contact temperature [°C]")
    ax.legend(fontsize=7)
    ax = axes[1]
    ax.plot((mp.u - u_pitch) * 1e3, mp.lambda_GF, "b-", label=f"ISO/TS 6336-22 λ_GF,Y (S_λ = {mp.S_lambda:.2f})")
    ax.axhline(mp.lambda_GFP, color="b", ls="--", lw=1, label="λ_GFP")
    if own is not None:
        ax.plot((own.u - u_pitch) * 1e3, own.specific_film, "k-", label="femgear h_min / R_a")
    ax.set_ylim(0, 1.15 * float(np.max([np.max(mp.lambda_GF), mp.lambda_GFP,
                                         np.max(own.specific_film) if own is not None else 0])))
    ax.set_ylabel("specific film thickness λ [-]")
    ax.set_xlabel("position on the path from the pitch point [mm]")
    ax.legend(fontsize=7)
    return _finish(fig, axes, title)


def plot_dynamic_factor(curve: DynamicFactorCurve, title: str = ""):
    """K_v against the pinion speed: femgear's per helix (the largest dynamic over the static mesh force of the
    time-domain sweep) and ISO 6336-1 method B, on one axis; the resonance ratio N = n₁/n_E1 on the top axis with
    ISO's ranges marked (main resonance N_S … 1.15, the transition to 1.5)."""
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(7.5, 4.5))
    for h, k in enumerate(curve.femgear):
        label = "femgear dynamics" + ("" if curve.femgear.shape[0] == 1 else f", {('left', 'right')[h]} helix")
        ax.plot(curve.speed_rpm, k, "o-" if h == 0 else "s--", ms=3, label=label)
    ax.plot(curve.speed_rpm, curve.iso, "k-", lw=1.5, label=f"ISO 6336-1 method B (n_E1 = {curve.n_E1:.0f} rpm)")
    lo, hi = float(curve.speed_rpm.min()), float(curve.speed_rpm.max())
    for N, style, text in ((curve.N_S, ":", "N_S"), (1.0, "-", "N = 1"), (1.15, ":", "1.15"), (1.5, ":", "1.5")):
        n = N * curve.n_E1
        if lo <= n <= hi:
            ax.axvline(n, color="0.5", ls=style, lw=0.8)
            ax.text(n, ax.get_ylim()[1], text, ha="center", va="bottom", fontsize=7, color="0.4")
    if lo <= curve.N_S * curve.n_E1 and 1.15 * curve.n_E1 <= hi:
        ax.axvspan(curve.N_S * curve.n_E1, 1.15 * curve.n_E1, color="0.9", zorder=0, label="ISO main resonance range")
    top = ax.secondary_xaxis("top", functions=(lambda n: n / curve.n_E1, lambda N: N * curve.n_E1))
    top.set_xlabel("resonance ratio N = n₁ / n_E1 [-]")
    ax.set_xlabel("pinion speed n₁ [rpm]")
    ax.set_ylabel("dynamic factor K_v [-]")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.suptitle(title or "dynamic factor K_v: femgear's dynamics beside ISO 6336-1 method B", fontsize=10)
    fig.tight_layout()
    return fig
