"""``femgear run SCENE``: parse, run and write a scene (:func:`femgear.edge.run.run_scene`), report.

The output folder is created and checked writable before anything is computed; a
``meta.name`` cannot place it outside ``out/``.  Prints the files written and a table
of key figures (or, with ``--json``, one JSON summary line: ``results.json``'s ``summary``).
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path

from femgear.edge.cli.common import add_scene_arguments, emit_json, load_case_arg


def register(sub) -> None:
    p = sub.add_parser("run", help="run what the scene's [physics] asks and write results")
    add_scene_arguments(p)
    p.add_argument("--out", type=Path, default=None, help="output folder (default: out/<meta.name>)")
    p.add_argument("--no-plots", action="store_true", help="skip PNG figures")
    p.add_argument("--no-vtk", action="store_true", help="skip the ParaView (.pvd/.vtu) output")
    p.add_argument("--json", action="store_true", help="print one JSON summary as the last line")
    p.set_defaults(func=_run)


def _run(args: argparse.Namespace) -> int:
    from femgear.edge.cli.report import CouplingProgress, key_figures, print_key_figures
    from femgear.edge.io.paths import child_path, prepare_output_dir
    from femgear.edge.run import run_scene

    case = load_case_arg(args)
    scene = case.scene
    if args.out is None:
        out = prepare_output_dir(child_path("out", scene.meta.name, "meta.name"), "meta.name")
    else:
        out = prepare_output_dir(args.out, "--out")
    t0 = time.perf_counter()
    with CouplingProgress(enabled=not (args.quiet or args.json)) as progress:
        written = run_scene(case, out, plots=not args.no_plots, vtk=not args.no_vtk, progress=progress)
    seconds = time.perf_counter() - t0
    if args.json:
        emit_json(written.summary)
    else:
        members = [name for name in written.files if "/" in name]     # the .vtu files of a .pvd collection
        for name, path in written.files.items():
            if "/" not in name:
                print(f"{name}: {path}")
        if members:
            print(f"(and the {len(members)} .vtu files of the .pvd collections, listed in results.json)")
        print_key_figures(key_figures(written.summary, seconds), title=f"{scene.meta.name}: key figures")
    return 0
