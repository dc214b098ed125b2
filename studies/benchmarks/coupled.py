"""Wall time of the full bidirectional baseline case (issue 7 target ≤ 60 s; the paper: 120 min per case).

    python studies/benchmarks/coupled.py [SCENE] [--quick]

Rows (median of 3 repeats, one with ``--quick``):
- ``run_coupled``: :func:`femgear.system.coupling.run_coupled` on the baseline scene with its
  defaults (PEM stiffness, formula lubrication, analytic thermal, Archard wear, lumped
  dynamics, 100 mesh periods with 50 dropped, 61 path positions × 128 phases, tolerance
  1e-6 on the dynamic mesh force and μ), in this process (imports done);
- ``run_coupled wear 3e6``: the same with 3 × 10⁶ wear cycles (the heaviest case of
  studies/paper/wear_cycles.py: the wear accumulation runs in every pass);
- ``femgear run``: the whole command ``femgear run SCENE --json --no-plots`` in a fresh
  process (interpreter start, imports, the contact pass along the path, the coupled
  loop, files), output to a temporary folder.
Prints a table and one JSON line.
"""

from __future__ import annotations

import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import json
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
TARGET_S = 60.0
PAPER_S = 120 * 60.0


def setup(scene_path: str | Path = ROOT / "studies" / "paper_baseline.toml", overrides: tuple[str, ...] = ()):
    from femgear.case import build_case
    from femgear.scene import load_scene
    from femgear.system.coupling import CouplingSetup

    return CouplingSetup.from_case(build_case(load_scene(scene_path, list(overrides))))


def _time_coupled(scene_path, overrides, repeats) -> dict:
    from femgear.system.coupling import run_coupled

    times, res = [], None
    for _ in range(repeats):
        t0 = time.perf_counter()
        res = run_coupled(setup(scene_path, overrides))
        times.append(time.perf_counter() - t0)
    return {"median_s": statistics.median(times), "times_s": times, "iterations": res.history.iteration[-1],
            "converged": res.converged, "last_change": res.history.mesh_force_change[-1]}


def _time_cli(scene_path, repeats) -> dict:
    exe = Path(sys.executable).with_name("femgear")
    cmd = [str(exe)] if exe.exists() else [sys.executable, "-m", "femgear"]
    times = []
    for _ in range(repeats):
        with tempfile.TemporaryDirectory() as tmp:
            t0 = time.perf_counter()
            proc = subprocess.run(cmd + ["run", str(scene_path), "--json", "--no-plots", "--out", tmp],
                                  capture_output=True, text=True, env={**os.environ, "OPENBLAS_NUM_THREADS": "1"})
            times.append(time.perf_counter() - t0)
        if proc.returncode != 0:
            raise RuntimeError(f"femgear run failed: {proc.stderr[-2000:]}")
    return {"median_s": statistics.median(times), "times_s": times, "iterations": None, "converged": None,
            "last_change": None}


def run(scene_path: str | Path = ROOT / "studies" / "paper_baseline.toml", quick: bool = False) -> dict:
    repeats = 1 if quick else 3
    return {"run_coupled": _time_coupled(scene_path, (), repeats),
            "run_coupled wear 3e6": _time_coupled(scene_path, ("wear.cycles=3e6",), repeats),
            "femgear run": _time_cli(scene_path, repeats), "repeats": repeats, "cpus": os.cpu_count()}


def table(res: dict) -> str:
    lines = [f"{'case':22s} {'median [s]':>10s} {'runs [s]':>24s} {'iter':>5s} {'≤ 60 s':>7s} {'vs paper':>9s}",
             "-" * 82]
    for name, r in res.items():
        if not isinstance(r, dict):
            continue
        runs = " ".join(f"{t:.1f}" for t in r["times_s"])
        it = "" if r["iterations"] is None else str(r["iterations"])
        lines.append(f"{name:22s} {r['median_s']:10.1f} {runs:>24s} {it:>5s} {str(r['median_s'] <= TARGET_S):>7s} "
                     f"{PAPER_S / r['median_s']:8.0f}×")
    return "\n".join(lines)


def main(argv: list[str]) -> int:
    args = [a for a in argv if not a.startswith("--")]
    scene = args[0] if args else ROOT / "studies" / "paper_baseline.toml"
    res = run(scene, quick="--quick" in argv)
    print(f"coupled baseline benchmark ({res['repeats']} repeat(s), {res['cpus']} CPUs; target ≤ {TARGET_S:.0f} s, "
          f"paper {PAPER_S / 60:.0f} min)")
    print(table(res))
    print(json.dumps({"benchmark": "coupled", **{f"{k.replace(' ', '_')}_s": v["median_s"] for k, v in res.items()
                                                 if isinstance(v, dict)}, "target_s": TARGET_S}))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
