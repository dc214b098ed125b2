"""Benchmark: how the cost of one converged line EHL solve grows with the grid (issue 43 item 1).

    python studies/benchmarks/line_scaling.py [--M 1000] [--L 4.3] [--levels 5-10] [--repeats 3]
                                              [--dense-max 4097] [--viscosity barus] [--ph PA] [--compressible]
                                              [--json FILE]

Per refinement level k (16 * 2**k + 1 nodes, 513 ... 16385 by default) one nested solve up to that level
(``solve_line_fd(M, L, level=k, tol=None)``: the levels from the cold start up, which is what a solve converged
to its tolerance on that level costs) by both paths of :mod:`femgear.physics.ehl.fd.line`:

* ``dense``: the dense kernel and LU on every level (``fast=False``; up to ``--dense-max`` nodes, the cost grows
  like n^2-n^3);
* ``fast``: the HODLR kernel and factorisation of :mod:`femgear.physics.ehl.fd.line_fast` on every level
  (``fast=True``);
* ``auto``: what the solver picks (dense up to ``DENSE_NODES``, HODLR above), the user-facing default.

For each: CPU seconds (process time), the median of ``--repeats`` solves with the kernels cached (as along a path
or a thermal loop), and the first solve, which builds the kernels (``cold``); Hc, Hmin and the difference between
the paths (the Newton tolerance is 1e-8); the growth of the median per doubling of n beside N log N's
2 (1 + 1/log2 N), and the exponent p of t ~ n^p fitted over the levels.  Then the default solve to 1 % (target
<= 0.5 s).  CPU seconds are process time with OPENBLAS_NUM_THREADS=1; the machine may be shared, so the ratios,
measured in one run, are the figures to read.
"""

from __future__ import annotations

import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import argparse
import json
import math
import statistics
import time
from pathlib import Path

import numpy as np

from femgear.physics.ehl.fd import line as fdl

PATHS = {"dense": False, "fast": True, "auto": None}


def _levels(text: str) -> list[int]:
    lo, _, hi = text.partition("-")
    return list(range(int(lo), int(hi or lo) + 1))


def time_level(M: float, L: float, k: int, path: str, repeats: int, rheology: dict) -> dict:
    """Cold and warm CPU seconds of the nested solve up to level ``k`` by ``path``."""
    fdl._kernel.cache_clear()
    cpu, r = [], None
    for _ in range(max(repeats, 1) + 1):
        t = time.process_time()
        r = fdl.solve_line_fd(M, L, level=k, tol=None, max_level=k, fast=PATHS[path], **rheology)
        cpu.append(time.process_time() - t)
    return {"path": path, "level": k, "nodes": r.nodes, "cold": cpu[0], "cpu": statistics.median(cpu[1:]),
            "Hc": r.Hc, "Hmin": r.Hmin, "newton": [lv["iterations"] for lv in r.levels],
            "krylov": int(sum(r.history["krylov"]))}


def growth(rows: list[dict]) -> dict:
    """Ratios per doubling of the median, and the exponent fitted to them."""
    n = np.array([r["nodes"] for r in rows], float)
    t = np.array([r["cpu"] for r in rows], float)
    ratios = list(t[1:] / t[:-1])
    p = float(np.polyfit(np.log(n), np.log(t), 1)[0]) if n.size >= 2 else float("nan")
    return {"ratios": ratios, "exponent": p,
            "nlogn": [2.0 * (1.0 + 1.0 / math.log2(x)) for x in n[1:]]}


def main(argv: list[str] | None = None) -> dict:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--M", type=float, default=1000.0)
    ap.add_argument("--L", type=float, default=4.3)
    ap.add_argument("--levels", default="5-10", help="refinement levels k, 16 2^k + 1 nodes (default 5-10)")
    ap.add_argument("--repeats", type=int, default=3, help="warm solves per level (median)")
    ap.add_argument("--dense-max", type=int, default=4097, help="largest grid solved by the dense path")
    ap.add_argument("--viscosity", default="barus", choices=("barus", "roelands"))
    ap.add_argument("--ph", type=float, help="Hertz pressure [Pa] (Roelands and Dowson-Higginson need it)")
    ap.add_argument("--compressible", action="store_true", help="Dowson-Higginson density")
    ap.add_argument("--json", help="write the figures to this file")
    args = ap.parse_args(argv)
    if (args.viscosity == "roelands" or args.compressible) and not args.ph:
        ap.error("--ph is needed with --viscosity roelands or --compressible")
    rheology = dict(viscosity=args.viscosity, ph=args.ph, compressible=args.compressible)
    out: dict = {"M": args.M, "L": args.L, **rheology, "dense_nodes": fdl.DENSE_NODES, "paths": {}}
    print(f"(M, L) = ({args.M:g}, {args.L:g}), {args.viscosity}{', Dowson-Higginson' if args.compressible else ''}"
          f"; CPU s, median of {args.repeats} warm solves")
    print(f"{'path':6} {'nodes':>6} {'cold':>8} {'warm':>8} {'x/doubling':>10} {'NlogN':>6} "
          f"{'Hc':>14} {'Hmin':>14} {'|dHc|, |dHmin| vs dense':>24}")
    for path in PATHS:
        rows = []
        for k in _levels(args.levels):
            if path == "dense" and 16 * 2**k + 1 > args.dense_max:
                continue
            row = time_level(args.M, args.L, k, path, args.repeats if path != "dense" or k < 9 else 1,
                             rheology)
            ref = next((d for d in out["paths"].get("dense", {}).get("rows", []) if d["level"] == k), None)
            if ref is not None and path != "dense":
                row["dHc"], row["dHmin"] = abs(row["Hc"] - ref["Hc"]), abs(row["Hmin"] - ref["Hmin"])
            ratio = f"{row['cpu'] / rows[-1]['cpu']:10.2f}" if rows else " " * 10
            nlogn = f"{2 * (1 + 1 / math.log2(row['nodes'])):6.2f}" if rows else " " * 6
            diff = f"{row['dHc']:.1e}, {row['dHmin']:.1e}" if "dHc" in row else ""
            print(f"{path:6} {row['nodes']:6d} {row['cold']:8.3f} {row['cpu']:8.3f} {ratio} {nlogn} "
                  f"{row['Hc']:14.10f} {row['Hmin']:14.10f} {diff:>24}", flush=True)
            rows.append(row)
        g = growth(rows)
        out["paths"][path] = {"rows": rows, **g}
        print(f"{path:6} fitted exponent t ~ n^{g['exponent']:.2f} over {rows[0]['nodes']}-{rows[-1]['nodes']} "
              f"nodes; growth per doubling {', '.join(f'{x:.2f}' for x in g['ratios'])}")
    cpu = []
    for _ in range(3):
        t = time.process_time()
        r = fdl.solve_line_fd(1000.0, 4.3, tol=0.01)
        cpu.append(time.process_time() - t)
    out["default_1000_4.3"] = {"cpu": statistics.median(cpu), "nodes": r.nodes, "Hc": r.Hc, "Hmin": r.Hmin,
                               "estimate": max(r.error_estimate.values())}
    print(f"default solve (1000, 4.3) to 1 %: {statistics.median(cpu):.3f} s CPU (median of 3), {r.nodes} nodes, "
          f"estimate {max(r.error_estimate.values()):.2%} (target <= 0.5 s)")
    if args.json:
        Path(args.json).write_text(json.dumps(out, indent=1))
    return out


if __name__ == "__main__":
    main()
