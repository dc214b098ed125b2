"""The sweep's results table ``results.csv``: one row per case, one column per swept key.

Columns: ``case``, ``status``, then one column per swept key holding its value as the
sweep file gave it (numbers stay numbers, so a spreadsheet or ``pandas.read_csv`` reads
them as numbers), then ``error``, ``seconds``, ``worker`` (``host:pid`` of the process that ran
the case), ``overrides`` (the case's overrides as typed) and the scalar summary figures of the case's run (``a.b.c`` columns, SI units).
Rows are sorted by the swept keys in the sweep file's order: numbers numerically,
other values in the order of the file; cases without a key come last for that key.
"""

from __future__ import annotations

import csv
import io
import math
from collections.abc import Iterable, Mapping
from pathlib import Path
from typing import Any

from femgear.edge.io.atomic import write_text_atomic
from femgear.edge.sweep.spec import SweepSpec

LEADING = ("case", "status")
TRAILING = ("error", "seconds", "worker", "overrides")


def is_number(value: Any) -> bool:
    """A finite-or-not real number, not a bool."""
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def table_rows(spec: SweepSpec, rows: Iterable[Mapping[str, Any]]) -> list[dict[str, Any]]:
    """The rows with one column per swept key added (values from the sweep file), sorted by those keys."""
    cases = {c.case_id: c for c in spec.cases}
    out = []
    for row in rows:
        case = cases.get(row["case"])
        values = case.values if case is not None else {}
        out.append({**row, **{k: values.get(k) for k in spec.keys}})
    order = _value_order(spec)
    return sorted(out, key=lambda r: (tuple(_rank(order[k], r[k]) for k in spec.keys), r["case"]))


def _value_order(spec: SweepSpec) -> dict[str, dict[str, int]]:
    """Per key: the position of each non-numeric value in the order of the sweep file."""
    order: dict[str, dict[str, int]] = {k: {} for k in spec.keys}
    for case in spec.cases:
        for key, value in case.values.items():
            if not is_number(value):
                order[key].setdefault(repr(value), len(order[key]))
    return order


def _rank(order: Mapping[str, int], value: Any) -> tuple[int, float]:
    if value is None:
        return (2, 0.0)
    if is_number(value):
        return (0, float(value) if not math.isnan(value) else math.inf)
    return (1, float(order.get(repr(value), len(order))))


def write_table(path: Path, spec: SweepSpec, rows: Iterable[Mapping[str, Any]]) -> list[dict[str, Any]]:
    """Write ``results.csv`` atomically; returns the rows as written (sorted, with the key columns)."""
    ordered = table_rows(spec, rows)
    first = list(LEADING) + [k for k in spec.keys if k not in LEADING + TRAILING] + list(TRAILING)
    columns = first + sorted({k for r in ordered for k in r} - set(first))
    buf = io.StringIO()
    writer = csv.DictWriter(buf, fieldnames=columns, extrasaction="ignore")
    writer.writeheader()
    writer.writerows(ordered)
    write_text_atomic(path, buf.getvalue())
    return ordered


__all__ = ["is_number", "table_rows", "write_table"]
