"""Benchmark: the ``tehl-point`` lubrication level over the whole path of the paper's pair.

    python studies/benchmarks/tehl_point.py [--crowning 10e-6] [--check 3]

The paper baseline (studies/paper_baseline.toml) with a lead crowning C_beta = 10 um on both
members (chosen before any run; ``--crowning``) and ``physics.lubrication = "tehl-point"``:
the scene's lubrication solver (:func:`femgear.levels.lubrication.lubrication_solver`) at
every position of the case's path (``numerics.path_points`` + the pitch point) under the
line load of the load sharing, as :func:`femgear.levels.lubrication.static_friction` does for
the dynamics. Prints the wall time of the whole path (target <= 60 s, >= 21 positions), the
grid level, and its accuracy: mu, dT, h_c against grid level +1 at ``--check`` positions
(ends and pitch point). One JSON line at the end.
"""

from __future__ import annotations

import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import argparse
import json
import time
import tomllib
from pathlib import Path

import numpy as np

from femgear.case import build_case
from femgear.levels.contact import contact_pass
from femgear.levels.lubrication import friction_along_path, lubrication_solver, tehl_point_solver
from femgear.physics.tehl.point_level import POINT_LEVEL
from femgear.scene import scene_from_dict

ROOT = Path(__file__).resolve().parents[2]


def crowned_scene(crowning: float):
    d = tomllib.loads((ROOT / "studies" / "paper_baseline.toml").read_text())
    d["modifications"] = {"crowning": crowning}
    d["physics"]["lubrication"] = "tehl-point"
    return scene_from_dict(d)


def check_level(case, w, idx, level: int) -> list[dict]:
    """mu, dT, h_c at positions ``idx`` on ``level`` and ``level`` + 1."""
    k, T = case.path, case.operating.ambient_temperature
    rows = []
    for i in idx:
        row = {"u_mm": float(k.u[i] * 1e3)}
        for lv in (level, level + 1):
            det: list = []
            t0 = time.perf_counter()
            tehl_point_solver(case, level=lv, details=det)(
                w=w[i], R=k.R[i], ue=k.ue[i], srr=abs(k.srr[i]), T=T)
            r = det[-1]
            row[lv] = {"mu": r.mu, "dT": r.dT_max, "hc_um": r.hc * 1e6, "hmin_um": r.hmin * 1e6,
                       "pmax_GPa": r.pmax / 1e9, "seconds": time.perf_counter() - t0}
        rows.append(row)
    return rows


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--crowning", type=float, default=10e-6)
    ap.add_argument("--check", type=int, default=3)
    args = ap.parse_args()
    scene = crowned_scene(args.crowning)
    case = build_case(scene)
    k = case.path
    cp = contact_pass(case)
    w = cp.line_load
    t0 = time.perf_counter()
    solver = lubrication_solver(case)
    mu, dT = friction_along_path(case, w, solver)
    seconds = time.perf_counter() - t0
    n = int(k.u.size)
    print(f"tehl-point, crowning {args.crowning * 1e6:g} um, grid level {POINT_LEVEL}: {n} path positions "
          f"in {seconds:.1f} s ({seconds / n:.2f} s each; target <= 60 s)")
    print(f"  mu {mu.min():.4f} .. {mu.max():.4f}, dT {dT.min():.1f} .. {dT.max():.1f} K")
    idx = sorted({0, int(np.argmin(np.abs(k.srr))), n - 1})[: args.check]
    rows = check_level(case, w, idx, POINT_LEVEL)
    lv, lv2 = POINT_LEVEL, POINT_LEVEL + 1
    print(f"  accuracy of level {lv} against level {lv2}:")
    for r in rows:
        a, b = r[lv], r[lv2]
        print(f"  u {r['u_mm']:7.2f} mm: mu {a['mu']:.4f} / {b['mu']:.4f} ({100 * (a['mu'] / b['mu'] - 1):+.1f} %), "
              f"dT {a['dT']:.1f} / {b['dT']:.1f} K, h_c {a['hc_um']:.3f} / {b['hc_um']:.3f} um "
              f"({100 * (a['hc_um'] / b['hc_um'] - 1):+.1f} %), {a['seconds']:.1f} s / {b['seconds']:.1f} s")
    print(json.dumps({"benchmark": "tehl_point", "positions": n, "seconds": round(seconds, 2),
                      "level": POINT_LEVEL, "target_s": 60.0, "crowning_m": args.crowning,
                      "check": rows}, default=float))


if __name__ == "__main__":
    main()
