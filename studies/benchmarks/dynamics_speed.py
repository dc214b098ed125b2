"""Low-speed dynamics at high-speed cost (issue 26 item 4): the main job's wall time against speed,
and the default step's accuracy against a converged small step, computed in the same run.

    python studies/benchmarks/dynamics_speed.py [--speeds 100 300 500 3000] [--scenes baseline marine]
                                                [--repeats N] [--no-jobs] [--no-accuracy]

1. Main job: ``femgear run SCENE --set operating.speed_rpm=RPM --no-plots --no-vtk --json`` in a
   fresh process per run (the whole coupled job: start-up, stiffness, coupling passes, files),
   wall time, median of ``--repeats`` (interleaved over the speeds), for the baseline
   (``studies/paper_baseline.toml``) and the marine pair (``studies/zoo/marine.toml``).
   Acceptance: t(100 rpm) ≤ 2 × t(500 rpm) on each scene.
2. Accuracy: the scene's dynamic model (``build_model``, the lubrication level's static μ(u))
   run by :func:`femgear.system.dynamics.run_dynamics` with its default step against ``expo`` over the
   same 100 mesh periods (50 dropped) at 2× and 4× the recording steps per mesh period and 2×
   the stiffness sub-steps, recorded throughout; the 4× run is the reference, and its change
   from the 2× run is printed as the reference's own error.  Keys: gear v_y (acceptance: within
   1 % at 100, 300 and 500 rpm), DTE RMS, mesh-force amplitudes, and the largest change of the
   member x/y displacement and velocity amplitudes.

Timings on a shared machine are noisy: quote the ratios of one run.  Writes
``out/benchmarks/dynamics_speed.json`` and prints a table and one JSON line.
"""

from __future__ import annotations

import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")   # many small dense products: threads only contend

import argparse
import json
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
SCENES = {"baseline": ROOT / "studies" / "paper_baseline.toml", "marine": ROOT / "studies" / "zoo" / "marine.toml"}
SPEEDS = (100.0, 300.0, 500.0, 3000.0)
MEMBER_KEYS = [f"{m}.{k}.{a}" for m in ("pinion", "gear") for k in ("displacement", "velocity") for a in "xy"]
KEYS = ["gear.velocity.y", "dte_rms", "mesh_force.L.amplitude", "mesh_force.R.amplitude"]


def setup(scene: str, rpm: float):
    """The scene's dynamic model at ``rpm``."""
    from femgear.case import build_case
    from femgear.scene import load_scene
    from femgear.system.dynamics import build_model

    return build_model(build_case(load_scene(SCENES[scene], [f"operating.speed_rpm={rpm!r}"])))


def job_seconds(scene: str, rpm: float, tree: Path = ROOT) -> dict:
    """Wall time of the main job in a fresh process (outputs in a temporary folder), with the femgear of
    ``tree`` (default: this one; ``--reference`` names another checkout, e.g. the commit before a change)."""
    env = {**os.environ, "PYTHONPATH": str(tree) + os.pathsep + os.environ.get("PYTHONPATH", "")}
    with tempfile.TemporaryDirectory() as tmp:
        cmd = [sys.executable, "-m", "femgear", "run", str(SCENES[scene]), "--set", f"operating.speed_rpm={rpm!r}",
               "--out", tmp, "--no-plots", "--no-vtk", "--json"]
        c0 = resource.getrusage(resource.RUSAGE_CHILDREN)
        t0 = time.perf_counter()
        proc = subprocess.run(cmd, capture_output=True, text=True, env=env, cwd=tree)
        seconds = time.perf_counter() - t0
        c1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    if proc.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)} failed ({proc.returncode}): {proc.stderr.strip()[-500:]}")
    return {"seconds": seconds, "cpu_s": (c1.ru_utime + c1.ru_stime) - (c0.ru_utime + c0.ru_stime)}


def accuracy(scene: str, rpm: float) -> dict:
    """Default run against expo at 2× and 4× the recording steps (2× the sub-steps), same periods."""
    from femgear.system.dynamics import run_dynamics, simulate
    from femgear.system.dynamics.expo import default_substeps
    from femgear.system.dynamics.response import analyse
    from femgear.system.dynamics.run import step_plan

    model = setup(scene, rpm)
    per, per_t = step_plan(model)
    sub = default_substeps(model, per)
    t0 = time.perf_counter()
    run = run_dynamics(model)
    seconds = time.perf_counter() - t0
    amps = {"default": run.amplitudes}
    ref_seconds = {}
    for f in (2, 4):
        t0 = time.perf_counter()
        sim = simulate(model, 100 * model.mesh_period, model.mesh_period / (f * per), "expo", substeps=2 * sub)
        amps[f"x{f}"] = analyse(sim, 50.0).amplitudes
        ref_seconds[f"x{f}"] = time.perf_counter() - t0

    def change(a, b, keys):
        return {k: a[k] / b[k] - 1 for k in keys}

    ref = amps["x4"]
    return {
        "scene": scene, "rpm": rpm, "mesh_frequency": model.mesh_frequency,
        "steps_per_mesh_period": per, "transient_steps_per_mesh_period": per_t, "substeps": sub,
        "stiffness_samples_per_mesh_period": per * sub, "steps": run.simulation.steps,
        "dynamics_seconds": seconds, "reference_seconds": ref_seconds,
        "reference_steps_per_mesh_period": 4 * per,
        "error": change(amps["default"], ref, KEYS),
        "error_members_max": max(abs(v) for v in change(amps["default"], ref, MEMBER_KEYS).values()),
        "reference_change_x2_x4": change(amps["x2"], ref, KEYS),
        "values": {k: ref[k] for k in KEYS},
    }


def run(scenes=("baseline", "marine"), speeds=SPEEDS, repeats: int = 1, jobs: bool = True,
        acc: bool = True, reference: Path | None = None) -> dict:
    out: dict = {"speeds": list(speeds), "repeats": repeats, "jobs": {}, "accuracy": [], "load": _load()}
    trees = {"": ROOT, **({"reference:": reference} if reference else {})}
    if jobs:
        samples = {(p, s, r): [] for p in trees for s in scenes for r in speeds}
        for _ in range(repeats):
            for s in scenes:
                for r in speeds:
                    for p, tree in trees.items():        # interleaved: the reference in the same minutes
                        samples[(p, s, r)].append(job_seconds(s, r, tree))
        for p, tree in trees.items():
            for s in scenes:
                rec: dict = {"tree": str(tree)}
                for key, name in (("seconds", "seconds"), ("cpu_s", "cpu_seconds")):
                    med = {r: statistics.median(x[key] for x in samples[(p, s, r)]) for r in speeds}
                    rec[name] = {str(r): med[r] for r in speeds}
                    rec["all_" + name] = {str(r): [x[key] for x in samples[(p, s, r)]] for r in speeds}
                    if 100.0 in med and 500.0 in med:
                        rec["ratio_100_500" + ("" if key == "seconds" else "_cpu")] = med[100.0] / med[500.0]
                out["jobs"][p + s] = rec
        out["load"] += " → " + _load()
    if acc:
        out["accuracy"] = [accuracy(s, r) for s in scenes for r in speeds]
    return out


def _load() -> str:
    """The machine's load average (``/proc/loadavg``: 1, 5, 15 min), stated with every timing."""
    try:
        return " ".join(Path("/proc/loadavg").read_text().split()[:3])
    except OSError:
        return "unknown"


def _table(res: dict) -> None:
    if res["jobs"]:
        print(f"main job (femgear run, fresh process), median wall and CPU time [s]; load average {res['load']}")
        print(f"{'scene':>23s} " + " ".join(f"{r:>8.0f}" for r in res["speeds"]) + "  t100/t500")
        for s, j in res["jobs"].items():
            for name, key, tag in (("seconds", "ratio_100_500", "wall"), ("cpu_seconds", "ratio_100_500_cpu", "CPU")):
                ratio = j.get(key)
                print(f"{s + ' ' + tag:>23s} " + " ".join(f"{j[name][str(r)]:8.2f}" for r in res["speeds"])
                      + (f"  {ratio:8.2f}" if ratio is not None else ""))
    if res["accuracy"]:
        print("\ndefault step against expo at 4x its recording steps (x2 vs x4 = the reference's own change)")
        print(f"{'scene':>9s} {'rpm':>6s} {'steps/Tm':>8s} {'trans.':>6s} {'sub':>4s} {'dyn s':>6s} "
              f"{'gear v_y':>9s} {'DTE rms':>9s} {'F_L amp':>9s} {'F_R amp':>9s} {'members':>8s} {'ref x2':>8s}")
        for a in res["accuracy"]:
            e = a["error"]
            print(f"{a['scene']:>9s} {a['rpm']:6.0f} {a['steps_per_mesh_period']:8d} "
                  f"{a['transient_steps_per_mesh_period']:6d} {a['substeps']:4d} {a['dynamics_seconds']:6.2f} "
                  + " ".join(f"{100 * e[k]:+8.3f}%" for k in KEYS)
                  + f" {100 * a['error_members_max']:7.3f}% {100 * a['reference_change_x2_x4']['gear.velocity.y']:+7.3f}%")


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--speeds", type=float, nargs="+", default=list(SPEEDS))
    p.add_argument("--scenes", nargs="+", choices=sorted(SCENES), default=["baseline", "marine"])
    p.add_argument("--repeats", type=int, default=1)
    p.add_argument("--no-jobs", action="store_true", help="skip the main-job timings")
    p.add_argument("--no-accuracy", action="store_true", help="skip the accuracy against the small step")
    p.add_argument("--reference", type=Path, default=None,
                   help="another checkout (e.g. `git archive COMMIT | tar -x -C DIR`) timed interleaved with this one")
    args = p.parse_args(argv)
    res = run(tuple(args.scenes), tuple(args.speeds), args.repeats, not args.no_jobs, not args.no_accuracy,
              args.reference)
    _table(res)
    from femgear.edge.io.results import write_json

    print(write_json(ROOT / "out" / "benchmarks" / "dynamics_speed.json", res))
    print(json.dumps(res, default=float))
    return 0


if __name__ == "__main__":
    sys.exit(main())
