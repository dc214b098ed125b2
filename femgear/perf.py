"""Measuring cost: median wall time and peak Python-heap memory of a call.

Used by the benchmark scripts in ``studies/benchmarks`` and the speed–accuracy study;
never by tests (machines are shared and noisy, so figures are medians, reported next
to a reference measured in the same run).
"""

from __future__ import annotations

import statistics
import time
import tracemalloc
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any


@dataclass(frozen=True)
class Measurement:
    seconds: float        #: median wall time [s]
    peak_bytes: int       #: peak traced allocation of one call (numpy buffers included) [B]
    repeats: int
    value: Any            #: what the last call returned


def measure(fn: Callable[[], Any], repeats: int = 3) -> Measurement:
    """Call ``fn`` ``repeats`` times; the first call also traces its peak memory."""
    if repeats < 1:
        raise ValueError(f"repeats must be ≥ 1 (got {repeats})")
    tracemalloc.start()
    try:
        t = time.perf_counter()
        value = fn()
        times = [time.perf_counter() - t]
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    for _ in range(repeats - 1):
        t = time.perf_counter()
        value = fn()
        times.append(time.perf_counter() - t)
    return Measurement(seconds=statistics.median(times), peak_bytes=peak, repeats=repeats, value=value)


def pareto_front(rows: list[dict[str, Any]], cost: str = "seconds", error: str = "error") -> list[dict[str, Any]]:
    """Rows not dominated in (cost, error): nothing else is both cheaper and more accurate."""
    ordered = sorted(rows, key=lambda r: (r[cost], r[error]))
    front, best = [], float("inf")
    for r in ordered:
        if r[error] < best:
            front.append(r)
            best = r[error]
    return front
