"""Why the envelope's pure-sliding corners at 60 m/s do not converge: their film heats beyond any oil.

    python studies/ehl/tehl_runaway.py [--json out/tehl_runaway.json]

The six points of studies/benchmarks/tehl_envelope.py that raise (turbine oil VG 32, R 20 mm, u_e 60 m/s, SRR ±2:
one surface at 120 m/s, the other at rest; 40 °C at 0.5 and 2.5 GPa, 150 °C at 2.5 GPa), with the remedies tried:

- continuation in the slide from pure rolling (which converges at every one of them) with the generalised Reynolds
  equation (:func:`femgear.physics.tehl.opposite.solve_continued`), the Eyring shear with the limiting shear stress
  0.08 p of the benchmark, so that the heat is bounded by τ_L u_s: the peak film and surface temperature rise along
  SRR 0.2 … 2 until the film passes the loop's 400 K bound;
- Blok's flash temperature of the surfaces at SRR 2 for friction coefficients as low as 0.005 (a lower bound on the
  film's own rise: the film is hotter than its walls).

Each line prints the inlet, p_H, SRR, the peak film rise, the surface rise, μ, φ = h_c/h_c,iso and the estimate, or
where the continuation stops and why.
"""

from __future__ import annotations

import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import argparse
import json
import math
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
SRRS = (0.2, 0.4, 0.6, 0.8, 1.0, 1.5, 2.0)
CASES = ((40.0, 0.5e9), (40.0, 2.5e9), (150.0, 2.5e9))
R, UE = 0.02, 60.0


def setup(argv: list[str] | None = None) -> argparse.Namespace:
    """The command line ``argv`` parsed."""
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--json", help="write the figures to this file")
    return ap.parse_args(argv)


def run(args: argparse.Namespace) -> dict:
    """The slide continuation of each case and Blok's flash temperatures, printed as they come."""
    sys.path.insert(0, str(ROOT / "studies" / "benchmarks"))
    from tehl_envelope import E_RED, _setup

    from femgear.physics.lubrication.flash import blok_flash_temperature
    from femgear.physics.tehl.opposite import solve_continued

    oil, props = _setup("VG32")
    out: dict = {"slide": [], "blok": []}
    for T, ph in CASES:
        w = 2.0 * math.pi * R * ph**2 / E_RED
        for srr in SRRS:
            def flow(s: float, srr=srr) -> tuple[float, float]:
                return UE * (1 + srr * (1 - s) / 2), UE * (1 - srr * (1 - s) / 2)
            try:
                r = solve_continued(w, R, UE, T + 273.15, oil, E_RED, props, flow, f"slide to {srr}", tau0=5e6,
                                    limiting_shear=0.08)
            except Exception as exc:    # where the continuation stops, and why
                row = {"T": T, "ph": ph, "srr": srr, "converged": False, "error": str(exc)[:240]}
                out["slide"].append(row)
                print(f"{T:5.0f} °C {ph / 1e9:4.1f} GPa SRR {srr:4.1f}: stops: {row['error']}", flush=True)
                break
            row = {"T": T, "ph": ph, "srr": srr, "converged": True, "dT_max": r.dT_max, "dT_surface": r.dT_surface,
                   "mu": r.mu, "phi": r.thermal_ratio, "estimate": max(r.error_estimate.values())}
            out["slide"].append(row)
            print(f"{T:5.0f} °C {ph / 1e9:4.1f} GPa SRR {srr:4.1f}: peak film rise {r.dT_max:5.0f} K (film "
                  f"{T + r.dT_max:4.0f} °C), surface {r.dT_surface:4.0f} K, mu {r.mu:.4f}, phi {r.thermal_ratio:.3f}, "
                  f"estimate {100 * row['estimate']:.2f} %", flush=True)
    for ph in (0.5e9, 2.5e9):
        w = 2.0 * math.pi * R * ph**2 / E_RED
        b = math.sqrt(8.0 * w * R / (math.pi * E_RED))
        for mu in (0.005, 0.01, 0.02):
            rise = float(blok_flash_temperature(mu, w, 2.0 * UE, b, 2.0 * UE, 0.0, props.B1, props.B2))
            out["blok"].append({"ph": ph, "mu": mu, "rise": rise, "heat": mu * w * 2.0 * UE})
            print(f"Blok at SRR 2, {ph / 1e9:.1f} GPa, mu {mu}: flash rise {rise:5.0f} K (heat "
                  f"{mu * w * 2.0 * UE / 1e6:.2f} MW/m)")
    return out


def main(argv: list[str] | None = None) -> dict:
    args = setup(argv)
    out = run(args)
    if args.json:
        Path(args.json).write_text(json.dumps(out, indent=1))
    return out


if __name__ == "__main__":
    main()
