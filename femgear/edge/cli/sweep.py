"""``femgear sweep SWEEP.toml``: run a parameter sweep, resumably."""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

from femgear.edge.cli.common import emit_json


def register(sub) -> None:
    p = sub.add_parser("sweep", help="run many load cases of a base scene (resumable)")
    p.add_argument("sweep", metavar="SWEEP", help="sweep file (TOML): base, name, outputs, [grid], [[case]] (see docs/guide/sweeps.md)")
    p.add_argument("--workers", type=int, default=2, help="local worker processes (default 2)")
    p.add_argument("--scheduler", default=None, metavar="ADDRESS",
                   help="run on a Dask distributed scheduler, e.g. tcp://10.0.0.5:8786 (the workers need femgear "
                        "and the filesystem shared at the same path; see docs/guide/sweeps.md)")
    p.add_argument("--relative-paths", action="store_true",
                   help="with --scheduler: send the base scene and case folders relative to the working directory "
                        "(workers started in the same shared folder) instead of absolute paths")
    p.add_argument("--outputs", default=None, metavar="COL[,COL...]",
                   help="results.csv columns drawn against the swept keys in summary.png (default: the sweep "
                        "file's outputs, else the Hertz pressure at the pitch point, the minimum film, the mean "
                        "friction coefficient and the dynamic transmission error (DTE) RMS, where computed)")
    p.add_argument("--out", type=Path, default=Path("out") / "sweeps", help="output root (default out/sweeps)")
    p.add_argument("--plots", action="store_true", help="write each case's PNG figures")
    p.add_argument("--no-progress", action="store_true", help="no progress bar")
    p.add_argument("--json", action="store_true", help="print one JSON summary as the last line")
    p.set_defaults(func=_sweep)


def _sweep(args: argparse.Namespace) -> int:
    """Exit 0 when every case finished, 1 when some failed (says how many), 130 when interrupted."""
    from femgear.edge.io.paths import prepare_output_dir
    from femgear.edge.sweep import SweepInterrupted, parse_sweep, run_sweep
    from femgear.edge.sweep.check import check_cases, check_outputs
    from femgear.errors import ArgumentError

    if args.workers < 1:
        raise ArgumentError("--workers", f"must be ≥ 1 (got {args.workers})")
    if args.relative_paths and not args.scheduler:
        raise ArgumentError("--relative-paths", "only applies with --scheduler")
    outputs = tuple(o.strip() for o in args.outputs.split(",") if o.strip()) if args.outputs else ()
    spec = parse_sweep(args.sweep)
    check_cases(spec)              # every case's scene, before any case runs (exit 2 naming the key)
    check_outputs(spec, outputs or spec.outputs, "--outputs" if outputs else "outputs")   # and what to draw
    prepare_output_dir(args.out / spec.name, "--out")
    start = time.perf_counter()
    try:
        result = run_sweep(spec, args.out, workers=args.workers, scheduler=args.scheduler, plots=args.plots,
                           progress=not (args.no_progress or args.quiet or args.json), check=False,
                           outputs=outputs, outputs_argument="--outputs", relative_paths=args.relative_paths)
    except SweepInterrupted as exc:
        print(f"femgear: {exc}", file=sys.stderr)
        return 130
    failed = [r for r in result.rows if r["status"] == "failed"]
    for row in failed:
        print(f"failed: {row['case']}: {row['error']}", file=sys.stderr)
    summary = {"sweep": spec.name, "cases": len(result.rows), "ran": result.ran, "skipped": result.skipped,
               "failed": len(failed), "table": str(result.table),
               "summary_png": str(result.summary) if result.summary else None, "seconds": time.perf_counter() - start}
    if args.json:
        emit_json(summary)
    else:
        print(f"{summary['cases']} cases ({result.ran} run, {result.skipped} already done, "
              f"{len(failed)} failed): {result.table}")
        if result.summary:
            print(f"summary figure: {result.summary}")
    if failed:
        print(f"femgear: error: {len(failed)} of {len(result.rows)} cases failed (see {result.table})",
              file=sys.stderr)
        return 1
    return 0
