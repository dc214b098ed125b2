"""Running a sweep: local process pool or a Dask distributed cluster, resumable.

Each case writes its outputs into a temporary folder that is renamed to
``cases/<case_id>`` only when complete, so a folder that exists is a finished case
(atomic rename); a rerun skips those.  A failing case records its error in the table
and in ``cases/<case_id>.error.json`` and does not stop the sweep; it is retried on
the next run.  The table ``results.csv`` has one row per case: its overrides, its
status, and the scalar summary figures of its run.
"""

from __future__ import annotations

import csv
import io
import json
import logging
import os
import shutil
import signal
import time
import uuid
from collections.abc import Callable
from concurrent.futures import ProcessPoolExecutor, as_completed
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from femgear.edge.io import write_json
from femgear.edge.io.atomic import write_text_atomic
from femgear.edge.sweep.spec import SweepSpec

log = logging.getLogger("femgear.edge.sweep")


def run_case(base: str, overrides: tuple[str, ...], case_dir: str, plots: bool = False) -> dict[str, Any]:
    """Run one case (in a worker).  Never raises: returns a row with ``status`` and figures."""
    from femgear.edge.run import run_scene
    from femgear.scene import load_scene

    final = Path(case_dir)
    tmp = final.parent / f".{final.name}.tmp-{uuid.uuid4().hex[:8]}"
    row: dict[str, Any] = {"case": final.name, "overrides": " ".join(overrides)}
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
    """Scalar leaves of a nested dict as ``a.b.c`` columns (lists are left out)."""
    out: dict[str, Any] = {}
    for key, value in d.items():
        name = f"{prefix}{key}"
        if isinstance(value, dict):
            out.update(flatten(value, name + "."))
        elif isinstance(value, (str, int, float, bool)) or value is None:
            out[name] = value
    return out


@dataclass(frozen=True)
class SweepResult:
    rows: tuple[dict[str, Any], ...]
    table: Path
    ran: int
    skipped: int

    @property
    def failed(self) -> int:
        return sum(r["status"] == "failed" for r in self.rows)


def _write_table(path: Path, rows: list[dict[str, Any]]) -> None:
    columns = ["case", "status", "overrides", "error", "seconds"]
    columns += sorted({k for r in rows for k in r} - set(columns))
    buf = io.StringIO()
    writer = csv.DictWriter(buf, fieldnames=columns, extrasaction="ignore")
    writer.writeheader()
    writer.writerows(sorted(rows, key=lambda r: r["case"]))
    write_text_atomic(path, buf.getvalue())


def _ignore_sigint() -> None:
    """Worker initialiser: Ctrl-C reaches the whole process group; only the parent acts on it."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)


def _submitter(workers: int, scheduler: str | None):
    """(submit, as_completed, stop) for a local pool or a Dask cluster.

    ``stop(abandon)`` cancels the cases not started; running ones are waited for, or
    with ``abandon`` their workers are terminated (their temporary folders are removed
    by the next run).
    """
    if scheduler:
        from distributed import Client
        from distributed import as_completed as dask_completed

        client = Client(scheduler)

        def stop_dask(futures, abandon: bool) -> None:
            client.cancel([f for f in futures if not f.done()] if abandon else
                          [f for f in futures if f.status == "pending"])
            client.close()

        return (lambda *a: client.submit(run_case, *a, pure=False)), dask_completed, stop_dask
    pool = ProcessPoolExecutor(max_workers=workers, initializer=_ignore_sigint)

    def stop_pool(futures, abandon: bool) -> None:
        for fut in futures:
            fut.cancel()
        if abandon:
            for proc in list((getattr(pool, "_processes", None) or {}).values()):
                proc.terminate()
        pool.shutdown(wait=True, cancel_futures=True)

    return (lambda *a: pool.submit(run_case, *a)), as_completed, stop_pool


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
              on_row: Callable[[dict[str, Any]], None] | None = None) -> SweepResult:
    """Run the unfinished cases of ``spec`` and write ``<out_root>/<name>/results.csv``.

    Ctrl-C or SIGTERM (KeyboardInterrupt): cases not started are cancelled, running ones
    finish (a second interrupt abandons them), ``results.csv`` is written from the case
    folders that exist, and :class:`SweepInterrupted` is raised.
    """
    if workers < 1:
        raise ValueError(f"workers must be ≥ 1 (got {workers})")
    out = Path(out_root) / spec.name
    cases_dir = out / "cases"
    cases_dir.mkdir(parents=True, exist_ok=True)
    for stale in cases_dir.glob(".*.tmp-*"):   # outputs of cases killed mid-way (one sweep per folder)
        shutil.rmtree(stale, ignore_errors=True)
    rows = _rows_on_disk(cases_dir, spec, {})
    todo = [c for c in spec.cases if c.case_id not in rows]
    table = out / "results.csv"
    failed: dict[str, dict[str, Any]] = {}
    if todo:
        submit, completed, stop = _submitter(workers, scheduler)
        futures = []
        try:
            futures = [submit(str(spec.base), c.overrides, str(cases_dir / c.case_id), plots) for c in todo]
            with _progress(progress, len(spec.cases), len(rows)) as advance:
                for fut in completed(futures):
                    row = fut.result()
                    rows[row["case"]] = row
                    if row["status"] == "failed":
                        failed[row["case"]] = row
                    _write_table(table, list(rows.values()))
                    log.info("case %s: %s (%.1f s)", row["case"], row["status"], row.get("seconds", 0.0))
                    advance(row["status"] == "failed")
                    if on_row:
                        on_row(row)
        except KeyboardInterrupt:
            _stop_after_interrupt(stop, futures)
            rows = _rows_on_disk(cases_dir, spec, failed)
            _write_table(table, list(rows.values()))
            raise SweepInterrupted(table, finished=sum(r["status"] == "done" for r in rows.values()),
                                   total=len(spec.cases)) from None
        stop(futures, False)
    _write_table(table, list(rows.values()))
    return SweepResult(rows=tuple(rows[c.case_id] for c in spec.cases), table=table,
                       ran=len(todo), skipped=len(spec.cases) - len(todo))


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
