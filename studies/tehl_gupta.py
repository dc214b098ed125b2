"""Thermal film reduction φ_T = h_c / h_c,iso of the line TEHL against Gupta et al. (1992).

    python studies/tehl_gupta.py [--ue 10] [--srr 0,0.25,0.5,0.75,1]

At the tests' contact (tests/tehl/_case.py: w' = 84.3 kN/m, R = 12.3 mm, oil at 313 K) and
u_e = 10 m/s, for two inlet lengths: the default domain [−4.5 b, 1.5 b] (level 4, 192
cells) and a long inlet [−8 b, 1.5 b] (level 5, 304 cells, same cell size).  Gupta's factor
(:func:`femgear.friction.traction.gupta_thermal_factor`) uses L = β_T η0 u_e² / k_f with
u_e the mean velocity and SRR = (v1 − v2)/u_e.  Prints one row per SRR.
"""

from __future__ import annotations

import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import argparse  # noqa: E402
import importlib.util  # noqa: E402
from pathlib import Path  # noqa: E402

from femgear.errors import ConvergenceError  # noqa: E402
from femgear.friction.traction import gupta_thermal_factor  # noqa: E402
from femgear.tehl import solve_tehl_line  # noqa: E402

_CASE = Path(__file__).resolve().parents[1] / "tests" / "tehl" / "_case.py"
_spec = importlib.util.spec_from_file_location("_case", _CASE)
case = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(case)
DOMAINS = ((-4.5, 4, 192), (-8.0, 5, 304))


def phi(ue: float, srr: float, x0: float, level: int, cells: int) -> str:
    try:
        r = solve_tehl_line(case.W, case.R, ue, srr, case.T0, case.OIL, case.E_RED, case.PROPS, tau0=case.TAU0,
                            level=level, cells=cells, x0=x0)
    except ConvergenceError:
        return f"{'fail':>8} {'':>4}"
    return f"{r.hc / r.hc_isothermal:8.3f} {r.iterations:4d}"


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--ue", type=float, default=10.0)
    ap.add_argument("--srr", default="0,0.25,0.5,0.75,1")
    args = ap.parse_args()
    eta0 = float(case.OIL.viscosity(0.0, case.T0))
    L = case.OIL.beta_t * eta0 * args.ue**2 / case.PROPS.k_oil
    print(f"u_e = {args.ue} m/s, L = {L:.2f}; phi and thermal iterations per inlet start x0/b")
    heads = " ".join(f"{'phi(' + str(x0) + ')':>8} {'its':>4}" for x0, _, _ in DOMAINS)
    print(f"{'SRR':>5} {heads} {'Gupta':>7}")
    from femgear.ehl.dimensional import solve_line_dimensional
    from femgear.tehl.line import ehl_oil_at
    ph = solve_line_dimensional(case.W, case.R, args.ue, case.E_RED, ehl_oil_at(case.OIL, case.T0), level=3).ph
    for s in (float(v) for v in args.srr.split(",")):
        g = float(gupta_thermal_factor(ph, case.E_RED, s, args.ue, eta0, case.OIL.beta_t, case.PROPS.k_oil))
        print(f"{s:5.2f} " + " ".join(phi(args.ue, s, *d) for d in DOMAINS) + f" {g:7.3f}", flush=True)


if __name__ == "__main__":
    main()
