"""Argument checks shared by the sub-commands: finite numbers, bounded grid levels and
a memory budget checked before anything is allocated.

The memory models are measured peak resident sizes (``/usr/bin/time -f %M``, 2-core
machine, OPENBLAS_NUM_THREADS=1) of ``femgear ehl`` fitted with a margin:

- line (dense Newton on ``n = 16·2^level + 1`` nodes): 0.10 GB + 56 n² bytes
  (level 7: 0.31 GB measured, 0.34 GB modelled; level 8: 0.86 / 1.04 GB);
- point (multilevel Newton-Krylov, DC-FFT): 0.10 GB + 0.15 GB · 4^(level-3)
  (level 2: 0.15 / 0.14 GB; level 3: 0.26 / 0.25 GB; level 4: 0.67 / 0.70 GB).
"""

from __future__ import annotations

import math

from femgear.errors import ArgumentError, ResourceError
from femgear.perf import memory_budget

BASE_BYTES = 0.10e9


def ehl_memory(kind: str, level: int) -> float:
    """Estimated peak memory [bytes] of ``femgear ehl KIND --level LEVEL`` (module docstring)."""
    if kind == "line":
        n = 16.0 * 2.0**level + 1.0
        return BASE_BYTES + 56.0 * n * n
    return BASE_BYTES + 0.15e9 * 4.0 ** (level - 3)


def check_memory(argument: str, needed: float, hint: str = "") -> None:
    """Raise :class:`ResourceError` naming ``argument`` when ``needed`` exceeds the budget."""
    budget = memory_budget()
    if needed > budget:
        raise ResourceError(argument, needed, budget, hint)


def finite(argument: str, value: float, *, positive: bool = False, nonnegative: bool = False) -> float:
    """``value`` if finite (and > 0 / ≥ 0 when asked), else :class:`ArgumentError` naming ``argument``."""
    if not math.isfinite(value):
        raise ArgumentError(argument, f"must be a finite number (got {value!r})")
    if positive and value <= 0:
        raise ArgumentError(argument, f"must be > 0 (got {value!r})")
    if nonnegative and value < 0:
        raise ArgumentError(argument, f"must be ≥ 0 (got {value!r})")
    return value


def level_in(argument: str, level: int, lowest: int, kind: str) -> int:
    """A grid level ≥ ``lowest`` whose memory estimate fits the budget."""
    if level < lowest:
        raise ArgumentError(argument, f"must be ≥ {lowest} (got {level})")
    if level > 100:  # keeps 4^level and 2^(2 level) finite floats
        raise ArgumentError(argument, f"must be ≤ 100 (got {level}); levels above 10 need terabytes")
    needed = ehl_memory(kind, level)
    budget = memory_budget()
    if needed > budget:
        fits = max((k for k in range(lowest, level) if ehl_memory(kind, k) <= budget), default=None)
        hint = f"the finest level that fits is {fits}" if fits is not None else "no level fits"
        raise ResourceError(argument, needed, budget, hint)
    return level


__all__ = ["check_memory", "ehl_memory", "finite", "level_in", "memory_budget"]
