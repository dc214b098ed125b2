"""``femgear sweep SWEEP.toml``: run a parameter sweep, resumably."""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

from femgear.edge.cli.common import emit_json


def register(sub) -> None:
    p = sub.add_parser("sweep", help="run many load cases of a base scene (resumable)")
    p.add_argument("sweep", metavar="SWEEP", help="sweep file (TOML): base scene, [grid], [[case]]")
    p.add_argument("--workers", type=int, default=2, help="local worker processes (default 2)")
    p.add_argument("--scheduler", default=None, metavar="ADDRESS",
                   help="run on a Dask distributed scheduler, e.g. tcp://10.0.0.5:8786")
    p.add_argument("--out", type=Path, default=Path("out") / "sweeps", help="output root (default out/sweeps)")
    p.add_argument("--plots", action="store_true", help="write each case's PNG figures")
    p.add_argument("--no-progress", action="store_true", help="no progress bar")
    p.add_argument("--json", action="store_true", help="print one JSON summary as the last line")
    p.set_defaults(func=_sweep)


def _sweep(args: argparse.Namespace) -> int:
    """Exit 0 when every case finished, 1 when some failed (says how many), 130 when interrupted."""
    from femgear.edge.io.paths import prepare_output_dir
    from femgear.edge.sweep import SweepInterrupted, parse_sweep, run_sweep
    from femgear.errors import ArgumentError

    if args.workers < 1:
        raise ArgumentError("--workers", f"must be ≥ 1 (got {args.workers})")
    spec = parse_sweep(args.sweep)
    prepare_output_dir(args.out / spec.name, "--out")
    start = time.perf_counter()
    try:
        result = run_sweep(spec, args.out, workers=args.workers, scheduler=args.scheduler, plots=args.plots,
                           progress=not (args.no_progress or args.quiet or args.json))
    except SweepInterrupted as exc:
        print(f"femgear: {exc}", file=sys.stderr)
        return 130
    failed = [r for r in result.rows if r["status"] == "failed"]
    for row in failed:
        print(f"failed: {row['case']}: {row['error']}", file=sys.stderr)
    summary = {"sweep": spec.name, "cases": len(result.rows), "ran": result.ran, "skipped": result.skipped,
               "failed": len(failed), "table": str(result.table), "seconds": time.perf_counter() - start}
    if args.json:
        emit_json(summary)
    else:
        print(f"{summary['cases']} cases ({result.ran} run, {result.skipped} already done, "
              f"{len(failed)} failed): {result.table}")
    if failed:
        print(f"femgear: error: {len(failed)} of {len(result.rows)} cases failed (see {result.table})",
              file=sys.stderr)
        return 1
    return 0
