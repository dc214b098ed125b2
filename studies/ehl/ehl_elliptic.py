"""Elliptic point-contact EHL: Hc against Nijenbanning-Venner-Moes (1994) over lambda = R_x/R_y.

For each (M, L) and lambda the nested solve gives Hc on every level (the domain follows the
Hertz ellipse, stretched cells hy/hx = b/a: :func:`femgear.physics.ehl.core.domain.default_domain`); the table
shows the finest-level Hc, its change from the level below (grid convergence), the deviation
from NVM and from Hamrock-Dowson (1977, exact k), the seconds of the solve and those of the
circular contact (lambda = 1) at the same number of nodes across the contact.

NVM's fit range: the paper's computations span lambda = 1 .. 1/16 (recalled, not read:
/work/shared/notes/ehl_extensions.md marks it unverified); lambda = 0.02 is extrapolation.
At low M the rigid-isoviscous term 145/(lambda M^2) dominates NVM at small lambda.

Usage: python studies/ehl/ehl_elliptic.py [--level 3] [--cases 20,10 100,10] [--ratios 0.5 0.2 0.1 0.05 0.02]
Writes out/ehl_elliptic.json.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import time

from femgear.physics.contact.film import hamrock_dowson_central, nvm_central
from femgear.physics.contact.hertz import ellipticity_exact
from femgear.physics.ehl.point import solve_point

NVM_RANGE = (1.0 / 16.0, 1.0)


def setup(argv: list[str] | None = None) -> argparse.Namespace:
    """The cases, ratios, level and method of the command line ``argv`` (defaults: the documented table)."""
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--level", type=int, default=3)
    ap.add_argument("--cases", nargs="*", default=["20,10", "100,10"])
    ap.add_argument("--ratios", nargs="*", type=float, default=[0.5, 0.2, 0.1, 0.05, 0.02])
    ap.add_argument("--method", default="auto", choices=("auto", "fas", "newton"),
                    help="point solver (auto: the multigrid inside its range, Newton elsewhere)")
    return ap.parse_args(argv)


def hd_moes(M: float, L: float, ratio: float) -> float:
    """Hamrock-Dowson Hc converted to Moes units at 2U = 1e-11 (notes: ehl_extensions.md, test 5)."""
    U = 0.5e-11
    W = M * (2 * U) ** 0.75
    G = L * (2 * U) ** -0.25
    k = ellipticity_exact(1.0 / ratio)
    return float(hamrock_dowson_central(U, G, W, k)) / (2 * U) ** 0.5


def one(M: float, L: float, ratio: float, level: int, method: str = "auto") -> dict:
    t0 = time.perf_counter()
    r = solve_point(M, L, ratio=ratio, level=level, method=method)
    sec = time.perf_counter() - t0
    hc = [lv["Hc"] for lv in r.levels]
    nvm = float(nvm_central(M, L, ratio))
    return {"M": M, "L": L, "ratio": ratio, "level": level, "Hc": r.Hc, "Hmin": r.Hmin,
            "Hc_levels": hc, "grid_change": abs(hc[-1] / hc[-2] - 1) if len(hc) > 1 else None,
            "nvm": nvm, "dev_nvm": r.Hc / nvm - 1, "hd": hd_moes(M, L, ratio),
            "dev_hd": r.Hc / hd_moes(M, L, ratio) - 1, "in_nvm_range": NVM_RANGE[0] <= ratio <= NVM_RANGE[1],
            "seconds": sec, "nodes": r.nodes, "newton": r.iterations, "flags": list(r.flags),
            "method": r.levels[-1].get("method", "newton")}


def run(args: argparse.Namespace) -> list[dict]:
    """Every (M, L) of ``args.cases``: the circular contact, then each ratio (a failed case is a row with its error)."""
    rows = []
    print(f"{'M':>5} {'L':>4} {'lam':>6} {'Hc':>7} {'NVM':>7} {'dNVM%':>7} {'HD':>7} {'dHD%':>7} "
          f"{'grid%':>6} {'s':>6} {'s(lam=1)':>8} range")
    for case in args.cases:
        M, L = (float(v) for v in case.split(","))
        circ = one(M, L, 1.0, args.level, args.method)
        rows.append(circ)
        for lam in args.ratios:
            try:
                row = one(M, L, lam, args.level, args.method)
            except Exception as exc:  # report and go on: the table shows every case
                print(f"{M:5g} {L:4g} {lam:6g} failed: {exc}")
                rows.append({"M": M, "L": L, "ratio": lam, "error": str(exc)})
                continue
            row["seconds_circular"] = circ["seconds"]
            rows.append(row)
            print(f"{M:5g} {L:4g} {lam:6g} {row['Hc']:7.4f} {row['nvm']:7.4f} {100 * row['dev_nvm']:7.2f} "
                  f"{row['hd']:7.4f} {100 * row['dev_hd']:7.2f} {100 * row['grid_change']:6.2f} "
                  f"{row['seconds']:6.1f} {circ['seconds']:8.1f} {'in' if row['in_nvm_range'] else 'OUT'}",
                  flush=True)
    return rows


def main(argv: list[str] | None = None) -> int:
    args = setup(argv)
    rows = run(args)
    os.makedirs("out", exist_ok=True)
    with open("out/ehl_elliptic.json", "w") as f:
        json.dump(rows, f, indent=1)
    print(json.dumps({"study": "ehl_elliptic", "level": args.level, "cases": len(rows)}))
    return 0


if __name__ == "__main__":
    sys.exit(main())
