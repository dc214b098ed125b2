"""PNG plots of the housing layer (matplotlib is imported inside the functions only): the sensors' accelerations
per mesh order over speed and, for the FE housing, the radiated sound power per order and overall."""

from __future__ import annotations

import numpy as np

from femgear.edge.plot import pyplot
from femgear.system.dynamics.housing_result import HousingResult


def plot_housing_orders(h: HousingResult, name: str = "", note: str = ""):
    """Sensor acceleration amplitude per mesh order over the pinion speed (one panel per sensor, up to four; lines
    outside an FRF grid left out); with the FE housing a last panel of L_W per order and overall (σ = 1).
    ``note`` is added to the title (e.g. "fitted on conditions …" for a fitted path)."""
    plt = pyplot()
    s = h.sweep
    n_s = min(len(h.sensors), 4)
    panels = n_s + (s.sound_power is not None)
    cols = min(panels, 3)
    rows = -(-panels // cols)
    fig, axes = plt.subplots(rows, cols, figsize=(4.2 * cols, 3.4 * rows), squeeze=False)
    axes = axes.ravel()
    for i in range(n_s):
        ax = axes[i]
        for k in range(s.frequency.shape[1]):
            a = np.where(s.valid[:, k], np.abs(s.sensor_acceleration[:, k, i]), np.nan)
            ax.semilogy(s.speeds, a, label=f"order {k + 1}", lw=1.0)
        ax.axvline(h.operating.speed, color="k", lw=0.6, ls=":")
        ax.set(title=f"sensor {h.sensors[i]}", xlabel="pinion speed [rev/min]", ylabel="acceleration amplitude [m/s²]")
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=6)
    if s.sound_power is not None:
        ax = axes[n_s]
        for k in range(s.frequency.shape[1]):
            ax.plot(s.speeds, s.sound_power_level[:, k], lw=0.8, label=f"order {k + 1}")
        ax.plot(s.speeds, s.overall_sound_power_level, "k", lw=1.6, label="overall")
        ax.plot(s.speeds, s.overall_a_weighted, "k--", lw=1.2, label="overall, A-weighted")
        ax.set(title="ERP sound power (σ = 1)", xlabel="pinion speed [rev/min]", ylabel="L_W [dB re 1 pW]")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=6)
    for ax in axes[panels:]:
        ax.set_visible(False)
    what = f"housing {h.model} ({h.coupling}): mesh orders over speed, linear response per order"
    fig.suptitle((f"{name}: " if name else "") + what + (f"; {note}" if note else ""), fontsize=10)
    fig.tight_layout()
    return fig
