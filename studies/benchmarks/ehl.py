"""Benchmark: time and memory of the point-contact EHL solver to a 1 % grid-converged Hc.

For (M, L) = (20, 10) and (200, 10), solve with finest level 1..LMAX (nested iteration,
so the time of level k includes all coarser levels), median of REPEATS runs, peak traced
memory of the first run. Prints a table per case with the error of Hc against the finest
level and the change from the previous level, the first level whose change is < 1 %
("1 %-grid-converged"), and one JSON line.  Targets (issue 4): <= 10 s for (20, 10),
<= 60 s for (200, 10).  Usage: python studies/benchmarks/ehl.py [--lmax 4] [--repeats 1]
"""

from __future__ import annotations

import argparse
import json

from femgear.contact.film import nvm_central
from femgear.ehl.point import solve_point
from femgear.perf import measure

CASES = ((20.0, 10.0, 10.0), (200.0, 10.0, 60.0))  # M, L, target seconds


def setup() -> argparse.Namespace:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--lmax", type=int, default=4, help="finest level (4 = 257x257)")
    ap.add_argument("--repeats", type=int, default=1)
    ap.add_argument("--quick", action="store_true", help="levels 1-2 only (CI)")
    return ap.parse_args()


def run(args: argparse.Namespace) -> dict:
    lmax = 2 if args.quick else args.lmax
    out = {}
    for M, L, target in CASES:
        rows = []
        for lev in range(1, lmax + 1):
            m = measure(lambda: solve_point(M, L, level=lev), repeats=args.repeats)
            r = m.value
            rows.append({"level": lev, "nodes": r.nodes, "seconds": m.seconds,
                         "peak_MB": m.peak_bytes / 2**20, "Hc": r.Hc, "Hmin": r.Hmin,
                         "Pmax": r.Pmax, "newton": r.history["level"].count(r.nodes)})
        fin = rows[-1]["Hc"]
        conv = None
        for k, row in enumerate(rows):
            row["err_vs_finest_%"] = 100 * (row["Hc"] / fin - 1)
            row["change_%"] = None if k == 0 else 100 * (row["Hc"] / rows[k - 1]["Hc"] - 1)
            if conv is None and k > 0 and abs(row["change_%"]) < 1.0:
                conv = row
        nvm = float(nvm_central(M, L))
        print(f"\n(M, L) = ({M:g}, {L:g})   NVM Hc = {nvm:.4f}   target {target:g} s")
        print(f"{'level':>5} {'nodes':>7} {'s (med)':>8} {'peak MB':>8} {'Hc':>8} {'Hmin':>7} "
              f"{'Pmax':>6} {'Newton':>6} {'err vs finest %':>15} {'change %':>9}")
        for row in rows:
            ch = "" if row["change_%"] is None else f"{row['change_%']:+.3f}"
            print(f"{row['level']:>5} {row['nodes']:>7} {row['seconds']:>8.2f} {row['peak_MB']:>8.1f} "
                  f"{row['Hc']:>8.4f} {row['Hmin']:>7.4f} {row['Pmax']:>6.3f} {row['newton']:>6} "
                  f"{row['err_vs_finest_%']:>+15.3f} {ch:>9}")
        if conv:
            print(f"1 %-grid-converged at level {conv['level']} ({conv['nodes']} nodes): "
                  f"{conv['seconds']:.1f} s (target {target:g} s: "
                  f"{'met' if conv['seconds'] <= target else 'missed'}); Hc vs NVM "
                  f"{100 * (conv['Hc'] / nvm - 1):+.2f} %")
        else:
            print("not 1 %-grid-converged within the levels run")
        out[f"M{M:g}_L{L:g}"] = {"rows": rows, "converged_level": conv and conv["level"],
                                 "seconds_to_1pct": conv and conv["seconds"], "target_s": target,
                                 "nvm": nvm}
    return out


if __name__ == "__main__":
    res = run(setup())
    print(json.dumps({"benchmark": "ehl", "cases": res}, separators=(",", ":")))
