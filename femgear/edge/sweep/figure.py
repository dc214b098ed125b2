"""The sweep's summary figure: which outputs to draw, checked against the table, and ``summary.png``."""

from __future__ import annotations

import difflib
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

from femgear.edge.sweep.spec import SweepSpec
from femgear.edge.sweep.table import is_number
from femgear.errors import ArgumentError

#: drawn when neither the sweep file (``outputs``) nor ``--outputs`` chooses; those a case has (SI units):
#: Hertz pressure at the pitch point [Pa], minimum film [m], mean friction coefficient [-], DTE RMS [m]
DEFAULT_OUTPUTS = ("contact.pitch.hertz_pressure", "film.minimum", "friction.mu_mean", "dynamics.amplitudes.dte_rms")


def choose_outputs(spec: SweepSpec, rows: Sequence[Mapping[str, Any]], requested: Sequence[str] = (),
                   argument: str = "outputs") -> tuple[str, ...]:
    """The outputs to draw: ``requested`` (each must be a numeric column of a finished case, else
    :class:`ArgumentError` naming ``argument`` with the closest column names), or the defaults present."""
    done = [r for r in rows if r.get("status") == "done"]
    if not requested:
        return tuple(k for k in DEFAULT_OUTPUTS if any(is_number(r.get(k)) for r in done))
    available = sorted({k for r in done for k, v in r.items() if is_number(v)} - set(spec.keys) - {"seconds"})
    for name in requested:
        if not any(is_number(r.get(name)) for r in done):
            close = difflib.get_close_matches(name, available, n=3, cutoff=0.5)
            hint = f"; did you mean {', '.join(close)}?" if close else "; see the columns of results.csv"
            raise ArgumentError(argument, f"{name!r} is not a numeric column of the finished cases{hint}")
    return tuple(requested)


def write_summary(spec: SweepSpec, rows: Sequence[Mapping[str, Any]], folder: Path,
                  requested: Sequence[str] = (), argument: str = "outputs") -> Path | None:
    """Draw ``summary.png`` of the finished cases in ``folder``; None when no case finished or nothing to draw."""
    from femgear.edge.io.figures import save_figure
    from femgear.edge.plot.sweep import plot_sweep_summary

    outputs = choose_outputs(spec, rows, requested, argument)
    done = [r for r in rows if r.get("status") == "done"]
    if not done or not outputs or not spec.keys:
        return None
    fig = plot_sweep_summary(done, spec.keys, outputs,
                             title=f"sweep {spec.name} of scene {_scene_name(spec)}: {len(done)} of {len(rows)} "
                                   "cases finished (SI units)")
    return save_figure(fig, folder / "summary.png")


def _scene_name(spec: SweepSpec) -> str:
    """The base scene's ``meta.name`` (else its file name)."""
    from femgear.scene.load import read_toml

    meta = read_toml(spec.base).get("meta", {})
    return str(meta.get("name") or spec.base.name) if isinstance(meta, dict) else spec.base.name


__all__ = ["DEFAULT_OUTPUTS", "choose_outputs", "write_summary"]
