"""Benchmark: cost of a line-contact TEHL solve against the isothermal one, and a TEHL map.

    python studies/benchmarks/tehl.py [--levels 4,5,6] [--repeats 5] [--samples 12] [--quick] [--line-only]

1. At a mid-path contact of the paper baseline (w' = 84.3 kN/m, R = 12.3 mm, u_e = 1.09 m/s,
   oil at 313 K) and SRR 0, 0.3, 1.0: wall time of the isothermal FE line EHL
   (:func:`femgear.physics.ehl.dimensional.solve_line_dimensional`) and of the TEHL solve
   (:func:`femgear.physics.tehl.solve_tehl_line`, which includes its isothermal start) per grid level,
   timed in alternation (iso, TEHL, iso, TEHL, ...: a shared machine's load hits both
   alike), medians and the median of the per-pair ratios (issue 16 target: ≤ 2×); the TEHL solve at that
   level includes its thermal levels below it (the nested iteration of femgear.physics.tehl.line).
2. Point contact at the seed paper's benchmark condition (500 N, 10 m/s, 80 °C, R = 20 mm
   assumed): isothermal FE point EHL vs :func:`femgear.physics.tehl.point.solve_tehl_point` at grid
   level ``--point-level`` (2 = 65 x 65), SRR 0 and 0.3.
3. A friction/temperature map of TEHL solves over the baseline envelope
   (:func:`femgear.physics.tehl.solver.tehl_map`, level 4): build time, and its interpolation error
   against ``--samples`` fresh TEHL solves at random points; the time of one map query.
Prints tables and one JSON line.
"""

from __future__ import annotations

import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import argparse
import json
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[2]
W, R, UE, T0 = 84332.0, 0.0123, 1.09, 313.0


def _median_time(fn, repeats):
    ts = []
    for _ in range(repeats):
        t = time.perf_counter()
        v = fn()
        ts.append(time.perf_counter() - t)
    return float(np.median(ts)), v


def _pairs(iso, tehl, repeats):
    """Alternating timings: (median iso [s], median tehl [s], median of the ratios, last result)."""
    a, b = [], []
    for _ in range(repeats):
        t = time.perf_counter()
        iso()
        a.append(time.perf_counter() - t)
        t = time.perf_counter()
        r = tehl()
        b.append(time.perf_counter() - t)
    a, b = np.array(a), np.array(b)
    return float(np.median(a)), float(np.median(b)), float(np.median(b / a)), r


def _line_rows(levels, repeats, setup, oil):
    """Part 1: the line TEHL against the isothermal solve on the same level."""
    from femgear.physics.ehl.dimensional import solve_line_dimensional
    from femgear.physics.tehl import solve_tehl_line

    rows = []
    print(f"{'level':>5} {'SRR':>5} {'iso [s]':>8} {'tehl [s]':>8} {'ratio':>6} {'its':>4} {'newton':>6} "
          f"{'dT [K]':>7} {'mu':>7} {'estimate':>8}")
    for lev in levels:
        def iso():
            return solve_line_dimensional(W, R, UE, setup["E_red"], oil, level=lev)
        for srr in (0.0, 0.3, 1.0):
            t_iso, t_th, ratio, r = _pairs(iso, lambda: solve_tehl_line(W, R, UE, srr, T0, level=lev, **setup),
                                           repeats)
            est = max(r.error_estimate.values())
            rows.append({"level": lev, "srr": srr, "isothermal_s": t_iso, "tehl_s": t_th, "ratio": ratio,
                         "thermal_iterations": r.iterations, "newton_iterations": r.newton_iterations,
                         "dT_max": r.dT_max, "mu": r.mu, "hc": r.hc, "hmin": r.hmin, "estimate": est})
            print(f"{lev:5d} {srr:5.2f} {t_iso:8.3f} {t_th:8.3f} {ratio:6.2f} {r.iterations:4d} "
                  f"{r.newton_iterations:6d} {r.dT_max:7.2f} {r.mu:7.4f} {100 * est:7.2f}%")
    return rows


def main() -> dict:
    from femgear.case import build_case
    from femgear.levels.lubrication import tehl_axes, tehl_setup
    from femgear.physics.tehl.line import ehl_oil_at
    from femgear.physics.tehl.solver import tehl_line_solver, tehl_map
    from femgear.scene import load_scene

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--levels", default="4,5,6")
    ap.add_argument("--repeats", type=int, default=5)
    ap.add_argument("--samples", type=int, default=12)
    ap.add_argument("--point-level", type=int, default=2)
    ap.add_argument("--quick", action="store_true", help="level 4, one repeat, a 32-point map (CI)")
    ap.add_argument("--line-only", action="store_true", help="part 1 only (the line TEHL against the isothermal)")
    args = ap.parse_args()
    levels = [4] if args.quick else [int(v) for v in args.levels.split(",")]
    repeats = 1 if args.quick else args.repeats
    case = build_case(load_scene(ROOT / "studies" / "paper_baseline.toml"))
    setup = tehl_setup(case).kwargs()
    oil = ehl_oil_at(setup["oil"], T0)
    rows = _line_rows(levels, repeats, setup, oil)
    if args.line_only:
        print(json.dumps({"solve": rows}))
        return {"solve": rows}
    from femgear.physics.ehl.dimensional import solve_point_dimensional
    from femgear.physics.tehl.point import solve_tehl_point

    plev = 1 if args.quick else args.point_level
    poil = ehl_oil_at(setup["oil"], 353.0)
    t_iso_p, _ = _median_time(lambda: solve_point_dimensional(500.0, 0.02, None, 10.0, setup["E_red"], poil,
                                                              level=plev), repeats)
    point_rows = []
    for srr in (0.0, 0.3):
        t_p, r = _median_time(lambda: solve_tehl_point(500.0, 0.02, 10.0, srr, 353.0, level=plev, **setup), repeats)
        point_rows.append({"level": plev, "srr": srr, "isothermal_s": t_iso_p, "tehl_s": t_p, "ratio": t_p / t_iso_p,
                           "hc_um": r.hc * 1e6, "hc_iso_um": r.hc_isothermal * 1e6, "dT_max": r.dT_max, "mu": r.mu})
        print(f"point level {plev} SRR {srr:.2f}: iso {t_iso_p:.2f} s, tehl {t_p:.2f} s, ratio {t_p / t_iso_p:.2f}; "
              f"h_c {r.hc * 1e6:.3f} µm (iso {r.hc_isothermal * 1e6:.3f}; paper 0.82), dT {r.dT_max:.1f} K, "
              f"mu {r.mu:.4f} (paper 0.042)")
    axes = tehl_axes(case)
    if args.quick:
        axes = {k: v[[0, -1]] if k != "srr" else v[[0, 2, -1]] for k, v in axes.items()}
    fmap = tehl_map(tehl_setup(case), axes=axes, level=4)
    n = int(np.prod([v.size for v in axes.values()]))
    err = fmap.validate(tehl_line_solver(tehl_setup(case), level=4), samples=args.samples).error
    q = {k: np.array([float(np.mean(v))]) for k, v in axes.items()}
    t = time.perf_counter()
    for _ in range(1000):
        fmap(**q)
    t_query = (time.perf_counter() - t) / 1000
    mp = {"solves": n, "build_s": fmap.build_seconds, "per_solve_s": fmap.build_seconds / n, "samples": err.samples,
          "mu_max_abs": err.mu_max_abs, "mu_rms_abs": err.mu_rms_abs, "mu_max_rel": err.mu_max_rel,
          "dT_max_abs": err.dT_max_abs, "query_us": t_query * 1e6}
    print(f"map: {n} TEHL solves in {fmap.build_seconds:.1f} s ({mp['per_solve_s']:.2f} s each); error vs "
          f"{err.samples} fresh solves: |Δμ| max {err.mu_max_abs:.4f} (rms {err.mu_rms_abs:.4f}, rel {err.mu_max_rel:.2f}),"
          f" |ΔT| max {err.dT_max_abs:.2f} K; query {t_query * 1e6:.0f} µs")
    out = {"solve": rows, "point": point_rows, "map": mp}
    print(json.dumps(out))
    return out


if __name__ == "__main__":
    main()
