"""The paper's §4.3 TEHL benchmark (500 N, 10 m/s, 80 °C): femgear's point TEHL against
Hamrock–Dowson and against the paper's figures (h_c 0.82 um, mu 0.042).

    python studies/ehl/tehl_point_benchmark.py [--R 0.02] [--level 2] [--srr 0.1 0.3 0.5]

The paper (Wang et al. 2026, §4.3) gives load, speed and temperature only. Taken here, and
stated in the output:

* radius: a circular contact of R = 20 mm (R_x = R_y; the value of studies/benchmarks/tehl.py;
  the paper's pair has a normal-section reduced radius of 10.7-12.4 mm along its path, its
  Fig. 6 a point contact without a second radius). ``--R`` changes it; the radius at which
  Hamrock–Dowson gives the paper's 0.82 um is printed too;
* speed: 10 m/s is the entrainment (mean rolling) speed u_e; SRR (not stated) 0.1, 0.3, 0.5;
* oil: the paper's Table 2 (studies/paper_baseline.toml: eta 0.08 Pa s at 313 K,
  22 GPa^-1, 0.042 1/K) at 80 °C = 353.15 K, steel E = 210 GPa, nu = 0.3.

Hamrock & Dowson (1977): H_c = 2.69 U^0.67 G^0.53 W^-0.067 (1 - 0.61 e^(-0.73 k)), k = 1.0339 for
a circle, groups on the mean speed and E' = E/(1 - nu^2) (:func:`femgear.physics.contact.film.
hamrock_dowson_central`), with the Barus alpha of the oil at 80 °C. Prints one table and a JSON line.
"""

from __future__ import annotations

import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import argparse
import json
import sys
from pathlib import Path

from scipy.optimize import brentq

from femgear.case import build_case
from femgear.levels.lubrication import tehl_setup
from femgear.physics.contact.film import hamrock_dowson_central
from femgear.physics.ehl.dimensional import solve_point_dimensional
from femgear.physics.tehl.line import ehl_oil_at
from femgear.physics.tehl.point import solve_tehl_point
from femgear.scene import load_scene

ROOT = Path(__file__).resolve().parents[2]
F, UE, T = 500.0, 10.0, 353.15
PAPER = {"hc_um": 0.82, "mu": 0.042}


def hd_central(R: float, eta0: float, alpha: float, E_red: float) -> float:
    U = eta0 * UE / (E_red * R)
    return float(hamrock_dowson_central(U, alpha * E_red, F / (E_red * R * R), 1.0339)) * R


def setup(argv: list[str] | None = None) -> argparse.Namespace:
    """The command line ``argv`` parsed (defaults: R = 20 mm, level 2, SRR 0.1, 0.3, 0.5)."""
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--R", type=float, default=0.02)
    ap.add_argument("--level", type=int, default=2)
    ap.add_argument("--srr", nargs="*", type=float, default=[0.1, 0.3, 0.5])
    return ap.parse_args(argv)


def run(args: argparse.Namespace) -> dict:
    """The paper's §4.3 point contact: Hamrock-Dowson, the isothermal FE film and TEHL at each SRR."""
    scene = load_scene(ROOT / "studies" / "paper_baseline.toml")
    ts = tehl_setup(build_case(scene))
    oil = ehl_oil_at(ts.oil, T)
    E = ts.E_red
    hd = hd_central(args.R, oil.eta0, oil.alpha, E)
    R_paper = brentq(lambda r: hd_central(r, oil.eta0, oil.alpha, E) - PAPER["hc_um"] * 1e-6, 1e-3, 10.0)
    iso = solve_point_dimensional(F, args.R, None, UE, E, oil, level=args.level + 1)
    print(f"§4.3: F = {F:g} N, u_e = {UE:g} m/s, T = {T - 273.15:g} °C, R = {args.R * 1e3:g} mm (assumed), "
          f"eta(80 °C) = {oil.eta0 * 1e3:.2f} mPa s, alpha = {oil.alpha * 1e9:.1f} 1/GPa, "
          f"a = {iso.a * 1e6:.0f} um, p_h = {iso.ph / 1e9:.3f} GPa, M = {iso.M:.1f}, L = {iso.L:.2f}")
    print(f"  Hamrock-Dowson h_c = {hd * 1e6:.3f} um; isothermal FE (level {args.level + 1}) h_c = "
          f"{iso.hc * 1e6:.3f} um ({100 * (iso.hc / hd - 1):+.1f} % vs HD); paper 0.82 um "
          f"(HD gives 0.82 um at R = {R_paper * 1e3:.0f} mm)")
    rows = []
    print(f"  {'SRR':>5} {'h_c um':>7} {'vs HD':>7} {'vs 0.82':>8} {'h_min':>6} {'mu':>7} {'vs 0.042':>8} {'dT K':>6}")
    for srr in args.srr:
        r = solve_tehl_point(F, args.R, UE, srr, T, level=args.level, **ts.kwargs())
        row = {"srr": srr, "hc_um": r.hc * 1e6, "hmin_um": r.hmin * 1e6, "mu": r.mu, "dT": r.dT_max,
               "hc_vs_hd": r.hc / hd - 1, "hc_vs_paper": r.hc * 1e6 / PAPER["hc_um"] - 1,
               "mu_vs_paper": r.mu / PAPER["mu"] - 1}
        rows.append(row)
        print(f"  {srr:5.2f} {row['hc_um']:7.3f} {100 * row['hc_vs_hd']:+6.1f}% {100 * row['hc_vs_paper']:+7.1f}% "
              f"{row['hmin_um']:6.3f} {r.mu:7.4f} {100 * row['mu_vs_paper']:+7.1f}% {r.dT_max:6.1f}")
    return {"study": "tehl_point_benchmark", "R_m": args.R, "level": args.level, "hd_hc_um": hd * 1e6,
            "iso_hc_um": iso.hc * 1e6, "R_for_paper_hc_m": R_paper, "rows": rows}


def main(argv: list[str] | None = None) -> int:
    print(json.dumps(run(setup(argv))))
    return 0


if __name__ == "__main__":
    sys.exit(main())
