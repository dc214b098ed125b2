"""The Campbell (interference) diagram as a PNG figure (matplotlib imported inside the function only)."""

from __future__ import annotations

import numpy as np

from femgear.edge.plot import pyplot
from femgear.system.dynamics.campbell import MESH_ENERGY_MIN, CampbellDiagram, order_frequency

#: short labels of the strain-energy shares
SHORT = {"mesh_L": "mesh L", "mesh_R": "mesh R", "bearing_pinion_L": "brg pL", "bearing_pinion_R": "brg pR",
         "bearing_gear_L": "brg gL", "bearing_gear_R": "brg gR", "loop": "loop", "shafts": "shafts"}


def mode_label(d: CampbellDiagram, mode: int, at: int = 0, top: int = 3) -> str:
    """'f Hz: mesh L 34 %, mesh R 30 %, brg pL 5 %': a mode's frequency at speed index ``at`` and its largest
    strain-energy shares (≥ 1 %)."""
    shares = sorted(((v[at, mode], k) for k, v in d.energy.items() if v[at, mode] >= 0.01), reverse=True)[:top]
    text = ", ".join(f"{SHORT[k]} {100 * v:.0f} %" for v, k in shares)
    return f"{d.frequency[at, mode]:.0f} Hz: {text}"


def plot_campbell(d: CampbellDiagram, name: str = "", f_max: float | None = None):
    """Natural frequencies against driver speed (solid: modes with ≥ 5 % mesh strain energy, labelled with
    their shares; grey: the others), the mesh orders (dashed) and the shaft orders (dotted), and the critical
    speeds (circles) where an order meets a mode with ≥ 5 % mesh strain energy."""
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(11, 7.5))
    n = d.speed_rpm
    meshy = d.mesh_energy.max(axis=0) >= MESH_ENERGY_MIN
    top = f_max or 1.15 * float(np.max(d.frequency[:, meshy] if meshy.any() else d.frequency))
    for mode in range(d.frequency.shape[1]):
        f = d.frequency[:, mode]
        if f.min() > top:
            continue
        if meshy[mode]:
            line, = ax.plot(n, f, lw=1.6)
            ax.text(n[-1], f[-1], " " + mode_label(d, mode, at=-1), fontsize=6.5, va="center",
                    color=line.get_color())
        else:
            ax.plot(n, f, color="0.75", lw=0.8)
    placed: list[float] = []
    for order in d.orders:
        style = "--" if order[0].startswith("mesh") else ":"
        ax.plot(n, order_frequency(d, order, n), style, color="k", lw=0.8, alpha=0.6)
        f_end = order_frequency(d, order, n[-1:])[0]
        if f_end < top:
            while any(abs(f_end - y) < 0.02 * top for y in placed):       # labels of close orders stacked
                f_end += 0.02 * top
            placed.append(f_end)
            ax.text(n[-1], f_end, f" {order[0]}", fontsize=6.5, va="bottom", ha="left", alpha=0.7)
        else:
            x = 60 * top / (order[2] * d.speed_ratio[order[1]])
            ax.text(x, top, order[0], fontsize=6.5, rotation=60, va="top", ha="right", alpha=0.7)
    for c in d.critical:
        if c["frequency_hz"] <= top:
            ax.plot(c["speed_rpm"], c["frequency_hz"], "o", mfc="none", mec="C3", ms=7)
    ax.plot([], [], "o", mfc="none", mec="C3", label=f"critical speed: an order meets a mode with ≥ "
                                                       f"{100 * MESH_ENERGY_MIN:.0f} % mesh strain energy")
    ax.plot([], [], "--", color="k", label="mesh orders (k × z₁ × pinion speed)")
    ax.plot([], [], ":", color="k", label="shaft orders of pinion and gear")
    ax.plot([], [], color="0.75", label="modes with < 5 % mesh strain energy")
    ax.set_xlim(n[0], n[-1] + 0.45 * (n[-1] - n[0]))
    ax.set_ylim(0, top)
    ax.set_xlabel("driver speed [rpm]")
    ax.set_ylabel("natural frequency / excitation frequency [Hz]")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.09), ncol=2, frameon=False)
    title = "Campbell diagram: natural frequencies against speed (gyroscopic, tracked by MAC), labelled with " \
            "their strain-energy shares at the top speed"
    fig.suptitle(f"{name}:\n{title}" if name else title, fontsize=9.5)
    fig.tight_layout()
    return fig
