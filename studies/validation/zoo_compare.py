"""Compare two runs of the zoo matrix number by number: every number of every cell's ``results.json``.

A refactor that must not change an answer (a restructuring of the levels or the driver) is checked by running
the matrix before and after it into two folders and comparing them:

    python studies/validation/zoo_matrix.py --coarse --jobs 1            # writes out/zoo_matrix/
    cp -r out/zoo_matrix out/zoo_before                                   # ... change the code, run it again ...
    python studies/validation/zoo_compare.py out/zoo_before out/zoo_matrix [--rtol 1e-9] [--by-key] [--json]

Cells present in only one folder are listed; within a cell, the ``summary`` of both files is walked together
and every number compared relatively (``|a − b| ≤ rtol · max(|a|, |b|)``, and ``atol`` for values that are zero
on one side).  Keys that hold wall or CPU times (``seconds``, ``*_seconds``) and the file list (``outputs``) are
skipped: they differ from run to run.  A key present on one side only is reported as added or removed (new keys
are allowed by the ``results.json`` contract; removed ones are not).  ``--by-key`` lists the moved numbers by
summary key instead (list indices folded, ``S_H[]``): in how many cells each moved, by how much at most, and one
example, the form a list of "every number that moved by more than 1 %" takes (``--rtol 0.01``).
"""

from __future__ import annotations

import argparse
import json
import math
import re
import sys
from pathlib import Path

#: keys whose values are expected to differ between two runs of the same code
SKIPPED = ("seconds", "outputs", "wall_seconds", "cpu_seconds")


def _skipped(key: str) -> bool:
    last = key.rsplit(".", 1)[-1]
    return last in SKIPPED or last.endswith("_seconds")


def walk(a, b, key: str, rtol: float, atol: float, out: dict) -> None:
    """Compare ``a`` and ``b`` (JSON values at ``key``) into ``out`` (``compared``, ``differ``, ``added``,
    ``removed``, ``worst``)."""
    if _skipped(key):
        return
    if isinstance(a, dict) and isinstance(b, dict):
        for k in sorted(set(a) | set(b)):
            sub = f"{key}.{k}" if key else k
            if k not in a:
                out["added"].append(sub)
            elif k not in b:
                out["removed"].append(sub)
            else:
                walk(a[k], b[k], sub, rtol, atol, out)
        return
    if isinstance(a, list) and isinstance(b, list):
        if len(a) != len(b):
            out["differ"].append((key, f"length {len(a)} → {len(b)}", None))
            return
        for i, (x, y) in enumerate(zip(a, b, strict=True)):
            walk(x, y, f"{key}[{i}]", rtol, atol, out)
        return
    numbers = all(isinstance(v, int | float) and not isinstance(v, bool) for v in (a, b))
    if numbers:
        out["compared"] += 1
        if math.isnan(a) and math.isnan(b):
            return
        scale = max(abs(a), abs(b))
        rel = abs(a - b) / scale if scale > 0 else 0.0
        if abs(a - b) > max(rtol * scale, atol):
            out["differ"].append((key, f"{a!r} → {b!r} (rel {rel:.2e})", rel))
        if rel > out["worst"][1] and abs(a - b) > atol:
            out["worst"] = (key, rel)
    elif a != b:
        out["differ"].append((key, f"{a!r} → {b!r}", None))


def cells(folder: Path) -> dict[str, Path]:
    """``scene/cell`` → its results.json under a zoo matrix output folder."""
    return {str(p.parent.relative_to(folder)): p for p in sorted(folder.glob("*/*/results.json"))}


def compare(before: Path, after: Path, rtol: float, atol: float) -> dict:
    a, b = cells(before), cells(after)
    report: dict = {"only_before": sorted(set(a) - set(b)), "only_after": sorted(set(b) - set(a)), "cells": {}}
    for name in sorted(set(a) & set(b)):
        out = {"compared": 0, "differ": [], "added": [], "removed": [], "worst": ("", 0.0)}
        walk(json.loads(a[name].read_text())["summary"], json.loads(b[name].read_text())["summary"], "", rtol, atol,
             out)
        report["cells"][name] = out
    return report


def by_key(report: dict) -> dict[str, dict]:
    """The moved numbers of a :func:`compare` report by summary key, list indices folded (``S_H[0]`` → ``S_H[]``):
    key → {``cells``: the cells it moved in, ``max_rel``: its largest relative move (None for a changed text or
    length), ``example``: (cell, what) of that move}."""
    out: dict[str, dict] = {}
    for cell, c in report["cells"].items():
        for key, what, rel in c["differ"]:
            row = out.setdefault(re.sub(r"\[\d+\]", "[]", key), {"cells": [], "max_rel": None, "example": (cell, what)})
            if cell not in row["cells"]:
                row["cells"].append(cell)
            if rel is not None and (row["max_rel"] is None or rel > row["max_rel"]):
                row["max_rel"], row["example"] = rel, (cell, what)
    return dict(sorted(out.items()))


def setup(argv: list[str] | None = None) -> argparse.Namespace:
    """The command line ``argv`` parsed: the two folders and the tolerances."""
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("before", type=Path)
    ap.add_argument("after", type=Path)
    ap.add_argument("--rtol", type=float, default=1e-9, help="relative tolerance (default 1e-9)")
    ap.add_argument("--atol", type=float, default=1e-300, help="absolute tolerance for values near zero")
    ap.add_argument("--by-key", action="store_true", help="list the moved numbers by summary key, not by cell")
    ap.add_argument("--json", action="store_true", help="print one JSON object as the last line")
    return ap.parse_args(argv)


def run(args: argparse.Namespace) -> dict:
    """The comparison report of the two folders (see :func:`compare`)."""
    return compare(args.before, args.after, args.rtol, args.atol)


def main(argv: list[str] | None = None) -> int:
    args = setup(argv)
    report = run(args)
    bad = 0
    for key, row in by_key(report).items() if args.by_key else ():
        rel = "text/length" if row["max_rel"] is None else f"max rel {row['max_rel']:.2g}"
        print(f"{key:55s} {len(row['cells']):3d} cells  {rel:16s} e.g. {row['example'][0]}: {row['example'][1][:80]}")
    for name, c in report["cells"].items():
        flag = "equal" if not (c["differ"] or c["removed"]) else "DIFFER"
        bad += flag != "equal"
        if args.by_key:
            continue
        worst = f"worst {c['worst'][1]:.1e} at {c['worst'][0]}" if c["worst"][0] else "all identical"
        print(f"{name:45s} {flag:7s} {c['compared']:6d} numbers, {worst}"
              + (f", {len(c['added'])} keys added" if c["added"] else ""))
        for key, what, _ in c["differ"][:10]:
            print(f"    {key}: {what}")
        for key in c["removed"][:10]:
            print(f"    removed: {key}")
    for side in ("only_before", "only_after"):
        if report[side]:
            print(f"{side.replace('_', ' ')}: {', '.join(report[side])}")
    total = sum(c["compared"] for c in report["cells"].values())
    print(f"{len(report['cells'])} cells, {total} numbers compared at rtol {args.rtol:g}: {bad} cells differ")
    if args.json:
        print(json.dumps({"cells": len(report["cells"]), "numbers": total, "differ": bad,
                          "only_before": report["only_before"], "only_after": report["only_after"]}))
    return 1 if bad or report["only_before"] else 0


if __name__ == "__main__":
    sys.exit(main())
