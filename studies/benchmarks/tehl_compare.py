"""Benchmark: the line TEHL of this tree against that of an older commit, in the same run.

    python studies/benchmarks/tehl_compare.py [--base 6efa5bc] [--level 5] [--pairs 11]

The femgear package of commit ``--base`` is exported (``git archive``) into a temporary
folder as the package ``femgear_base`` (imports rewritten), so both versions run in one
process.  At the mid-path contact of the paper baseline (as studies/benchmarks/tehl.py) and
SRR 0, 0.3, 1, each round times an isothermal solve followed by the old TEHL solve and an
isothermal solve followed by the new one (order alternated between rounds: a shared
machine's load hits both alike); printed: the medians of the per-pair TEHL/isothermal
ratios (issue 16 target: <= 2), the thermal and Newton iterations, and the new answers
relative to the old (h_c, h_min, mu; peak rise in K).  One JSON line at the end.
"""

from __future__ import annotations

import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import argparse
import json
import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[2]
W, R, UE, T0 = 84332.0, 0.0123, 1.09, 313.0


def export_base(rev: str, into: Path) -> None:
    """femgear of commit ``rev`` as the package femgear_base under ``into``."""
    tar = subprocess.run(["git", "-C", str(ROOT), "archive", rev, "femgear"], check=True, capture_output=True).stdout
    subprocess.run(["tar", "-x", "-C", str(into)], input=tar, check=True)
    (into / "femgear").rename(into / "femgear_base")
    for f in (into / "femgear_base").rglob("*.py"):
        f.write_text(re.sub(r"\bfemgear\b", "femgear_base", f.read_text()))


def main() -> dict:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--base", default="6efa5bc", help="the older commit")
    ap.add_argument("--level", type=int, default=5)
    ap.add_argument("--pairs", type=int, default=11)
    args = ap.parse_args()
    tmp = tempfile.TemporaryDirectory()
    export_base(args.base, Path(tmp.name))
    sys.path.insert(0, tmp.name)
    from femgear_base.tehl import solve_tehl_line as base_tehl_line

    from femgear.case import build_case
    from femgear.levels.lubrication import tehl_setup
    from femgear.physics.ehl.dimensional import solve_line_dimensional
    from femgear.physics.tehl import solve_tehl_line
    from femgear.physics.tehl.line import ehl_oil_at
    from femgear.scene import load_scene

    setup = tehl_setup(build_case(load_scene(ROOT / "studies" / "paper_baseline.toml")))
    oil = ehl_oil_at(setup.oil, T0)
    solvers = {"base": base_tehl_line, "new": solve_tehl_line}
    rows = []
    print(f"level {args.level}, base {args.base}, {args.pairs} pairs: TEHL / isothermal (median of pairs)")
    for srr in (0.0, 0.3, 1.0):
        ratios: dict = {k: [] for k in solvers}
        last: dict = {}
        for rnd in range(args.pairs):
            for name in (list(solvers) if rnd % 2 == 0 else list(solvers)[::-1]):
                t = time.perf_counter()
                solve_line_dimensional(W, R, UE, setup.E_red, oil, level=args.level)
                t_iso = time.perf_counter() - t
                t = time.perf_counter()
                last[name] = solvers[name](W, R, UE, srr, T0, level=args.level, **setup.kwargs())
                ratios[name].append((time.perf_counter() - t) / t_iso)
        b, n = last["base"], last["new"]
        row = {"srr": srr, "base_ratio": float(np.median(ratios["base"])), "new_ratio": float(np.median(ratios["new"])),
               "base_its": [b.iterations, b.newton_iterations], "new_its": [n.iterations, n.newton_iterations],
               "d_hc": n.hc / b.hc - 1, "d_hmin": n.hmin / b.hmin - 1, "d_mu": n.mu / b.mu - 1 if b.mu else 0.0,
               "d_dT": n.dT_max - b.dT_max}
        rows.append(row)
        print(f"SRR {srr:4.2f}: base {row['base_ratio']:.2f} ({b.iterations}/{b.newton_iterations} its), new "
              f"{row['new_ratio']:.2f} ({n.iterations}/{n.newton_iterations}); new - base: h_c {row['d_hc']:.1e}, "
              f"h_min {row['d_hmin']:.1e}, mu {row['d_mu']:.1e}, dT {row['d_dT']:.3f} K")
    print(json.dumps({"compare": rows}))
    return {"compare": rows}


if __name__ == "__main__":
    main()
