"""The rigid-isoviscous limit of the point-contact EHL solver (issue 4, 'Limits').

With rigid surfaces and L = 0 the Hertzian-unit problem is self-similar: H M^2 does not
depend on M, and the pressure spreads over X_s = sqrt(2 H), many Hertz radii at small M.
A fully flooded inlet needs a large domain: far upstream H ~ r^2/2, so P ~ r^-3 and a
domain truncated at radius R X_s misses a load ~ 1/R.  The study solves on square-ish
domains X in [-R, 2] X_s, Y in [-R, R] X_s for several R, extrapolates each in the mesh
size (Richardson with the observed order of three nested levels) and then in 1/R
(H(R) = H_inf - C/R - D/R^2), and compares H_inf with Brewe, Hamrock & Taylor
(1979) and with the rigid-isoviscous asymptote of Nijenbanning, Venner & Moes (1994).
``--elastic M`` adds the full elastic solver at that small M on the same domains: it must
approach the rigid value as M -> 0.

Usage: python studies/ehl/ehl_rigid_limit.py [--lmax 4] [--radii 8 16 32] [--elastic 0.5]
"""

from __future__ import annotations

import argparse
import json
import math
import os
import sys
import time
from pathlib import Path

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import numpy as np

from femgear.physics.contact.film import nvm_central, rigid_isoviscous_point
from femgear.physics.ehl.core import params as pr
from femgear.physics.ehl.core.grid import Domain
from femgear.physics.ehl.point import solve_point

try:
    from studies.ehl.ehl_grid_convergence import richardson
except ImportError:
    from ehl_grid_convergence import richardson

OUT = Path(__file__).resolve().parents[2] / "out" / "ehl_rigid_limit"
M_RIGID = 5.0  # any M gives the same H M^2 when rigid; 5 keeps the Hertz start on the grid


def ri_domain(M: float, R: float) -> Domain:
    """X in [-R, 2] X_s, Y in [-R, R] X_s with X_s = sqrt(2 H_RI) in Hertzian units."""
    xs = math.sqrt(2.0 * rigid_isoviscous_point() / M**2 / pr.point_h_moes_factor(M))
    return Domain(-R * xs, 2.0 * xs, -R * xs, R * xs)


def inverse_radius_fit(radii, values) -> tuple[float, float]:
    """H(R) = H_inf - C/R - D/R^2 through the values (D only with three or more radii;
    least squares beyond); returns (H_inf, C)."""
    x = 1.0 / np.asarray(radii, float)
    A = np.column_stack([np.ones_like(x), -x, -x**2][: min(3, x.size)])
    coef, *_ = np.linalg.lstsq(A, np.asarray(values, float), rcond=None)
    return float(coef[0]), float(coef[1])


def solve_rigid_limit(M: float, R: float, lmax: int, rigid: bool = True) -> dict:
    t0 = time.perf_counter()
    r = solve_point(M, 0.0, level=lmax, coarse_level=2, rigid=rigid, domain=ri_domain(M, R))
    hm2 = [lv["Hc"] * M**2 for lv in r.levels]
    extrap, order = richardson(hm2)
    return {"M": M, "R": R, "rigid": rigid, "HM2": hm2, "HM2_extrapolated": extrap,
            "order": order, "load_error": r.load_error, "seconds": time.perf_counter() - t0}


def setup(argv: list[str] | None = None) -> argparse.Namespace:
    """The command line ``argv`` parsed (defaults: the documented study)."""
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--lmax", type=int, default=4)
    ap.add_argument("--radii", type=float, nargs="+", default=[8.0, 16.0, 32.0])
    ap.add_argument("--elastic", type=float, default=None, help="also the elastic solver at this M")
    return ap.parse_args(argv)


def run(args: argparse.Namespace) -> tuple:
    """The rigid (and elastic) solves per domain radius, the 1/R fits to the infinite domain, the reference films."""
    rows = [solve_rigid_limit(M_RIGID, R, args.lmax) for R in args.radii]
    if args.elastic:
        rows += [solve_rigid_limit(args.elastic, R, args.lmax, rigid=False) for R in args.radii]
    print(f"{'M':>5} {'rigid':>5} {'R':>4} {'H M^2 per level':>28} {'order':>6} {'extrap.':>8} {'s':>6}")
    for row in rows:
        levels = " ".join(f"{v:8.3f}" for v in row["HM2"])
        order = f"{row['order']:.2f}" if row["order"] else "-"
        print(f"{row['M']:5g} {str(row['rigid']):>5} {row['R']:4g} {levels:>28} {order:>6} "
              f"{row['HM2_extrapolated']:8.3f} {row['seconds']:6.1f}")
    summary = {}
    for rigid in (True, False):
        sel = [r for r in rows if r["rigid"] is rigid]
        if len(sel) >= 2:
            h_inf, c = inverse_radius_fit([r["R"] for r in sel], [r["HM2_extrapolated"] for r in sel])
            summary["rigid" if rigid else "elastic"] = {"HM2_infinite_domain": h_inf, "C": c}
    bht = rigid_isoviscous_point()
    nvm = float(nvm_central(1e-3, 0.0)) * 1e-6  # its RI asymptote: H M^2 at vanishing M
    for key, s in summary.items():
        print(f"{key}: H M^2 -> {s['HM2_infinite_domain']:.2f} (H_inf - {s['C']:.1f}/R - D/R^2); "
              f"Brewe-Hamrock-Taylor {bht:.2f} ({s['HM2_infinite_domain'] / bht - 1:+.1%}), "
              f"NVM asymptote {nvm:.2f} ({s['HM2_infinite_domain'] / nvm - 1:+.1%})")
    return rows, summary, bht, nvm


def main(argv: list[str] | None = None) -> int:
    args = setup(argv)
    rows, summary, bht, nvm = run(args)
    OUT.mkdir(parents=True, exist_ok=True)
    (OUT / "rigid_limit.json").write_text(json.dumps(
        {"rows": rows, "summary": summary, "brewe_hamrock_taylor": bht, "nvm": nvm}, indent=1))
    print(f"wrote {OUT / 'rigid_limit.json'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
