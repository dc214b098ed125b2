"""Strongly piezoviscous point contacts on refined grids: (M, L) = (20, 20) and (100, 20).

    python studies/ehl/ehl_point_high_alpha.py [--levels 2 3 4] [--cases 20,20 100,20] [--method fas]

For each case and finest level (2 = 65^2, 3 = 129^2, 4 = 257^2) one nested Newton-Krylov
solve (``solve_point(M, L, level=k, method='newton')``, Barus, incompressible: the defaults;
alpha_bar = 19.8 and 33.8, beyond the range of ``method='auto'``'s multigrid), or with
``--method fas`` the multigrid with the HIGH_ALPHA cycles (on 257^2 with the spike
elimination of :mod:`femgear.physics.ehl.fd.eliminate`; a solve whose multigrid fails falls back to
Newton, printed as ``fallback``): wall time, peak traced memory,
Hc, Hmin (Moes units), their Richardson estimates (:mod:`femgear.physics.ehl.core.accuracy`), the
artificial-diffusion factor the finest level needed, and the NVM central film
(Nijenbanning, Venner & Moes 1994; :func:`femgear.physics.contact.film.nvm_central`; the NVM
formula has no minimum film) beside them. A solve that fails prints its error, whose
message says why (:func:`femgear.physics.ehl.fe.newton._stall_reason`: the median damping of the
last Newton steps and the node of the largest Newton component). One run per cell (the
257^2 solves take minutes), timed with tracemalloc on (it slows allocation-heavy code, so
the seconds are an upper bound); the last line is JSON.
"""

from __future__ import annotations

import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import argparse
import json
import math
import sys
import time
import tracemalloc

from femgear.errors import ConvergenceError
from femgear.physics.contact.film import nvm_central
from femgear.physics.ehl.core import params as pr
from femgear.physics.ehl.point import solve_point


def one(M: float, L: float, level: int, method: str = "newton") -> dict:
    """One nested solve to ``level``: figures or the failure."""
    tracemalloc.start()
    t = time.perf_counter()
    try:
        r = solve_point(M, L, level=level, method=method)
        row = {"Hc": r.Hc, "Hmin": r.Hmin, "Pmax": r.Pmax, "error_estimate": r.error_estimate,
               "ad_factor": r.levels[-1].get("ad_factor"), "iterations": r.iterations,
               "flags": list(r.flags), "method": r.history.get("method"),
               "fallback": bool(r.history.get("fallback")),
               "sequence": [(lv["nodes"], lv["Hc"], lv["Hmin"]) for lv in r.levels]}
    except ConvergenceError as exc:
        h = exc.history
        row = {"error": str(exc).split(" (last: ")[0], "iterations": len(h.get("residual", []))}
    row["seconds"] = time.perf_counter() - t
    row["peak_MB"] = tracemalloc.get_traced_memory()[1] / 2**20
    tracemalloc.stop()
    return {"M": M, "L": L, "level": level, "nodes": (16 * 2**level + 1) ** 2,
            "alpha_bar": pr.point_alpha_bar(M, L), "nvm_Hc": float(nvm_central(M, L)), **row}


def show(row: dict) -> None:
    n = int(round(row["nodes"] ** 0.5))
    head = f"({row['M']:g}, {row['L']:g}) {n:>3}^2"
    if "error" in row:
        print(f"{head}: FAILED after {row['seconds']:.0f} s, {row['iterations']} Newton its, "
              f"peak {row['peak_MB']:.0f} MB\n    {row['error']}")
        return
    e = row["error_estimate"]
    fmt = lambda v: "-" if v is None else f"{100 * v:.2f} %"  # noqa: E731
    print(f"{head}: Hc {row['Hc']:.4f} (est {fmt(e['Hc'])}; NVM {row['nvm_Hc']:.4f}, "
          f"{100 * (row['Hc'] / row['nvm_Hc'] - 1):+.1f} %)  Hmin {row['Hmin']:.4f} "
          f"(est {fmt(e['Hmin'])})  Pmax {row['Pmax']:.3f}  ad {row['ad_factor']}  "
          f"{row['seconds']:.1f} s  {row['peak_MB']:.0f} MB  {row['iterations']} its  "
          f"{row['method']}{' (fallback)' if row['fallback'] else ''}")
    seq = row["sequence"][-3:]
    if len(seq) == 3:  # three grids h, h/2, h/4: the observed order log2(d1 / d2)
        for name, i in (("Hc", 1), ("Hmin", 2)):
            d1, d2 = seq[1][i] - seq[0][i], seq[2][i] - seq[1][i]
            order = f"{math.log2(d1 / d2):.2f}" if d1 * d2 > 0 else "-"
            print(f"    {name}: " + " / ".join(f"{s[i]:.5f}" for s in seq) + f"  (observed order {order})")


def setup(argv: list[str] | None = None) -> argparse.Namespace:
    """The command line ``argv`` parsed (defaults: the documented study)."""
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--levels", type=int, nargs="+", default=[2, 3, 4])
    ap.add_argument("--cases", nargs="+", default=["20,20", "100,20"])
    ap.add_argument("--method", default="newton", choices=["newton", "fas", "auto"])
    return ap.parse_args(argv)


def run(args: argparse.Namespace) -> list[dict]:
    """Every (M, L) on every level by ``args.method``."""
    rows = []
    for case in args.cases:
        M, L = (float(v) for v in case.split(","))
        for level in args.levels:
            rows.append(one(M, L, level, args.method))
            show(rows[-1])
    return rows


def main(argv: list[str] | None = None) -> int:
    args = setup(argv)
    rows = run(args)
    print(json.dumps({"study": "ehl_point_high_alpha", "rows": rows}))
    return 0


if __name__ == "__main__":
    sys.exit(main())
