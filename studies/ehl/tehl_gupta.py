"""Thermal film reduction φ_T = h_c / h_c,iso of the line TEHL against Gupta et al. (1992).

    python studies/ehl/tehl_gupta.py [--ph 0.5,1,1.5] [--ue 5,10] [--srr 0,0.5,1]
                                 [--model eyring,newtonian] [--x0 -4.5,-8] [--json out/tehl_gupta.json]

The tests' oil and steel (tests/tehl/_case.py: R = 12.3 mm, oil at 313 K, η0 = 0.08 Pa s,
β_T = 0.042 /K, k_f = 0.14 W/(m K)) with the load per length set by the Hertz pressure,
w' = 2π R p_h² / E'.  Inlet start x0 (outlet 1.5 b): −4.5 b on level 4 with 192 thermal
cells, −8 b on level 5 with 256 (two EHL cells per thermal cell); the isothermal film from
−8 b is within 1.5 % of its value from −24 b for p_h ≥ 0.5 GPa and u_e ≤ 10 m/s, from −4.5 b
it is 12 % short at 0.5 GPa, 10 m/s.  Gupta's factor
(:func:`femgear.physics.lubrication.traction.gupta_thermal_factor`, L = β_T η0 u_e²/k_f with u_e the
mean velocity) is evaluated with S = SRR = (v1 − v2)/u_e and with the slide-to-sum
convention S = (v1 − v2)/(v1 + v2) = SRR/2 (columns "G" and "G/2", ratios φ/G).  Prints one
row per case and writes all rows as JSON (default out/tehl_gupta.json, git-ignored).

Reading (default run, ≈ 4 min; numbers in tests/tehl/test_slow.py): rolling φ is within
3.5 % of Gupta at every p_h and u_e on the long inlet; with sliding φ/G is 1.18–1.45
(S = SRR) or 1.08–1.24 (S = SRR/2) at 0.5–1.5 GPa, the gap growing with load and speed, so
it is neither the load range nor inlet starvation.  Newtonian and Eyring shear give φ within
0.01 of each other.  Every case converges on the long inlet (6–83 thermal iterations, the
Newtonian sliding ones the slowest); on the short inlet Eyring SRR 0.5 and 1 at 1.5 GPa,
10 m/s raise ConvergenceError.

Why 256 thermal cells from −8 b: two EHL cells per thermal cell, no aliasing of the EHL
pressure slope.  (The inlet back-flow chatter that once made the cell count matter came from
advecting with the layer shear-rate profile; see femgear.physics.tehl.energy.)
"""

from __future__ import annotations

import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import argparse
import importlib.util
import itertools
import json
import math
import sys
from pathlib import Path

from femgear.errors import ConvergenceError
from femgear.physics.lubrication.traction import gupta_thermal_factor
from femgear.physics.tehl import solve_tehl_line

ROOT = Path(__file__).resolve().parents[2]
_spec = importlib.util.spec_from_file_location("_case", ROOT / "tests" / "tehl" / "_case.py")
case = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(case)
DOMAINS = {-4.5: (4, 192), -8.0: (5, 256)}   # inlet start x0/b: (EHL level, thermal cells)


def load_for(ph: float) -> float:
    """Load per length [N/m] of Hertz pressure ``ph`` [Pa] at the case's R and E'."""
    return 2.0 * math.pi * case.R * ph**2 / case.E_RED


def setup(ph: str = "0.5,1,1.5", ue: str = "5,10", srr: str = "0,0.5,1", model: str = "eyring,newtonian",
          x0: str = "-4.5,-8") -> list[tuple]:
    """The cases (p_h [Pa], u_e, SRR, model, x0) of the comma-separated lists (p_h in GPa)."""
    return [(p * 1e9, u, s, m, x) for p, u, m, x, s in itertools.product(floats(ph), floats(ue), model.split(","),
                                                                       floats(x0), floats(srr))]


def run(cases: list[tuple] | None = None, echo=None) -> list[dict]:
    """:func:`solve` of every case (default: :func:`setup`'s); ``echo(row)`` after each."""
    rows = []
    for c in setup() if cases is None else cases:
        rows.append(solve(*c))
        if echo:
            echo(rows[-1])
    return rows


def solve(ph: float, ue: float, srr: float, model: str, x0: float) -> dict:
    """One TEHL solve and Gupta's factor in both SRR conventions."""
    level, cells = DOMAINS[x0]
    eta0 = float(case.OIL.viscosity(0.0, case.T0))
    row = {"ph": ph, "ue": ue, "srr": srr, "model": model, "x0": x0, "level": level, "cells": cells,
           "L": case.OIL.beta_t * eta0 * ue**2 / case.PROPS.k_oil}
    for key, s in (("gupta", srr), ("gupta_half", srr / 2)):
        row[key] = float(gupta_thermal_factor(ph, case.E_RED, s, ue, eta0, case.OIL.beta_t, case.PROPS.k_oil))
    try:
        r = solve_tehl_line(load_for(ph), case.R, ue, srr, case.T0, case.OIL, case.E_RED, case.PROPS, model=model,
                            tau0=case.TAU0, level=level, cells=cells, x0=x0)
    except ConvergenceError as exc:
        return {**row, "phi": None, "error": str(exc)}
    return {**row, "phi": r.hc / r.hc_isothermal, "hc_iso": r.hc_isothermal, "hc": r.hc, "iterations": r.iterations,
            "dT_max": r.dT_max, "mu": r.mu, "seconds": r.seconds}


def fmt(r: dict) -> str:
    head = f"{r['ph'] / 1e9:4.1f} {r['ue']:5.1f} {r['L']:5.2f} {r['model']:>9} {r['x0']:5.1f} {r['srr']:4.2f}"
    if r["phi"] is None:
        return f"{head} {'fail':>6} {'':>9} {'':>4} {r['gupta']:6.3f} {'':>6} {r['gupta_half']:6.3f}"
    return (f"{head} {r['phi']:6.3f} {r['hc_iso'] * 1e6:9.3f} {r['iterations']:4d} {r['gupta']:6.3f} "
            f"{r['phi'] / r['gupta']:6.3f} {r['gupta_half']:6.3f} {r['phi'] / r['gupta_half']:6.3f}")


def floats(text: str) -> list[float]:
    return [float(v) for v in text.split(",")]


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--ph", default="0.5,1,1.5", help="Hertz pressures [GPa]")
    ap.add_argument("--ue", default="5,10", help="entrainment speeds [m/s]")
    ap.add_argument("--srr", default="0,0.5,1")
    ap.add_argument("--model", default="eyring,newtonian")
    ap.add_argument("--x0", default="-4.5,-8", help=f"inlet starts, among {sorted(DOMAINS)}")
    ap.add_argument("--json", default=str(ROOT / "out" / "tehl_gupta.json"))
    args = ap.parse_args(argv)
    print(f"{'ph':>4} {'ue':>5} {'L':>5} {'model':>9} {'x0':>5} {'SRR':>4} {'phi':>6} {'hc_iso_um':>9} {'its':>4} "
          f"{'G':>6} {'phi/G':>6} {'G/2':>6} {'phi/G2':>6}")
    rows = run(setup(args.ph, args.ue, args.srr, args.model, args.x0), echo=lambda r: print(fmt(r), flush=True))
    out = Path(args.json)
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(json.dumps(rows, indent=1))
    print(f"wrote {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
