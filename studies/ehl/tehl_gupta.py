"""Thermal film reduction φ_T = h_c / h_c,iso of the line TEHL against the inlet-heating factors of Murch &
Wilson (1975) and Gupta et al. (1992), over the thermal loading L_th = β η0 u_e² / k_f.

    python studies/ehl/tehl_gupta.py [--lth 0.1,0.3,1,3,10] [--ph 0.5,1,1.5] [--srr 0,0.5,1] [--oil VG32,VG100]
                                     [--walls steel|bulk] [--json out/tehl_gupta.json]

The contacts: steel on steel (E' 226 GPa), R 20 mm, the benchmark's oils (studies/benchmarks/tehl_envelope.py:
turbine oil VG 32 at 50 °C, VG 100 at 80 °C), Eyring τ0 5 MPa and limiting shear 0.08 p, the entrainment speed
set by L_th and the load per length by the Hertz pressure, w' = 2π R p_H² / E'.  Solved to the default tolerance
(1 %).  ``--walls bulk``: the surfaces held at the bulk temperature (effusivity 10^6 times steel's, surface rise
below 1 mK), the assumption of Murch & Wilson's inlet-zone analysis as we recall it (unverified, as the forms).  Columns: φ, Murch & Wilson's 3.94/(3.94 + L_th^0.62) (rolling, no load dependence), Gupta's fit with
S = SRR = (v1 − v2)/u_e and with the slide-to-sum reading S = SRR/2, and φ over each
(:mod:`femgear.physics.tehl.inlet`: both forms as recalled in the project notes; the papers are not in the stored
library, so u_e (not the sum speed) and the two S readings are assumptions reported side by side).

Reading (tests/tehl/test_inlet_heating.py): rolling, over both oils, p_H 0.5–1.5 GPa and L_th 0.1–10, φ/Gupta
is 0.970–1.138 and φ/Murch-Wilson 0.850–1.083 (the largest gap to the load-independent Murch & Wilson factor at
1.5 GPa, L_th = 10); with ``--walls bulk`` φ/Murch-Wilson 0.879–1.109 (estimates ≤ 1 %; 3 Dec 2026).  With sliding femgear's film stays above Gupta's fit (tests/tehl/test_slow.py: φ/G 1.1–1.45
with S = SRR, 1.05–1.2 with S = SRR/2).  The largest gap, VG 32 at 1.5 GPa and L_th = 10: φ 0.413 (estimate
0.6 %), 14.99 % below Murch & Wilson's 0.486 and 3.6 % above Gupta's 0.399 (the two factors 22 % apart there); with
the walls at the bulk temperature φ 0.427, 12.1 % below Murch & Wilson's.
"""

from __future__ import annotations

import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import argparse
import dataclasses
import json
import math
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
R = 0.02
BULK_WALLS = 1e6
"""the solids' effusivity factor of ``--walls bulk`` (module docstring) [-]"""


def _floats(text: str) -> list[float]:
    return [float(v) for v in text.split(",")]


def case(oil: str, T_C: float, lth: float, ph: float, srr: float, walls: str = "steel") -> dict:
    """One contact: φ and the two factors; ``walls`` "steel" (the benchmark's solids) or "bulk" (module docstring)."""
    sys.path.insert(0, str(ROOT / "studies" / "benchmarks"))
    from tehl_envelope import E_RED, _setup

    from femgear.physics.lubrication.traction import gupta_thermal_factor
    from femgear.physics.tehl.inlet import murch_wilson_factor
    from femgear.physics.tehl.line import solve_tehl_line

    o, props = _setup(oil)
    if walls == "bulk":
        props = dataclasses.replace(props, B1=BULK_WALLS * props.B1, B2=BULK_WALLS * props.B2, k1=None, k2=None)
    elif walls != "steel":
        raise ValueError(f"walls must be 'steel' or 'bulk' (got {walls!r})")
    T = T_C + 273.15
    eta = float(o.viscosity(0.0, T))
    ue = math.sqrt(lth * props.k_oil / (o.beta_t * eta))
    w = 2.0 * math.pi * R * ph**2 / E_RED
    r = solve_tehl_line(w, R, ue, srr, T, o, E_RED, props, tau0=5e6, limiting_shear=0.08)
    phi = r.hc / r.hc_isothermal
    g = [float(gupta_thermal_factor(ph, E_RED, s, ue, eta, o.beta_t, props.k_oil)) for s in (srr, srr / 2)]
    return {"oil": oil, "T": T_C, "walls": walls, "L_th": lth, "ph": ph, "srr": srr, "ue": ue, "M": r.M, "L": r.L, "phi": phi,
            "murch_wilson": float(murch_wilson_factor(lth)), "gupta": g[0], "gupta_half": g[1],
            "estimate": max(r.error_estimate.values())}


def setup(argv: list[str] | None = None) -> argparse.Namespace:
    """The command line ``argv`` parsed: the grid of oils, pressures, slide-to-roll ratios and thermal loadings."""
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--lth", default="0.1,0.3,1,3,10")
    ap.add_argument("--ph", default="0.5,1,1.5", help="Hertz pressures [GPa]")
    ap.add_argument("--srr", default="0")
    ap.add_argument("--oil", default="VG32,VG100")
    ap.add_argument("--walls", default="steel", choices=("steel", "bulk"))
    ap.add_argument("--json", default=str(ROOT / "out" / "tehl_gupta.json"))
    return ap.parse_args(argv)


TEMPERATURES = {"VG32": 50.0, "VG100": 80.0}
"""inlet temperature of each oil [°C] (the benchmark's)"""


def run(args: argparse.Namespace, report=None) -> list[dict]:
    """One row of :func:`case` per grid point, each passed to ``report`` as it is solved."""
    rows = []
    for oil in args.oil.split(","):
        for ph in _floats(args.ph):
            for srr in _floats(args.srr):
                for lth in _floats(args.lth):
                    rows.append(case(oil, TEMPERATURES[oil], lth, ph * 1e9, srr, args.walls))
                    if report is not None:
                        report(rows[-1])
    return rows


def _print(r: dict) -> None:
    print(f"{r['oil']:6} {r['ph'] / 1e9:4.1f} {r['srr']:4.1f} {r['L_th']:5.1f} {r['ue']:6.2f} {r['M']:6.3g} "
          f"{r['L']:5.3g} {r['phi']:6.3f} {r['murch_wilson']:6.3f} {r['phi'] / r['murch_wilson']:7.3f} "
          f"{r['gupta']:6.3f} {r['phi'] / r['gupta']:6.3f} {r['gupta_half']:6.3f} "
          f"{r['phi'] / r['gupta_half']:6.3f}", flush=True)


def main(argv: list[str] | None = None) -> list[dict]:
    args = setup(argv)
    print(f"{'oil':6} {'p_H':>4} {'SRR':>4} {'L_th':>5} {'u_e':>6} {'M':>6} {'L':>5} {'phi':>6} {'MW':>6} {'phi/MW':>7} "
          f"{'G':>6} {'phi/G':>6} {'G/2':>6} {'phi/G2':>6}")
    rows = run(args, _print)
    Path(args.json).parent.mkdir(parents=True, exist_ok=True)
    Path(args.json).write_text(json.dumps(rows, indent=1))
    return rows


if __name__ == "__main__":
    main()
