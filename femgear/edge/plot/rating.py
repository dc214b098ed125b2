"""The rating figure along the path of contact: ISO's contact temperature and λ beside femgear's own."""

from __future__ import annotations

import numpy as np

from femgear.edge.plot import pyplot
from femgear.edge.plot.path import _finish
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
