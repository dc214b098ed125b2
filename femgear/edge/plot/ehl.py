"""Centre-line figure of an EHL solution (matplotlib imported on the first figure)."""

from __future__ import annotations

import numpy as np

from femgear.edge.plot import pyplot


def plot_centreline(result):
    """P and H along Y = 0 (point contact) or along X (line contact) of an
    :class:`femgear.physics.ehl.results.EHLResult`."""
    plt = pyplot()

    if result.P.ndim == 2:
        j0 = int(np.argmin(np.abs(result.y)))
        P, H = result.P[j0], result.H[j0]
    else:
        P, H = result.P, result.H
    fig, ax = plt.subplots(figsize=(7, 4))
    ax.plot(result.x, P, "b-", label="P = p/p_h")
    ax.set_xlabel("X = x/a")
    ax.set_ylabel("P", color="b")
    ax2 = ax.twinx()
    ax2.plot(result.x, H, "r-", label="H")
    ax2.set_ylabel("H = h R/a^2", color="r")
    ax2.set_ylim(0, 3 * max(result.Hc_hertz, 1e-12))
    ax.set_title(f"{result.kind} contact M={result.M:g} L={result.L:g}: "
                 f"Hc={result.Hc:.4g}, Hmin={result.Hmin:.4g} (Moes)")
    return fig


__all__ = ["plot_centreline"]
