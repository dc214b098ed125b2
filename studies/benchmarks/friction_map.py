"""Friction/temperature map: build time, query cost and interpolation error per resolution.

    python studies/benchmarks/friction_map.py [SCENE]

Prints a table and one JSON line.  The error is measured against fresh solves of the
same (Hertz-level thermal Eyring) solver at 400 random points of the envelope.
"""

from __future__ import annotations

import json
import statistics
import sys
import time
from pathlib import Path

import numpy as np

from femgear.case import build_case
from femgear.levels.lubrication import envelope_contact, line_friction
from femgear.physics.lubrication.map import FrictionMap, envelope_axes, hertz_level_solver
from femgear.scene import load_scene

ROOT = Path(__file__).resolve().parents[2]


def setup(scene_path: str | Path = ROOT / "studies" / "paper_baseline.toml"):
    case = build_case(load_scene(scene_path))
    return case, hertz_level_solver(line_friction(case))


def run(case, solver, resolutions=(1, 2, 3)) -> list[dict]:
    rows = []
    contact = envelope_contact(case)
    for r in resolutions:
        axes = envelope_axes(contact, case.operating.ambient_temperature, r)
        fmap = FrictionMap.build(solver, axes).validate(solver, samples=400)
        q = {k: np.full(20000, v[len(v) // 2]) for k, v in axes.items()}
        q["srr"] = np.linspace(-axes["srr"][-1], axes["srr"][-1], 20000)
        times = []
        for _ in range(5):
            t = time.perf_counter()
            fmap(**q)
            times.append((time.perf_counter() - t) / 20000)
        t = time.perf_counter()
        solver(**{k: v[:200] for k, v in q.items()})
        direct = (time.perf_counter() - t) / 200
        rows.append({"resolution": r, "points": int(fmap.mu.size), "build_s": fmap.build_seconds,
                     "query_us": 1e6 * statistics.median(times), "direct_solve_us": 1e6 * direct,
                     "mu_max_abs_err": fmap.error.mu_max_abs, "mu_rms_abs_err": fmap.error.mu_rms_abs,
                     "dT_max_abs_err_K": fmap.error.dT_max_abs})
    return rows


if __name__ == "__main__":
    rows = run(*setup(*sys.argv[1:2]))
    print(f"{'res':>3} {'points':>7} {'build s':>8} {'query µs':>9} {'direct µs':>10} {'|Δμ| max':>9} {'|Δμ| rms':>9} {'|ΔT| max K':>10}")
    for r in rows:
        print(f"{r['resolution']:>3} {r['points']:>7} {r['build_s']:>8.2f} {r['query_us']:>9.2f} {r['direct_solve_us']:>10.1f} "
              f"{r['mu_max_abs_err']:>9.2e} {r['mu_rms_abs_err']:>9.2e} {r['dT_max_abs_err_K']:>10.3f}")
    print(json.dumps({"benchmark": "friction_map", "rows": rows}))
