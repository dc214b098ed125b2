"""Benchmark: the turbo zoo pair's ``tehl`` run against the baseline's, in the same run (issue 43 item 7).

    python studies/benchmarks/tehl_pair_cost.py [--repeats N] [--json FILE] [--profile] [--keep DIR]

Each repeat runs ``femgear run`` on ``studies/paper_baseline.toml`` and on ``studies/zoo/turbo.toml`` with
``physics.lubrication="tehl"`` and the zoo matrix's ``--coarse`` numerics (a cell of
``studies/validation/zoo_matrix.py``: the same command, the same ``OPENBLAS_NUM_THREADS=1``), the two alternating
(baseline, turbo, baseline, turbo, ...) so that a shared machine's load hits both alike.  Printed: per run the wall
and CPU seconds (the child's user + system time, ``os.wait4``); then the median of each and the ratios turbo /
baseline of the medians and the median of the per-repeat ratios (target: wall ≤ 3).  ``--profile``: one more
turbo run under cProfile, its 25 dearest functions (cumulative) printed.  ``--keep DIR``: each scene's last
``results.json`` under ``DIR/<scene>/lubrication_tehl/`` (the layout of the zoo matrix's output, so that
``studies/validation/zoo_compare.py`` compares two such folders).
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from studies.validation.zoo_matrix import COARSE, run_timed  # noqa: E402

SCENES = {"paper_baseline": ROOT / "studies" / "paper_baseline.toml", "turbo": ROOT / "studies" / "zoo" / "turbo.toml"}
OUT = ROOT / "out" / "benchmarks" / "tehl_pair_cost"
CELL = 'physics.lubrication="tehl"'


def command(scene: Path, out: Path, profile: Path | None = None) -> list[str]:
    """The zoo matrix's ``lubrication=tehl --coarse`` cell of ``scene`` as one ``femgear run`` (under cProfile into
    ``profile``)."""
    head = [sys.executable] + (["-m", "cProfile", "-o", str(profile)] if profile else []) + ["-m", "femgear"]
    cmd = head + ["run", str(scene), "--out", str(out), "--json", "--no-plots", "--no-vtk", "--set", CELL]
    for o in COARSE:
        cmd += ["--set", o]
    return cmd


def run_once(name: str, repeat: int, timeout: float, profile: Path | None = None) -> dict:
    """One run of ``name``'s cell: wall and CPU seconds, exit code, the output folder."""
    out = OUT / f"{name}_{repeat}"
    shutil.rmtree(out, ignore_errors=True)
    t = time.perf_counter()
    p, cpu = run_timed(command(SCENES[name], out, profile), timeout, cwd=ROOT,
                       env={**os.environ, "OPENBLAS_NUM_THREADS": "1"})
    wall = time.perf_counter() - t
    if p.returncode != 0:
        raise SystemExit(f"{name}: exit {p.returncode}: {p.stderr.strip()[-400:]}")
    return {"scene": name, "repeat": repeat, "wall": wall, "cpu": cpu, "out": str(out)}


def measure(repeats: int, timeout: float) -> dict:
    """The alternating runs and their medians and ratios."""
    runs = []
    for i in range(repeats):
        for name in SCENES:
            r = run_once(name, i, timeout)
            runs.append(r)
            print(f"{name:15s} run {i}: wall {r['wall']:7.1f} s   CPU {r['cpu']:7.1f} s", flush=True)
    med = {n: {k: float(np.median([r[k] for r in runs if r["scene"] == n])) for k in ("wall", "cpu")} for n in SCENES}
    per = {k: [t[k] / b[k] for b, t in zip(runs[0::2], runs[1::2])] for k in ("wall", "cpu")}
    ratio = {k: med["turbo"][k] / med["paper_baseline"][k] for k in ("wall", "cpu")}
    return {"runs": runs, "median": med, "ratio_of_medians": ratio,
            "median_ratio": {k: float(np.median(v)) for k, v in per.items()}}


def keep(runs: list[dict], into: Path) -> None:
    """Each scene's last results.json into ``into/<scene>/lubrication_tehl/`` (the zoo matrix's layout)."""
    for name in SCENES:
        last = [r for r in runs if r["scene"] == name][-1]
        dst = into / name / "lubrication_tehl"
        dst.mkdir(parents=True, exist_ok=True)
        shutil.copy(Path(last["out"]) / "results.json", dst / "results.json")


def profile(timeout: float, top: int = 25) -> str:
    """One turbo run under cProfile; its ``top`` dearest functions (cumulative time)."""
    import io
    import pstats

    prof = OUT / "turbo.prof"
    OUT.mkdir(parents=True, exist_ok=True)
    run_once("turbo", -1, timeout, profile=prof)
    text = io.StringIO()
    pstats.Stats(str(prof), stream=text).sort_stats("cumulative").print_stats(top)
    return text.getvalue()


def main(argv: list[str] | None = None) -> dict:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeats", type=int, default=3, help="alternating pairs of runs")
    ap.add_argument("--timeout", type=float, default=3600.0, help="seconds per run")
    ap.add_argument("--json", type=Path, help="write the figures to this file")
    ap.add_argument("--profile", action="store_true", help="one more turbo run under cProfile, its top functions")
    ap.add_argument("--keep", type=Path, help="keep each scene's last results.json here (zoo matrix layout)")
    args = ap.parse_args(argv)
    res = measure(args.repeats, args.timeout)
    m, q, p = res["median"], res["ratio_of_medians"], res["median_ratio"]
    print(f"\nmedian of {args.repeats}: baseline wall {m['paper_baseline']['wall']:.1f} s, CPU "
          f"{m['paper_baseline']['cpu']:.1f} s; turbo wall {m['turbo']['wall']:.1f} s, CPU {m['turbo']['cpu']:.1f} s")
    print(f"turbo / baseline: wall {q['wall']:.2f} (median of the per-repeat ratios {p['wall']:.2f}), CPU "
          f"{q['cpu']:.2f} ({p['cpu']:.2f}); target wall <= 3")
    if args.keep:
        keep(res["runs"], args.keep)
    if args.profile:
        res["profile"] = profile(args.timeout)
        print(res["profile"])
    if args.json:
        args.json.write_text(json.dumps(res, indent=1))
    return res


if __name__ == "__main__":
    main()
