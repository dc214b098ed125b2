"""Grid convergence of the point-contact EHL solver: Hc, Hmin, Pmax per level and the
observed order p = log2(|H_{k-1} - H_{k-2}| / |H_k - H_{k-1}|), Richardson-extrapolated Hc
and its distance to the NVM formula.  One nested solve per case gives every level.
Usage: python studies/ehl/ehl_grid_convergence.py [--lmax 4] [--cases 20,10 200,10]
"""

from __future__ import annotations

import argparse
import json
import math
import sys

from femgear.physics.contact.film import nvm_central
from femgear.physics.ehl.point import solve_point


def setup() -> argparse.Namespace:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--lmax", type=int, default=4)
    ap.add_argument("--cases", nargs="*", default=["20,10", "100,10", "200,10"])
    return ap.parse_args()


def observed_order(h: list[float]) -> list[float | None]:
    """Order from three consecutive values of a sequence on grids refined by 2."""
    out: list[float | None] = [None, None]
    for k in range(2, len(h)):
        d1, d2 = h[k - 1] - h[k - 2], h[k] - h[k - 1]
        out.append(math.log2(abs(d1 / d2)) if d2 != 0 and d1 != 0 else None)
    return out


def richardson(values: list[float]) -> tuple[float, float | None]:
    """Richardson-extrapolated last value of a sequence refined by 2, with the observed
    order of its last three members; the last value itself when no positive order shows."""
    p = observed_order(values)[-1] if len(values) >= 3 else None
    if p and p > 0:
        return values[-1] + (values[-1] - values[-2]) / (2**p - 1), p
    return values[-1], None


def run(args: argparse.Namespace) -> list[dict]:
    table = []
    for case in args.cases:
        M, L = (float(v) for v in case.split(","))
        r = solve_point(M, L, level=args.lmax)
        hc = [lv["Hc"] for lv in r.levels]
        p = observed_order(hc)
        nvm = float(nvm_central(M, L))
        print(f"\n(M, L) = ({M:g}, {L:g}); NVM Hc = {nvm:.4f}")
        print(f"{'nodes':>7} {'h':>8} {'Hc':>8} {'Hmin':>8} {'Pmax':>7} {'change %':>9} {'order':>6} {'t (s)':>7}")
        for k, lv in enumerate(r.levels):
            ch = "" if k == 0 else f"{100 * (hc[k] / hc[k - 1] - 1):+.3f}"
            po = "" if p[k] is None else f"{p[k]:.2f}"
            print(f"{lv['nodes']:>7} {lv['h']:>8.4f} {lv['Hc']:>8.4f} {lv['Hmin']:>8.4f} "
                  f"{lv['Pmax']:>7.3f} {ch:>9} {po:>6} {lv['seconds']:>7.1f}")
        row = {"M": M, "L": L, "Hc": hc, "order": p, "nvm": nvm}
        ext, order = richardson(hc)
        if order:
            row["Hc_richardson"] = ext
            print(f"Richardson Hc = {ext:.4f} ({100 * (ext / nvm - 1):+.2f} % vs NVM)")
        table.append(row)
    return table


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    print(json.dumps({"study": "ehl_grid_convergence", "cases": run(setup())}, separators=(",", ":")))
    return 0


if __name__ == "__main__":
    sys.exit(main())
