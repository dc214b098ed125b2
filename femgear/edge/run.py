"""Bind a scene, run it and write its files: the edge around :func:`femgear.pipeline.run_case`.

The driver computes (``run_case`` is pure and returns a frozen :class:`femgear.results.RunResult`);
this module is where a run meets the disk: every file through :func:`femgear.edge.io.run.write_run`.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from femgear.case import Case, build_case
from femgear.edge.io.run import WEAR_CHECKPOINT, write_run
from femgear.pipeline import run_case
from femgear.results import RunResult
from femgear.system.coupling.state import CouplingState


@dataclass(frozen=True)
class WrittenRun:
    """A run and the files written from it; ``summary`` is the JSON summary as written."""

    result: RunResult
    """the run's typed result [-]"""
    summary: dict[str, Any]
    """the ``summary`` object of ``results.json`` as written [-]"""
    files: dict[str, Path] = field(default_factory=dict)
    """every file written, by key (``summary.outputs``) [-]"""


def run_scene(scene, out_dir: str | Path, plots: bool = True,
              progress: Callable[[CouplingState], None] | None = None, vtk: bool = False) -> WrittenRun:
    """Bind ``scene`` (or take the bound :class:`~femgear.case.Case` given), run it and write ``results.json``, the
    figures (``plots``) and the ParaView set (``vtk``) into ``out_dir`` (:func:`femgear.edge.io.run.write_run`; a
    static wear run's checkpoint goes there too)."""
    out_dir = Path(out_dir)
    case = scene if isinstance(scene, Case) else build_case(scene)
    result = run_case(case, progress=progress, wear_checkpoint=out_dir / WEAR_CHECKPOINT)
    summary, files = write_run(result, out_dir, plots, vtk)
    return WrittenRun(result=result, summary=summary, files=files)
