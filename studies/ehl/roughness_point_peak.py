"""The seed paper's single roughness peak (its eq. 22) passing through a circular EHL contact.

    python studies/ehl/roughness_point_peak.py [--level=3]

M = 20, L = 10 (Barus, incompressible), 129^2 nodes on [-4.5, 1.5] x [-3, 3] a (the paper:
257^2 on -4a..2a; it gives no A_b, l_b or x0, so they are chosen here): a transverse ridge
A_b = 0.2 H_c(smooth), l_b = 0.25 a on the pinion, pure rolling (c = 1), starting at
x0 = -2 a; BDF2, one cell per step (:func:`femgear.physics.ehl.transient.solve_point_transient`).
Prints the minimum film and the maximum pressure over the passage against the smooth
values and one JSON line; writes out/roughness/point_peak.{json,png} (centre-line film and
pressure with the peak at X = -1, -0.5, 0, 0.5, and Hmin, Pmax against the peak position).
"""

from __future__ import annotations

import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import json
import sys
import time
from pathlib import Path

from femgear.physics.ehl.core import params as pr
from femgear.physics.ehl.core.domain import default_domain
from femgear.physics.ehl.core.surface import paper_peak
from femgear.physics.ehl.transient import solve_point_transient

OUT = Path(__file__).resolve().parents[2] / "out" / "roughness"
M, L, X_START = 20.0, 10.0, -2.0


def setup(level: int = 3) -> dict:
    """The paper's single peak (amplitude 20 % of the smooth central film, half-width 0.25 a) starting at
    X_START, and the time steps of the snapshots at X = -1, -0.5, 0, 0.5 on grid ``level``."""
    dom = default_domain()
    h = (dom.x1 - dom.x0) / (16 * 2**level)
    Hc = 0.4965  # smooth central film at (20, 10), 129^2, Hertzian units (measured; only a scale)
    A, lb = 0.2 * Hc, 0.25

    def feature(X, Y):
        return paper_peak(X, Y, amplitude=A, half_width=lb, x0=X_START)

    snaps = tuple(int(round((p - X_START) / h)) for p in (-1.0, -0.5, 0.0, 0.5))
    return {"level": level, "domain": dom, "h": h, "A": A, "lb": lb, "feature": feature, "snapshots": snaps}


def run(level: int = 3) -> dict:
    s = setup(level)
    dom, h, A, lb, feature, snaps = s["domain"], s["h"], s["A"], s["lb"], s["feature"], s["snapshots"]
    t0 = time.perf_counter()
    r = solve_point_transient(M, L, feature, T_end=1.5 - X_START, level=level, snapshots=snaps)
    nx = int(round((dom.x1 - dom.x0) / h)) + 1
    ny = r.x.size // nx
    centre = {f"{X_START + k * r.dT:.2f}": [v[0].reshape(ny, nx)[ny // 2].tolist(),
                                             v[1].reshape(ny, nx)[ny // 2].tolist()]
              for k, v in r.snapshots.items()}
    out = {"level": level, "A_b": A, "l_b": lb, "Hmin_smooth": float(r.Hmin[0]),
           "Hmin_min": float(r.Hmin.min()), "Pmax_smooth": float(r.Pmax[0]),
           "Pmax_max": float(r.Pmax.max()), "steps": int(r.T.size - 1),
           "newton_mean": float(r.newton[1:].mean()), "seconds": time.perf_counter() - t0,
           "Hmin_moes_factor": pr.point_h_moes_factor(M)}
    OUT.mkdir(parents=True, exist_ok=True)
    (OUT / "point_peak.json").write_text(json.dumps({**out, "T": r.T.tolist(), "Hmin": r.Hmin.tolist(),
                                                     "Pmax": r.Pmax.tolist(), "centre": centre,
                                                     "x": r.x[:nx].tolist()}))
    _plot(r, nx, centre, OUT / "point_peak.png")
    return out


def _plot(r, nx, centre, path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(1, 3, figsize=(15, 4.5))
    x = r.x[:nx]
    for key, (P, H) in centre.items():
        ax[0].plot(x, H, label=f"peak at X={key}")
        ax[1].plot(x, P, label=f"peak at X={key}")
    ax[0].set(xlim=(-2, 1.5), ylim=(0, 1.5), xlabel="X = x/a (Y = 0)", ylabel="H", title="film, centre line")
    ax[1].set(xlim=(-2, 1.5), xlabel="X = x/a (Y = 0)", ylabel="P", title="pressure, centre line")
    ax[0].legend(fontsize=7)
    pos = X_START + r.T
    ax[2].plot(pos, r.Hmin / r.Hmin[0], label="Hmin / Hmin(smooth)")
    ax[2].plot(pos, r.Pmax / r.Pmax[0], label="Pmax / Pmax(smooth)")
    ax[2].set(xlabel="peak position X", title="the paper's single peak (eq. 22) passing, pure rolling")
    ax[2].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    level = next((int(a.split("=")[1]) for a in argv if a.startswith("--level=")), 3)
    res = run(level)
    print(f"Hmin {res['Hmin_min']:.4f} (smooth {res['Hmin_smooth']:.4f}), Pmax {res['Pmax_max']:.3f} "
          f"(smooth {res['Pmax_smooth']:.3f}), {res['steps']} steps, {res['newton_mean']:.2f} Newton/step, "
          f"{res['seconds']:.0f} s")
    print(json.dumps(res))
    return 0


if __name__ == "__main__":
    sys.exit(main())
