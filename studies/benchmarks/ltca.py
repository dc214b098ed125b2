"""LTCA cost: mesh + flank compliance once (cold, no cache), from the cache, one mesh cycle, memory.

    python studies/benchmarks/ltca.py [--level N] [--phases 64] [--repeat 3]

Prints one line per figure and a JSON line (also written to out/benchmarks/ltca.json).
Targets (issue 12): mesh + compliance ≤ 60 s at the default resolution, cached afterwards;
one mesh cycle of ≥ 64 phases, both helices, ≤ 5 s.  Timings are wall-clock medians; the
cold build is timed once per member in a throw-away cache folder.
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import statistics
import sys
import tempfile
import time
from pathlib import Path

from femgear.case import build_case
from femgear.case.pair import pair_from_scene
from femgear.levels.stiffness import body_options

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
ROOT = Path(__file__).resolve().parents[2]


def run(level: int = 1, phases: int = 64, repeat: int = 3, order: int = 1) -> dict:
    from femgear.physics.ltca.analysis import build_model, mesh_cycle, normal_force
    from femgear.scene import load_scene

    scene = load_scene(ROOT / "studies" / "paper_baseline.toml")
    pair = pair_from_scene(scene)
    E, nu = scene.material.youngs_modulus, scene.material.poisson_ratio
    body = body_options(build_case(scene))
    out: dict = {"level": level, "order": order, "phases": phases, "body": body}
    with tempfile.TemporaryDirectory() as tmp:
        os.environ["FEMGEAR_CACHE"] = tmp
        t0 = time.perf_counter()
        model = build_model(pair, E, nu, level=level, order=order, **body)
        out["build_cold_s"] = time.perf_counter() - t0
        t0 = time.perf_counter()
        build_model(pair, E, nu, level=level, order=order, **body)
        out["build_cached_s"] = time.perf_counter() - t0
    for m, k in model.kernels.items():
        for key in ("mesh_seconds", "assembly_seconds", "setup_seconds", "solve_seconds", "solves", "n_tets",
                    "cg_iterations", "cross_ratio"):
            out[f"member{m}_{key}"] = k.info[key]
        out[f"member{m}_ndofs"] = int(k.ndofs)
    force = normal_force(pair, scene.operating.torque, scene.operating.driver)
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        res = mesh_cycle(model, force, scene.modifications, n_phases=phases, keep_lines=False)
        times.append(time.perf_counter() - t0)
    out["cycle_s_median"] = statistics.median(times)
    out["cycle_s_all"] = times
    from femgear.physics.ltca.level import resolved_orders

    t0 = time.perf_counter()
    out["resolved_orders"] = resolved_orders(model, force, scene.modifications)[0]
    out["resolution_check_s"] = time.perf_counter() - t0
    out["lte_pp_um"] = res.lte_peak_to_peak() * 1e6
    out["k_mean"] = res.mean_stiffness()
    out["max_rss_MiB"] = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    return out


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--level", type=int, default=1)
    ap.add_argument("--phases", type=int, default=64)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--order", type=int, default=1)
    a = ap.parse_args(argv)
    r = run(a.level, a.phases, a.repeat, a.order)
    print(f"segments: pinion {r['member1_ndofs']} DOF / {r['member1_n_tets']} tets, gear {r['member2_ndofs']} DOF")
    print(f"mesh + compliance, cold (both members): {r['build_cold_s']:.1f} s   (target ≤ 60 s)")
    for m in (1, 2):
        print(f"  member {m}: mesh {r[f'member{m}_mesh_seconds']:.1f} s, assembly {r[f'member{m}_assembly_seconds']:.1f} s, "
              f"factor (LU) or AMG setup {r[f'member{m}_setup_seconds']:.1f} s, {r[f'member{m}_solves']} solves {r[f'member{m}_solve_seconds']:.1f} s")
    print(f"from the cache: {r['build_cached_s']:.3f} s")
    print(f"one mesh cycle, {r['phases']} phases, both helices (median of {len(r['cycle_s_all'])}): "
          f"{r['cycle_s_median']:.2f} s   (target ≤ 5 s)")
    print(f"resolved mesh orders of the dynamics tables (64 phases, 16 and 32 points per line): "
          f"{r['resolved_orders']} in {r['resolution_check_s']:.2f} s")
    print(f"peak memory (max RSS): {r['max_rss_MiB']:.0f} MiB")
    path = ROOT / "out" / "benchmarks" / "ltca.json"
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(r, indent=1))
    print(json.dumps(r))


if __name__ == "__main__":
    main(sys.argv[1:])
