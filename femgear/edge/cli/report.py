"""Readable command output: the closing table of a run and a progress display.

:func:`key_figures` picks the figures an engineer reads first from the ``summary`` of
``results.json`` (pure, testable); :func:`print_key_figures` renders them with rich.
:class:`CouplingProgress` shows the coupling passes as they arrive: a live line on a
terminal, INFO log records (``-v``) otherwise.
"""

from __future__ import annotations

import logging
import sys
from typing import Any

log = logging.getLogger("femgear.run")


def _get(d: dict[str, Any], *path: str) -> Any:
    for key in path:
        if not isinstance(d, dict) or key not in d:
            return None
        d = d[key]
    return d


def _fmt(value: Any, scale: float = 1.0, spec: str = ".4g") -> str:
    return "—" if value is None else format(value * scale, spec)


def key_figures(summary: dict[str, Any], seconds: float | None = None) -> list[tuple[str, str, str]]:
    """(quantity, value, unit) rows for the run's closing table; absent sub-models are left out."""
    rows: list[tuple[str, str, str]] = []
    co = summary.get("coupling")
    if co:
        changes = [c for c in _get(co, "history", "mesh_force_change") or [] if c is not None]
        last = f", last mesh-force change {changes[-1]:.2g}" if changes else ""
        state = "converged" if co.get("converged") else "NOT converged"
        rows.append(("coupling", f"{co.get('mode')}: {state} in {co.get('iterations')} passes{last}", ""))
    rows.append(("mesh stiffness, mean (ripple)",
                 f"{_fmt(_get(summary, 'stiffness', 'mean_total'), 1e-9)} "
                 f"({_fmt(_get(summary, 'stiffness', 'ripple_total'), 100, '.2f')} %)", "kN/µm"))
    te = summary.get("transmission_error")
    if te:
        harm = " ".join(_fmt(h, 1e6, ".3f") for h in list(te.get("lte_harmonics", []))[:3])
        rows.append(("loaded TE p-p (LTCA, normal); harmonics 1-3",
                     f"{_fmt(te.get('lte_peak_to_peak'), 1e6, '.4f')}; {harm}", "µm"))
        if te.get("lte_peak_to_peak_deviated") is not None:
            rows.append(("loaded TE p-p, worn/expanded flanks (last pass)",
                         _fmt(te.get("lte_peak_to_peak_deviated"), 1e6, ".4f"), "µm"))
        rows.append(("max LTCA contact pressure", f"{_fmt(te.get('max_pressure'), 1e-9, '.3f')} at "
                     f"{te.get('max_pressure_where')}" + (" (edge contact)" if te.get("edge_contact") else ""), "GPa"))
    rows.append(("Hertz pressure at the pitch point", _fmt(_get(summary, "contact", "pitch", "hertz_pressure"), 1e-9),
                 "GPa"))
    film = summary.get("film")
    if film:
        rows.append((f"central film at the pitch point ({film['level']})", _fmt(film.get("central_pitch"), 1e6), "µm"))
        rows.append((f"minimum film along the path ({film['level']})", _fmt(film.get("minimum"), 1e6), "µm"))
        if film.get("error_estimate_max") is not None:
            rows.append(("film error estimate, largest along the path", _fmt(film["error_estimate_max"], 100, ".2g"),
                         "%"))
        if film.get("central_isothermal_pitch") is not None:
            rows.append(("isothermal central film at the pitch point", _fmt(film["central_isothermal_pitch"], 1e6),
                         "µm"))
            rows.append(("thermal film ratio h_c/h_c,iso at the pitch point: TEHL / Murch-Wilson / Gupta",
                         " / ".join(_fmt(film.get(k), 1, ".3f") for k in ("phi_tehl_pitch", "phi_murch_wilson_pitch",
                                                                           "phi_gupta_pitch")), ""))
            rows.append(("thermal loading L_th = β η0 u_e²/k_f, largest", _fmt(film.get("thermal_loading_max"), 1, ".3g"),
                         ""))
            rows.append(("flash temperature, largest: TEHL / Blok for the same μ",
                         f"{_fmt(film.get('flash_tehl_max'), 1, '.3g')} / {_fmt(film.get('flash_blok_max'), 1, '.3g')}",
                         "K"))
    else:
        rows.append(("central film at the pitch point (formula)",
                     _fmt(_get(summary, "contact", "pitch", "film_central"), 1e6), "µm"))
    if "friction" in summary:
        f = summary["friction"]
        rows.append((f"μ max / mean ({f.get('level', '')})", f"{_fmt(f.get('mu_max'), 1, '.4f')} / {_fmt(f.get('mu_mean'), 1, '.4f')}", ""))
        rows.append(("max contact temperature rise", _fmt(f.get("max_temperature_rise"), 1, ".3g"), "K"))
    if "thermal" in summary:
        t = summary["thermal"]
        rows.append(("thermal deviation at pitch, pinion / gear",
                     f"{_fmt(t.get('deviation_pitch_pinion'), 1e6, '.3g')} / "
                     f"{_fmt(t.get('deviation_pitch_gear'), 1e6, '.3g')}", "µm"))
    if "wear" in summary:
        w = summary["wear"]
        rows.append((f"max wear depth after {w.get('cycles', 0):g} cycles, pinion / gear",
                     f"{_fmt(w.get('max_depth_pinion'), 1e6, '.3g')} / {_fmt(w.get('max_depth_gear'), 1e6, '.3g')}",
                     "µm"))
    amp = _get(summary, "dynamics", "amplitudes")
    if amp:
        rows.append(("gear amplitude x / y (half peak-to-peak)",
                     f"{_fmt(amp.get('gear.displacement.x'), 1e6, '.3g')} / "
                     f"{_fmt(amp.get('gear.displacement.y'), 1e6, '.3g')}", "µm"))
        rows.append(("dynamic mesh force per helix, mean ± amplitude",
                     f"{_fmt(amp.get('mesh_force.L.mean'), 1, '.5g')} ± {_fmt(amp.get('mesh_force.L.amplitude'), 1, '.3g')}",
                     "N"))
    if seconds is not None:
        rows.append(("wall time", f"{seconds:.3g}", "s"))
    return rows


def print_key_figures(rows: list[tuple[str, str, str]], title: str) -> None:
    """The closing table on stdout (plain text when stdout is not a terminal)."""
    from rich.console import Console
    from rich.table import Table

    table = Table(title=title, show_header=True, header_style="bold")
    table.add_column("quantity")
    table.add_column("value", justify="right")
    table.add_column("unit")
    for row in rows:
        table.add_row(*row)
    Console(file=sys.stdout, width=110).print(table)


class CouplingProgress:
    """Callback for :func:`femgear.edge.run.run_scene`: one line per coupling pass.

    On a terminal (stderr) and unless quiet, a rich status line is updated in place;
    every pass is also logged at INFO level (shown with ``-v``).
    """

    def __init__(self, enabled: bool):
        self.enabled = enabled and sys.stderr.isatty()
        self._status = None

    def __enter__(self) -> CouplingProgress:
        if self.enabled:
            from rich.console import Console

            self._status = Console(stderr=True).status("running the quasi-static pass ...")
            self._status.__enter__()
        return self

    def __call__(self, state) -> None:
        text = (f"coupling pass {state.iteration}: mesh-force change {state.mesh_force_change:.3g}, "
                f"μ change {state.mu_change:.3g} ({state.seconds:.2f} s)"
                if state.iteration else f"coupling pass 0: static start ({state.seconds:.2f} s)")
        log.info(text)
        if self._status is not None:
            self._status.update(text)

    def __exit__(self, *exc) -> bool:
        if self._status is not None:
            self._status.__exit__(*exc)
        return False


__all__ = ["CouplingProgress", "key_figures", "print_key_figures"]
