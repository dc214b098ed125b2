"""Whine against speed in the frequency domain (issue 42 item 2): a 200-speed sweep by harmonic balance against the
time-domain sweep of the same scene, timed in the same run, and their agreement.

    python studies/benchmarks/harmonic_sweep.py [--scenes baseline marine] [--speeds 200] [--rpm 300 3000]
                                                [--repeats 3] [--legacy]

For each scene, the same speeds (``--speeds`` between ``--rpm``), three ways:

1. ``harmonic``: :func:`femgear.system.dynamics.harmonic_sweep.harmonic_sweep` with ``method="harmonic"`` (one
   :class:`~femgear.system.dynamics.family.SpeedFamily`, the harmonic balance per speed; speeds where the flanks
   separate would run in the time domain and are counted);
2. ``time``: the same function with ``method="time"``: the same models, each integrated by the default integrator
   and step over 100 mesh periods (50 dropped), the mesh orders read by the line fit — the time-domain sweep of the
   same scene;
3. ``--legacy``: :func:`femgear.system.dynamics.sweep.speed_sweep` (the model rebuilt at every speed), as
   ``femgear dynamics --sweep`` ran before.

Wall time: median of ``--repeats`` calls each (interleaved); the ratio time/harmonic of the medians is the figure
(acceptance: ≥ 20).  Agreement: the largest relative difference of the mesh-order lines (orders 1–6, both helices,
the twelve bearing-load components) above 6e-5 of the mean mesh force (the time integration's own line error is
~6e-7 of it, ``tests/dynamics/test_harmonic.py``) and of the DTE RMS.  Timings on a shared machine are noisy: quote
the ratio of one run.  Writes ``out/benchmarks/harmonic_sweep.json`` and prints a table and one JSON line.
"""

from __future__ import annotations

import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")   # many small dense products: threads only contend

import argparse
import json
import statistics
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[2]
SCENES = {"baseline": ROOT / "studies" / "paper_baseline.toml", "marine": ROOT / "studies" / "zoo" / "marine.toml"}
FLOOR = 6e-5


def setup(scene: str):
    from femgear.case import build_case
    from femgear.scene import load_scene

    return build_case(load_scene(SCENES[scene]))


def compare(hb, td) -> dict:
    """Largest relative differences of the harmonic-balance sweep ``hb`` against the time-domain one ``td``: mesh-order
    lines of the mesh force and bearing loads above the floor, and the DTE RMS."""
    floor = FLOOR * np.abs(td.mesh_force_mean).max(axis=1)                       # per speed [N]
    out = {}
    for key, a, b in (("mesh_force", hb.mesh_force, td.mesh_force), ("bearing_force", hb.bearing_force, td.bearing_force)):
        f = floor.reshape((-1,) + (1,) * (b.ndim - 1))
        big = b >= f
        out[f"{key}_max_rel"] = float(np.abs(a[big] / b[big] - 1).max(initial=0.0))
        out[f"{key}_lines"] = int(big.sum())
    out["dte_rms_max_rel"] = float(np.abs(hb.dte_rms / td.dte_rms - 1).max())
    return out


def run(scenes=("baseline",), speeds: int = 200, rpm=(300.0, 3000.0), repeats: int = 3, legacy: bool = False,
        coarse: bool = False) -> dict:
    from femgear.system.dynamics.harmonic_sweep import harmonic_sweep
    from femgear.system.dynamics.sweep import speed_sweep

    if coarse:
        speeds, repeats = min(speeds, 6), 1
    out = {}
    for scene in scenes:
        case = setup(scene)
        grid = np.linspace(rpm[0], rpm[1], speeds)
        jobs = {"harmonic": lambda: harmonic_sweep(case, grid, method="harmonic"),
                "time": lambda: harmonic_sweep(case, grid, method="time")}
        if legacy:
            jobs["legacy"] = lambda: speed_sweep(case, grid)
        times: dict[str, list[float]] = {k: [] for k in jobs}
        results = {}
        for _ in range(repeats):
            for key, job in jobs.items():
                t0 = time.perf_counter()
                results[key] = job()
                times[key].append(time.perf_counter() - t0)
        hb, td = results["harmonic"], results["time"]
        med = {k: statistics.median(v) for k, v in times.items()}
        out[scene] = {"speeds": speeds, "rpm": list(rpm), "repeats": repeats, "seconds": med,
                      "ratio": med["time"] / med["harmonic"],
                      "per_speed_ms": {k: 1e3 * v / speeds for k, v in med.items()},
                      "handed_to_time": int(sum(m == "time" for m in hb.method)), **compare(hb, td)}
    return out


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--scenes", nargs="+", choices=sorted(SCENES), default=["baseline"])
    ap.add_argument("--speeds", type=int, default=200)
    ap.add_argument("--rpm", type=float, nargs=2, default=(300.0, 3000.0), metavar=("RPM0", "RPM1"))
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--legacy", action="store_true", help="also time speed_sweep (the model rebuilt at every speed)")
    args = ap.parse_args(argv)
    res = run(tuple(args.scenes), args.speeds, tuple(args.rpm), args.repeats, args.legacy)
    print(f"{'scene':10s} {'speeds':>6s} {'harmonic [s]':>12s} {'time [s]':>9s} {'ratio':>7s} "
          f"{'mesh lines':>10s} {'max diff':>8s} {'bearing lines':>13s} {'max diff':>8s} {'DTE RMS':>8s}")
    for scene, r in res.items():
        s = r["seconds"]
        print(f"{scene:10s} {r['speeds']:6d} {s['harmonic']:12.2f} {s['time']:9.1f} {r['ratio']:7.1f} "
              f"{r['mesh_force_lines']:10d} {100 * r['mesh_force_max_rel']:7.2f}% {r['bearing_force_lines']:13d} "
              f"{100 * r['bearing_force_max_rel']:7.2f}% {100 * r['dte_rms_max_rel']:7.2f}%"
              + (f"   legacy {s['legacy']:.1f} s" if "legacy" in s else ""))
    (ROOT / "out" / "benchmarks").mkdir(parents=True, exist_ok=True)
    payload = {"benchmark": "harmonic_sweep", "load_average": os.getloadavg()[0], "scenes": res}
    (ROOT / "out" / "benchmarks" / "harmonic_sweep.json").write_text(json.dumps(payload, indent=1))
    print(json.dumps(payload))


if __name__ == "__main__":
    main()
