"""Running a sweep: local process pool or a Dask distributed cluster, resumable.

Each case writes its outputs into a temporary folder that is renamed to
``cases/<case_id>`` only when complete, so a folder that exists is a finished case
(atomic rename); a rerun skips those.  A failing case records its error in the table
and in ``cases/<case_id>.error.json`` and does not stop the sweep; it is retried on
the next run.  Every case's scene is checked before any case runs
(:mod:`femgear.edge.sweep.check`).  The table ``results.csv`` has one row per case: one
column per swept key, its status, and the scalar summary figures of its run
(:mod:`femgear.edge.sweep.table`); ``summary.png`` draws chosen outputs against the swept
keys (:mod:`femgear.edge.sweep.figure`).

On a Dask cluster the case folders and the base scene are sent as absolute paths (the
workers need the filesystem shared at the same path); ``relative_paths=True`` sends
them relative to the working directory instead (workers started in the same shared
folder, mounted elsewhere).
"""

from __future__ import annotations

import json
import logging
import os
import shutil
import signal
import socket
import time
import uuid
from collections.abc import Callable, Sequence
from concurrent.futures import ProcessPoolExecutor, as_completed
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from femgear.edge.io import write_json
from femgear.edge.sweep.spec import SweepSpec
from femgear.edge.sweep.table import write_table

log = logging.getLogger("femgear.edge.sweep")


def run_sweep_case(base: str, overrides: tuple[str, ...], case_dir: str, plots: bool = False) -> dict[str, Any]:
    """Run one case (in a worker).  Never raises: returns a row with ``status`` and figures."""
    from femgear.edge.run import run_scene
    from femgear.scene import load_scene

    final = Path(case_dir)
    tmp = final.parent / f".{final.name}.tmp-{uuid.uuid4().hex[:8]}"
    row: dict[str, Any] = {"case": final.name, "overrides": " ".join(overrides),
                           "worker": f"{socket.gethostname()}:{os.getpid()}"}
    start = time.perf_counter()
    try:
        scene = load_scene(base, overrides)
        summary = dict(run_scene(scene, tmp, plots=plots).summary)
        summary.pop("outputs", None)
        row.update(status="done", seconds=time.perf_counter() - start, **flatten(summary))
        write_json(tmp / "case.json", row)
        os.replace(tmp, final)
        final.with_name(final.name + ".error.json").unlink(missing_ok=True)
    except Exception as exc:  # a failing case must not stop the sweep
        shutil.rmtree(tmp, ignore_errors=True)
        row.update(status="failed", error=f"{type(exc).__name__}: {exc}", seconds=time.perf_counter() - start)
        write_json(final.with_name(final.name + ".error.json"), row)
    return row


def flatten(d: dict[str, Any], prefix: str = "") -> dict[str, Any]:
    """Scalar leaves of a nested dict as ``a.b.c`` columns; a pair of the result schema (pinion and gear, left and
    right helix: :mod:`femgear.edge.io.summary_schema`) as its two columns ``a.b.0`` and ``a.b.1``; other lists
    are left out."""
    from femgear.edge.io.summary_schema import PAIR, kind_of

    out: dict[str, Any] = {}
    for key, value in d.items():
        name = f"{prefix}{key}"
        if isinstance(value, dict):
            out.update(flatten(value, name + "."))
        elif isinstance(value, (str, int, float, bool)) or value is None:
            out[name] = value
        elif isinstance(value, (list, tuple)) and len(value) == 2 and (kind_of(name) or ("", ""))[1] == PAIR:
            out[f"{name}.0"], out[f"{name}.1"] = value
    return out


@dataclass(frozen=True)
class SweepResult:
    rows: tuple[dict[str, Any], ...]
    table: Path
    ran: int
    skipped: int
    #: ``summary.png`` (None: no case finished, or nothing to draw)
    summary: Path | None = None

    @property
    def failed(self) -> int:
        return sum(r["status"] == "failed" for r in self.rows)


def _ignore_sigint() -> None:
    """Worker initialiser: Ctrl-C reaches the whole process group; only the parent acts on it."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)


def _submitter(workers: int, scheduler: str | None, base: str, cases_dir: str):
    """(submit, as_completed, stop) for a local pool or a Dask cluster.

    ``stop(abandon)`` cancels the cases not started; running ones are waited for, or
    with ``abandon`` their workers are terminated (their temporary folders are removed
    by the next run).  The workers of a cluster are checked first
    (:func:`femgear.edge.sweep.check.check_workers`).
    """
    if scheduler:
        from distributed import Client
        from distributed import as_completed as dask_completed

        from femgear.edge.sweep.check import check_workers

        client = _connect(Client, scheduler)
        try:
            log.info("sweep on %s: %d workers", scheduler, check_workers(client, base, cases_dir))
        except BaseException:
            client.close()
            raise

        def stop_dask(futures, abandon: bool) -> None:
            client.cancel([f for f in futures if not f.done()] if abandon else
                          [f for f in futures if f.status == "pending"])
            client.close()

        return (lambda *a: client.submit(run_sweep_case, *a, pure=False)), dask_completed, stop_dask
    pool = ProcessPoolExecutor(max_workers=workers, initializer=_ignore_sigint)

    def stop_pool(futures, abandon: bool) -> None:
        for fut in futures:
            fut.cancel()
        if abandon:
            for proc in list((getattr(pool, "_processes", None) or {}).values()):
                proc.terminate()
        pool.shutdown(wait=True, cancel_futures=True)

    return (lambda *a: pool.submit(run_sweep_case, *a)), as_completed, stop_pool


def _connect(client_class, scheduler: str):
    """A Dask client of ``scheduler``; an unreachable address is an :class:`ArgumentError` naming ``--scheduler``."""
    from femgear.errors import ArgumentError

    try:
        return client_class(scheduler, timeout="20s")
    except (OSError, TimeoutError, ValueError) as exc:
        raise ArgumentError("--scheduler", f"cannot reach the Dask scheduler {scheduler} ({exc}); start it with "
                                           "'dask scheduler' and give the address it prints") from None


def _rows_on_disk(cases_dir: Path, spec: SweepSpec, failed: dict[str, dict[str, Any]]) -> dict[str, dict[str, Any]]:
    """One row per finished case folder (its ``case.json``) plus this run's failures."""
    rows: dict[str, dict[str, Any]] = {}
    for case in spec.cases:
        done = cases_dir / case.case_id / "case.json"
        if done.exists():
            rows[case.case_id] = json.loads(done.read_text(encoding="utf-8"))
        elif case.case_id in failed:
            rows[case.case_id] = failed[case.case_id]
    return rows


def run_sweep(spec: SweepSpec, out_root: str | Path, workers: int = 2, scheduler: str | None = None,
              plots: bool = False, progress: bool = True,
              on_row: Callable[[dict[str, Any]], None] | None = None, *, check: bool = True,
              outputs: Sequence[str] = (), outputs_argument: str = "outputs",
              relative_paths: bool = False) -> SweepResult:
    """Run the unfinished cases of ``spec``; write ``<out_root>/<name>/results.csv`` and ``summary.png``.

    ``check`` validates every case's scene first (:func:`femgear.edge.sweep.check.check_cases`).
    ``outputs`` (default: the sweep file's ``outputs``, else a default set) are the columns drawn in
    ``summary.png``; a name that is no numeric column raises :class:`ArgumentError` naming
    ``outputs_argument`` (after the table is written: a rerun recomputes nothing).  With a
    ``scheduler`` the workers get absolute paths unless ``relative_paths``.

    Ctrl-C or SIGTERM (KeyboardInterrupt): cases not started are cancelled, running ones
    finish (a second interrupt abandons them), ``results.csv`` is written from the case
    folders that exist, and :class:`SweepInterrupted` is raised.
    """
    if workers < 1:
        raise ValueError(f"workers must be ≥ 1 (got {workers})")
    requested = tuple(outputs) or spec.outputs
    argument = outputs_argument if outputs else "outputs"
    if check:
        from femgear.edge.sweep.check import check_cases, check_outputs

        check_cases(spec)
        check_outputs(spec, requested, argument)
    out = Path(out_root) / spec.name
    if scheduler and not relative_paths:
        out = out.absolute()
    cases_dir = out / "cases"
    cases_dir.mkdir(parents=True, exist_ok=True)
    for stale in cases_dir.glob(".*.tmp-*"):   # outputs of cases killed mid-way (one sweep per folder)
        shutil.rmtree(stale, ignore_errors=True)
    rows = _rows_on_disk(cases_dir, spec, {})
    if requested and rows:
        from femgear.edge.sweep.figure import choose_outputs

        choose_outputs(spec, list(rows.values()), requested, argument)    # a typo found before computing
    todo = [c for c in spec.cases if c.case_id not in rows]
    table = out / "results.csv"
    if todo:
        base = os.path.relpath(spec.base) if relative_paths else str(spec.base)
        rows = _run_todo(spec, todo, rows, cases_dir, table, _submitter(workers, scheduler, base, str(cases_dir)),
                         base, plots, progress, on_row)
    ordered = write_table(table, spec, rows.values())
    from femgear.edge.sweep.figure import write_summary

    summary = write_summary(spec, ordered, out, requested, argument)
    return SweepResult(rows=tuple(rows[c.case_id] for c in spec.cases), table=table,
                       ran=len(todo), skipped=len(spec.cases) - len(todo), summary=summary)


def _run_todo(spec, todo, rows, cases_dir: Path, table: Path, submitter, base: str, plots: bool, progress: bool,
              on_row) -> dict[str, dict[str, Any]]:
    """Submit the unfinished cases, collect their rows as they finish (rewriting the table each time)."""
    submit, completed, stop = submitter
    failed: dict[str, dict[str, Any]] = {}
    futures = []
    try:
        futures = [submit(base, c.overrides, str(cases_dir / c.case_id), plots) for c in todo]
        with _progress(progress, len(spec.cases), len(rows)) as advance:
            for fut in completed(futures):
                row = fut.result()
                rows[row["case"]] = row
                if row["status"] == "failed":
                    failed[row["case"]] = row
                write_table(table, spec, rows.values())
                log.info("case %s: %s (%.1f s)", row["case"], row["status"], row.get("seconds", 0.0))
                advance(row["status"] == "failed")
                if on_row:
                    on_row(row)
    except KeyboardInterrupt:
        _stop_after_interrupt(stop, futures)
        rows = _rows_on_disk(cases_dir, spec, failed)
        write_table(table, spec, rows.values())
        raise SweepInterrupted(table, finished=sum(r["status"] == "done" for r in rows.values()),
                               total=len(spec.cases)) from None
    stop(futures, False)
    return rows


def _stop_after_interrupt(stop, futures) -> None:
    running = sum(f.running() if hasattr(f, "running") else f.status == "pending" for f in futures)
    log.warning("interrupted: cancelling the cases not started, waiting for %d running case(s) "
                "(interrupt again to abandon them)", running)
    try:
        stop(futures, False)
    except KeyboardInterrupt:
        log.warning("abandoning the running cases")
        stop(futures, True)


class SweepInterrupted(KeyboardInterrupt):
    """A sweep stopped by Ctrl-C/SIGTERM after writing a consistent ``results.csv``."""

    def __init__(self, table: Path, finished: int, total: int):
        self.table, self.finished, self.total = table, finished, total
        super().__init__(f"sweep interrupted: {finished} of {total} cases finished, listed in {table}; "
                         "rerun the same command to resume")


class _progress:
    """A rich progress bar with cases done, failed and the estimated time left."""

    def __init__(self, enabled: bool, total: int, already: int):
        self.enabled, self.total, self.already, self.failed = enabled, total, already, 0

    def __enter__(self):
        import sys

        self.enabled = self.enabled and sys.stderr.isatty()
        if not self.enabled:
            return lambda failed: None
        from rich.console import Console
        from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeRemainingColumn

        self.bar = Progress(TextColumn("sweep"), BarColumn(), MofNCompleteColumn(),
                            TextColumn("failed {task.fields[failed]}"), TimeRemainingColumn(),
                            console=Console(stderr=True))
        self.bar.__enter__()
        self.task = self.bar.add_task("sweep", total=self.total, completed=self.already, failed=0)

        def advance(failed: bool) -> None:
            self.failed += failed
            self.bar.update(self.task, advance=1, failed=self.failed)

        return advance

    def __exit__(self, *exc):
        if self.enabled:
            self.bar.__exit__(*exc)
        return False
