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
    peak_bytes: int       #: peak traced allocation of one call (numpy buffers included; 0 if not traced) [B]
    repeats: int
    value: Any            #: what the last call returned


def measure(fn: Callable[[], Any], repeats: int = 3, trace_memory: bool = True) -> Measurement:
    """Median wall time of ``repeats`` plain calls; peak memory from one more, traced call.

    Timing and tracing are separate because tracemalloc slows allocation-heavy Python
    loops several-fold.
    """
    if repeats < 1:
        raise ValueError(f"repeats must be ≥ 1 (got {repeats})")
    times = []
    for _ in range(repeats):
        t = time.perf_counter()
        value = fn()
        times.append(time.perf_counter() - t)
    peak = 0
    if trace_memory:
        tracemalloc.start()
        try:
            fn()
            peak = tracemalloc.get_traced_memory()[1]
        finally:
            tracemalloc.stop()
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
