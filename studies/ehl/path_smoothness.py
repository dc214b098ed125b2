"""Smooth along the path (issue 43 item 3): second differences of a lubrication level's path fields.

    python studies/ehl/path_smoothness.py [--level tehl] [--scene studies/paper_baseline.toml]

Runs the scene with dynamics off (``run_case``) and prints, per path field (h_c, h_min, p_max, the film's peak
temperature rise, μ, the contact temperature rise), the largest and the median second difference over the field's
maximum where the solver's inputs are smooth: the second differences of the load per length and of |SRR| below
0.5 % of their maximum, and one position either side (``tests/lubrication/test_path_smooth.py``, module docstring).
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

MASK = 0.005


def setup(argv: list[str] | None = None) -> argparse.Namespace:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--level", default="tehl")
    ap.add_argument("--scene", default=str(Path(__file__).resolve().parents[1] / "paper_baseline.toml"))
    return ap.parse_args(argv)


def _d2(a) -> np.ndarray:
    a = np.asarray(a, dtype=float)
    return np.abs(a[:-2] - 2.0 * a[1:-1] + a[2:]) / np.max(np.abs(a))


def run(args: argparse.Namespace | None = None, coarse: bool = False) -> dict:
    """{field: (max, median) of the masked second differences} of ``args.level`` on ``args.scene``."""
    import _common as common

    from femgear.pipeline import run_case

    args = args or setup([])
    case = common.case([f'physics.lubrication="{args.level}"', 'physics.wear="none"'], coarse=coarse, static=True,
                       base=args.scene)
    r = run_case(case)
    t, f = r.tribology, r.tribology.film
    m = (_d2(t.load_per_length) < MASK) & (_d2(np.abs(case.path.srr)) < MASK)
    m = m & np.r_[True, m[:-1]] & np.r_[m[1:], True]
    fields = {"hc": f.central, "hmin": f.minimum, "pmax": f.pressure_max, "film_dT": f.temperature_rise,
              "mu": t.friction_coefficient, "dT": t.temperature_rise}
    return {k: (float(_d2(v)[m].max()), float(np.median(_d2(v)[m]))) for k, v in fields.items() if v is not None}


def main(argv: list[str] | None = None) -> int:
    args = setup(argv)
    for k, (mx, med) in run(args).items():
        print(f"{args.level:10s} {k:8s} max {100 * mx:6.2f} %  median {100 * med:6.2f} %")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
