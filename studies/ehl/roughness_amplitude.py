"""Amplitude reduction of moving transverse waviness in an EHL line contact.

    python studies/ehl/roughness_amplitude.py [--quick] [--workers=2]

A harmonic waviness A_i cos(2 pi (X - c T)/lambda) on one surface enters the contact
from the inlet (raised-cosine ramp of 0.5 b) and passes through it
(:func:`femgear.physics.ehl.transient.solve_line_transient`: BDF2, one cell per step, level 5 =
513 nodes on [-4.5, 1.5] b). The deformed amplitude A_d is half the peak-to-peak of the
film at X = 0 over the last wavelength, after the front has left the domain (Venner,
Couhier, Lubrecht & Greenwood 1997). Rows:

* pure rolling (c = 1), (M, L) = (20, 10) over nabla = 1 ... 20 and (50, 10) at four
  nabla: the collapse A_d/A_i = F(nabla), nabla = (lambda/b) M^(3/4)/L^(1/2) (read in the
  1997 abstract), and the recalled curve 1/(1 + 0.15 nabla + 0.015 nabla^2);
* A_i = 0.1 and 0.3 H_c (independence of A_i), level 6 (grid and time step halved);
* rolling-sliding, SRR = 0.5, roughness on the faster surface (c = 1.25);
* the seed paper's single peak (eq. 22, A_b = 0.3 H_c, l_b = 0.1 b) passing through the
  contact in pure rolling: its film and pressure at four instants (PNG).

Writes out/roughness/roughness_amplitude.{json,png}; prints a table and one JSON line.
"""

from __future__ import annotations

import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import json
import sys
import time
from concurrent.futures import ProcessPoolExecutor
from functools import partial
from pathlib import Path

import numpy as np

from femgear.physics.ehl.core.surface import paper_peak, surface_speed
from femgear.physics.ehl.transient import (
    amplitude_reduction_fit,
    measure_amplitude_reduction,
    solve_line_transient,
    steady_hc_hertz,
)

OUT = Path(__file__).resolve().parents[2] / "out" / "roughness"
NABLA = (1.0, 2.0, 3.0, 5.0, 7.0, 10.0, 15.0, 20.0)


def cases(quick: bool) -> list[dict]:
    nab = (2.0, 5.0, 10.0) if quick else NABLA
    out = [dict(M=20.0, L=10.0, nabla=n) for n in nab]
    out += [dict(M=50.0, L=10.0, nabla=n) for n in ((5.0,) if quick else (2.0, 5.0, 10.0, 20.0))]
    if not quick:
        out += [dict(M=20.0, L=10.0, nabla=5.0, amp=0.3),
                dict(M=20.0, L=10.0, nabla=2.0, level=6), dict(M=20.0, L=10.0, nabla=10.0, level=6),
                dict(M=20.0, L=10.0, nabla=5.0, srr=0.5)]
    return out


def solve_case(c: dict) -> dict:
    speed = surface_speed(c.get("srr", 0.0), "pinion")
    t0 = time.perf_counter()
    ratio = measure_amplitude_reduction(c["M"], c["L"], c["nabla"], amplitude=c.get("amp", 0.1),
                                        speed=speed, level=c.get("level", 5))
    return {**c, "speed": speed, "Ad_Ai": ratio, "fit": float(amplitude_reduction_fit(c["nabla"])),
            "seconds": time.perf_counter() - t0}


def peak_passage(M: float = 20.0, L: float = 10.0) -> dict:
    """The paper's single peak (eq. 22) carried through the contact in pure rolling."""
    Hc = steady_hc_hertz(M, L)
    feature = partial(paper_peak, amplitude=0.3 * Hc, half_width=0.1, x0=-4.0)
    dT = 6.0 / 512
    steps = tuple(int(round((xc + 4.0) / dT)) for xc in (-1.5, -0.5, 0.0, 0.5))
    r = solve_line_transient(M, L, feature, speed=1.0, T_end=5.0, level=5, snapshots=steps)
    return {"x": r.x.tolist(), "T": r.T.tolist(), "Hmin": r.Hmin.tolist(), "Pmax": r.Pmax.tolist(),
            "snapshots": {str(k): [v[0].tolist(), v[1].tolist()] for k, v in r.snapshots.items()},
            "peak_at": {str(k): -4.0 + k * r.dT for k in r.snapshots}, "Hc": Hc}


def plot(rows: list[dict], peak: dict, path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(1, 3, figsize=(15, 4.5))
    n = np.geomspace(0.5, 30, 200)
    ax[0].semilogx(n, amplitude_reduction_fit(n), "k-", label="1/(1+0.15∇+0.015∇²) (recalled fit)")
    for (M, L), mk in (((20.0, 10.0), "o"), ((50.0, 10.0), "s")):
        sel = [r for r in rows if (r["M"], r["L"]) == (M, L) and r.get("amp", 0.1) == 0.1
               and r.get("level", 5) == 5 and r.get("srr", 0.0) == 0.0]
        ax[0].semilogx([r["nabla"] for r in sel], [r["Ad_Ai"] for r in sel], mk,
                       label=f"femgear, pure rolling, M={M:g}, L={L:g}")
    other = [r for r in rows if r.get("srr", 0.0) != 0.0]
    ax[0].semilogx([r["nabla"] for r in other], [r["Ad_Ai"] for r in other], "r^", label="SRR 0.5 (faster)")
    ax[0].set(xlabel="∇ = (λ/b) M^(3/4) / L^(1/2)", ylabel="A_d / A_i", title="transverse waviness, line contact")
    ax[0].legend(fontsize=7)
    x = np.array(peak["x"])
    for k, (P, H) in peak["snapshots"].items():
        ax[1].plot(x, np.array(H) / peak["Hc"], label=f"peak at X={peak['peak_at'][k]:.2f}")
        ax[2].plot(x, P, label=f"peak at X={peak['peak_at'][k]:.2f}")
    ax[1].set(xlim=(-2, 1.5), ylim=(0, 3), xlabel="X = x/b", ylabel="H / H_c(smooth)",
              title="paper's single peak (eq. 22), A_b = 0.3 H_c, l_b = 0.1 b")
    ax[2].set(xlim=(-2, 1.5), xlabel="X = x/b", ylabel="P = p/p_h", title="pressure")
    ax[1].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def setup(quick: bool = False) -> list[dict]:
    """The transient line cases (:func:`cases`; ``quick``: the short list)."""
    return cases(quick)


def run(quick: bool = False, workers: int = 2) -> dict:
    """Every case's amplitude reduction (a pool of ``workers``) and the peak passage."""
    t0 = time.perf_counter()
    with ProcessPoolExecutor(max_workers=workers) as pool:
        fut_peak = pool.submit(peak_passage)
        rows = list(pool.map(solve_case, setup(quick)))
        peak = fut_peak.result()
    return {"rows": rows, "peak": peak, "seconds": time.perf_counter() - t0}


def main(argv: list[str]) -> dict:
    quick = "--quick" in argv
    workers = next((int(a.split("=")[1]) for a in argv if a.startswith("--workers=")), 2)
    res = run(quick, workers)
    rows, peak = res["rows"], res["peak"]
    print(f"{'M':>5} {'L':>4} {'nabla':>6} {'A_i/Hc':>6} {'level':>5} {'c':>5} {'Ad/Ai':>7} {'fit':>6} {'s':>6}")
    for r in rows:
        print(f"{r['M']:5g} {r['L']:4g} {r['nabla']:6g} {r.get('amp', 0.1):6g} {r.get('level', 5):5d} "
              f"{r['speed']:5.2f} {r['Ad_Ai']:7.3f} {r['fit']:6.3f} {r['seconds']:6.1f}")
    OUT.mkdir(parents=True, exist_ok=True)
    summary = {"rows": rows, "peak_Hmin_min": min(peak["Hmin"]) / peak["Hc"],
               "peak_Pmax_max": max(peak["Pmax"]), "seconds": res["seconds"]}
    (OUT / "roughness_amplitude.json").write_text(json.dumps({**summary, "peak": peak}))
    plot(rows, peak, OUT / "roughness_amplitude.png")
    print(json.dumps(summary))
    return summary


if __name__ == "__main__":
    main(sys.argv[1:])
