"""The coupled baseline against an earlier commit, interleaved in one run (build once, apply many).

    python studies/benchmarks/build_once.py [--against COMMIT] [--repeats N]

``COMMIT`` (default b21c125, the last commit before the typed pipeline) is extracted
with ``git archive`` into a temporary folder and its ``run_coupled`` on the baseline
scene (61 path positions, its own defaults) is timed in a fresh process, alternating with
this tree's ``run_coupled`` (a) at the same time step (200 steps per mesh period:
``STEPS_PER_MODE_PERIOD = 0``), which isolates what building once saves, and (b) with
this tree's default step (halved until the highest mode is sampled 12 times: twice the
steps at 500 rpm).  Prints the medians, their ratios and one JSON line.  Timings on a
shared machine are noisy: quote the medians and ratios of one run.
"""

from __future__ import annotations

import json
import os
import statistics
import subprocess
import sys
import tarfile
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
SCENE = ROOT / "studies" / "paper_baseline.toml"

_NEW = """
import json, sys, time
import femgear.system.dynamics.run as R
R.STEPS_PER_MODE_PERIOD = int(sys.argv[1])
from femgear.case import build_case
from femgear.system.coupling import CouplingSetup, run_coupled
from femgear.scene import load_scene
t = time.perf_counter()
r = run_coupled(CouplingSetup.from_case(build_case(load_scene(sys.argv[2], ['numerics.path_points=61']))))
print(json.dumps({"seconds": time.perf_counter() - t, "iterations": r.state.iteration}))
"""
_OLD = """
import json, sys, time
from femgear.system.coupling import CouplingSetup, run_coupled
from femgear.scene import load_scene
t = time.perf_counter()
r = run_coupled(CouplingSetup.from_scene(load_scene(sys.argv[2])))
print(json.dumps({"seconds": time.perf_counter() - t, "iterations": r.state.iteration}))
"""


def _extract(commit: str, folder: Path) -> Path:
    archive = subprocess.run(["git", "-C", str(ROOT), "archive", commit, "femgear"], capture_output=True, check=True)
    with tarfile.open(fileobj=__import__("io").BytesIO(archive.stdout)) as tar:
        tar.extractall(folder, filter="data")
    return folder


def _time(code: str, path: Path, *args: str) -> float:
    env = {**os.environ, "OPENBLAS_NUM_THREADS": "1", "PYTHONPATH": str(path)}
    out = subprocess.run([sys.executable, "-c", code, *args], capture_output=True, text=True, env=env, cwd=path)
    if out.returncode != 0:
        raise RuntimeError(out.stderr[-2000:])
    return json.loads(out.stdout.strip().splitlines()[-1])["seconds"]


def run(against: str = "b21c125", repeats: int = 5) -> dict:
    times: dict[str, list[float]] = {"old": [], "new_equal_step": [], "new_default": []}
    with tempfile.TemporaryDirectory() as tmp:
        old = _extract(against, Path(tmp))
        for _ in range(repeats):
            times["old"].append(_time(_OLD, old, "0", str(SCENE)))
            times["new_equal_step"].append(_time(_NEW, ROOT, "0", str(SCENE)))
            times["new_default"].append(_time(_NEW, ROOT, "12", str(SCENE)))
    med = {k: statistics.median(v) for k, v in times.items()}
    return {"against": against, "repeats": repeats, "times_s": times, "median_s": med,
            "speedup_equal_step": med["old"] / med["new_equal_step"], "speedup_default": med["old"] / med["new_default"]}


def main(argv: list[str] | None = None) -> int:
    import argparse

    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--against", default="b21c125")
    p.add_argument("--repeats", type=int, default=5)
    a = p.parse_args(argv)
    res = run(a.against, a.repeats)
    for k, v in res["median_s"].items():
        print(f"{k:16s} median {v:6.2f} s   runs " + " ".join(f"{t:.2f}" for t in res["times_s"][k]))
    print(f"speed-up at equal step {res['speedup_equal_step']:.2f}x, with the new default step "
          f"{res['speedup_default']:.2f}x (against {res['against']})")
    print(json.dumps({"benchmark": "build_once", **{k: v for k, v in res.items() if k != "times_s"}}))
    return 0


if __name__ == "__main__":
    sys.exit(main())
