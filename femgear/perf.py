"""Cost: measuring it (median wall time, peak memory) and announcing it before a long stage.

:func:`measure` is used by the benchmark scripts in ``studies/benchmarks`` and the
speed–accuracy study; never by tests (machines are shared and noisy, so figures are
medians, reported next to a reference measured in the same run).

Long stages (the FE stiffness, the LTCA unit loads, the ``fe``/``fe3d`` thermal solves, the
TEHL map) announce themselves before they start (:func:`announce`): an :class:`Estimate` of
the DOF, memory and time is logged (INFO, i.e. ``-v``; at :data:`NOTICE`, shown by default, when
it exceeds :data:`LONG_STAGE_SECONDS`), and a memory estimate over :func:`memory_budget` raises
:class:`femgear.errors.ResourceError` naming the scene key and the level that fits — the
mechanism ``femgear ehl --level`` uses (:mod:`femgear.edge.cli.limits`).  :class:`Progress` logs
"done/total" lines for stages over :data:`PROGRESS_SECONDS`, shown by default once a stage has run
:data:`LONG_STAGE_SECONDS` (the LTCA contact cycle, the coupling passes, the wear integration).  :func:`interruptible` runs a stage in a
forked child, so that Ctrl-C is taken at once even inside a long compiled call that holds the
interpreter lock (CHOLMOD's factorisation).
"""

from __future__ import annotations

import logging
import math
import os
import pickle
import resource
import signal
import statistics
import time
import tracemalloc
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from femgear.errors import ArgumentError, ResourceError

log = logging.getLogger("femgear.cost")
NOTICE = 25                   #: log level between INFO and WARNING: shown by default, without "warning:"
logging.addLevelName(NOTICE, "NOTICE")
LONG_STAGE_SECONDS = 10.0     #: estimates above this are shown without -v
PROGRESS_SECONDS = 2.0        #: stages longer than this log progress lines (at most one per this interval)
GIB = 1024.0**3


def memory_budget() -> float:
    """Bytes a single job may use: ``FEMGEAR_MEMORY_GB`` if set, else 80 % of the available memory."""
    env = os.environ.get("FEMGEAR_MEMORY_GB")
    if env:
        try:
            value = float(env)
        except ValueError:
            raise ArgumentError("FEMGEAR_MEMORY_GB", f"must be a number of GB (got {env!r})") from None
        if not math.isfinite(value) or value <= 0:
            raise ArgumentError("FEMGEAR_MEMORY_GB", f"must be a positive number of GB (got {env!r})")
        return value * 1e9
    return 0.8 * available_bytes()


def available_bytes() -> float:
    """``MemAvailable`` of /proc/meminfo (the physical memory where it cannot be read) [B]."""
    try:
        with open("/proc/meminfo", encoding="ascii") as fh:
            for line in fh:
                if line.startswith("MemAvailable:"):
                    return float(line.split()[1]) * 1024.0
    except OSError:
        pass
    return float(os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES"))


def peak_rss_bytes() -> int:
    """Peak resident size of this process so far [B] (``getrusage``; Linux reports KiB)."""
    return int(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss) * 1024


def _duration(seconds: float) -> str:
    return f"{seconds:.0f} s" if seconds < 120 else f"{seconds / 60:.1f} min"


@dataclass(frozen=True)
class Estimate:
    """Expected cost of a stage: its size, peak memory and wall time."""

    stage: str            #: what runs, e.g. "LTCA unit loads, gear body (level 1)"
    dofs: int             #: unknowns of the largest system
    memory_bytes: float   #: expected peak resident memory [B]
    seconds: float        #: expected wall time on an unloaded 2-core machine [s]

    def line(self) -> str:
        parts = [f"{self.dofs / 1e3:.0f} k DOF"] if self.dofs else []
        parts += [f"about {self.memory_bytes / GIB:.2g} GiB"] if self.memory_bytes else []
        return f"{self.stage}: {', '.join(parts + [f'about {_duration(self.seconds)}'])}"


def announce(estimate: Estimate, argument: str, fits: Callable[[float], str] | None = None) -> None:
    """Log ``estimate`` (module docstring); raise :class:`ResourceError` naming ``argument`` when its memory
    exceeds :func:`memory_budget`.  ``fits(budget)`` names what fits instead (e.g. the finest level)."""
    budget = memory_budget()
    if estimate.memory_bytes > budget:
        raise ResourceError(argument, estimate.memory_bytes, budget,
                            f"{estimate.stage}; {fits(budget)}" if fits is not None else estimate.stage)
    log.log(NOTICE if estimate.seconds > LONG_STAGE_SECONDS else logging.INFO, estimate.line())


class Progress:
    """``progress(done, detail="")``: a "stage: done/total" line (with ``total`` None: "stage: detail") once the stage
    has run :data:`PROGRESS_SECONDS`, then at most one per that interval and one at the end.

    The lines are NOTICE (shown without ``-v``) when ``expected_seconds`` is long, and also once the stage has in
    fact run :data:`LONG_STAGE_SECONDS`, whatever was expected (a stage whose bodies came from the cache, a
    coupling loop that takes more passes), then at most one per that interval; INFO otherwise."""

    def __init__(self, stage: str, total: int | None, expected_seconds: float = 0.0):
        self.stage, self.total = stage, total
        self.long = expected_seconds > LONG_STAGE_SECONDS
        self.start = self.last = time.perf_counter()

    def __call__(self, done: int, detail: str = "") -> None:
        now = time.perf_counter()
        ran = now - self.start
        if ran < PROGRESS_SECONDS:
            return
        notice = self.long or ran >= LONG_STAGE_SECONDS
        interval = PROGRESS_SECONDS if self.long or not notice else LONG_STAGE_SECONDS
        finished = self.total is not None and done >= self.total
        if now - self.last < interval and not finished:
            return
        self.last = now
        count = f"{done}/{self.total}" if self.total is not None else ""
        text = ", ".join(part for part in (count, detail) if part)
        log.log(NOTICE if notice else logging.INFO, f"{self.stage}: {text} ({ran:.0f} s)")


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


_FORK_UNSAFE: list[str] = []   #: why a forked child of this process could hang (threads that do not survive fork)


def mark_fork_unsafe(reason: str) -> None:
    """Record that this process started threads its forked children cannot use (GNU OpenMP's team, started by
    the system's CHOLMOD: a child waits for it forever); :func:`interruptible` runs in this process from then on."""
    if reason not in _FORK_UNSAFE:
        _FORK_UNSAFE.append(reason)


def interruptible(fn: Callable[..., Any], *args, **kwargs) -> Any:
    """``fn(*args, **kwargs)`` in a forked child process; its result (or exception) comes back pickled.

    A compiled call that holds the interpreter lock (CHOLMOD's factorisation) defers Ctrl-C until it
    returns, up to a minute on the larger bodies; here the parent waits in a plain read, takes the
    KeyboardInterrupt at once, kills the child and re-raises.  The child's memory is returned to the system
    when it ends (the parent's peak stays low: benchmarks read ``RUSAGE_CHILDREN`` too).  Runs ``fn`` in
    this process where ``os.fork`` is missing, ``FEMGEAR_FORK=0`` or this process is unsafe to fork
    (:func:`mark_fork_unsafe`: it ran the system's CHOLMOD itself, which ``femgear run`` leaves to the children).
    """
    if not hasattr(os, "fork") or os.environ.get("FEMGEAR_FORK", "1") == "0" or _FORK_UNSAFE:
        return fn(*args, **kwargs)
    r, w = os.pipe()
    pid = os.fork()
    if pid == 0:                                       # the child: never returns into the caller's code
        os.close(r)
        signal.signal(signal.SIGINT, signal.SIG_IGN)   # the parent decides; it kills us on Ctrl-C
        try:
            try:
                payload = pickle.dumps((True, fn(*args, **kwargs)))
            except BaseException as exc:               # every failure goes back to the parent
                try:
                    payload = pickle.dumps((False, exc))
                except Exception:                      # an exception that does not pickle: its text
                    payload = pickle.dumps((False, RuntimeError(f"{type(exc).__name__}: {exc}")))
            with os.fdopen(w, "wb") as fh:
                fh.write(payload)
        finally:
            os._exit(0)
    os.close(w)
    try:
        with os.fdopen(r, "rb") as fh:
            data = fh.read()
        _, status = os.waitpid(pid, 0)
    except BaseException:
        os.kill(pid, signal.SIGKILL)
        os.waitpid(pid, 0)
        raise
    if not data:
        code = os.waitstatus_to_exitcode(status)
        name = getattr(fn, "__name__", "stage")
        if code == -signal.SIGKILL:
            raise MemoryError(f"{name}: the child process was killed (out of memory?)")
        if code in (-signal.SIGSEGV, -signal.SIGBUS, -signal.SIGABRT):
            # CHOLMOD (through cholespy) prints its own error and then crashes when memory runs out
            raise MemoryError(f"{name}: the child process crashed ({signal.Signals(-code).name}): the sparse "
                              "factorisation crashes this way when memory runs out")
        raise RuntimeError(f"{name}: the child process ended with status {code}")
    ok, value = pickle.loads(data)
    if ok:
        return value
    raise value
