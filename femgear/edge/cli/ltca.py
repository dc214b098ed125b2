"""``femgear ltca SCENE``: the loaded tooth contact analysis alone (no dynamics, no lubrication).

Per torque (``--torques``, default the scene's ``operating.torque``): the loaded TE over one mesh
period (both helices together and each alone), its peak-to-peak and mesh-order amplitudes, the
mean and ripple of the mesh stiffness, the load share per helix, the largest contact pressure and
where it sits (edge contact flagged), the unloaded TE; ``--harris`` adds the Harris map.  Writes
``results.json``, the figures and one ParaView set per torque into ``--out`` (default
``out/<meta.name>/ltca``); prints a table (or, with ``--json``, one JSON line).  The member bodies'
compliance is built once per geometry and cached on disk (``$FEMGEAR_CACHE``, default
``out/cache/ltca``).  See docs/ltca_tool.md.
"""

from __future__ import annotations

import argparse
import math
import time
from dataclasses import replace
from pathlib import Path

from femgear.edge.cli.common import add_scene_arguments, emit_json
from femgear.errors import ArgumentError


def register(sub) -> None:
    p = sub.add_parser("ltca", help="loaded tooth contact analysis (LTCA) alone: transmission error (TE), its "
                                            "harmonics, load maps, Harris map")
    add_scene_arguments(p)
    p.add_argument("--torques", default=None, metavar="T1,T2,...",
                   help="driver torques [N m] (default: the scene's operating.torque)")
    p.add_argument("--harris", action="store_true", help="add the Harris map (TE peak-to-peak against torque)")
    p.add_argument("--harris-range", default=None, metavar="TMIN,TMAX[,N]",
                   help="torque range of the Harris map [N m] (default: 0.1 to 2 x the design torque, 12 points)")
    p.add_argument("--harmonics", type=int, default=5, metavar="N", help="mesh orders of the TE reported as peak amplitudes (default 5)")
    p.add_argument("--phases", type=int, default=64, metavar="N", help="phases per mesh period (default 64)")
    p.add_argument("--points", type=int, default=16, metavar="N", help="points per contact line (default 16)")
    p.add_argument("--no-check", action="store_true", help="skip the 2x-points check of the harmonics")
    p.add_argument("--no-helix-te", action="store_true", help="skip the TE of each helix alone")
    p.add_argument("--out", type=Path, default=None, help="output folder (default: out/<meta.name>/ltca)")
    p.add_argument("--no-plots", action="store_true", help="skip PNG figures")
    p.add_argument("--no-vtk", action="store_true", help="skip the ParaView output")
    p.add_argument("--json", action="store_true", help="print one JSON summary as the last line")
    p.set_defaults(func=_run)


def parse_torques(text: str | None, key: str) -> list[float]:
    """A comma-separated list of numbers, or :class:`ArgumentError` naming ``key``."""
    parts = [t for t in (text or "").split(",") if t.strip()]
    if not parts:
        raise ArgumentError(key, "no torque given (e.g. --torques 100,200,300)")
    try:
        return [float(t) for t in parts]
    except ValueError:
        raise ArgumentError(key, f"not a comma-separated list of numbers: {text!r}") from None


def harris_torques(text: str | None, design: float) -> list[float]:
    """The Harris map's torques from ``TMIN,TMAX[,N]`` (default 0.1 … 2 × ``design``, 12 points)."""
    if text is None:
        return [round(f * design, 6) for f in (0.1 + 1.9 * k / 11 for k in range(12))]
    vals = parse_torques(text, "--harris-range")
    if len(vals) not in (2, 3) or (len(vals) == 3 and (vals[2] != int(vals[2]) or not 2 <= vals[2] <= 50)):
        raise ArgumentError("--harris-range", f"expected TMIN,TMAX[,N] with 2 <= N <= 50, got {text!r}")
    lo, hi, n = vals[0], vals[1], int(vals[2]) if len(vals) == 3 else 12
    if not (math.isfinite(lo) and math.isfinite(hi) and 0 < lo < hi):
        raise ArgumentError("--harris-range", f"expected 0 < TMIN < TMAX, got {text!r}")
    return [lo + (hi - lo) * k / (n - 1) for k in range(n)]


def _options(args: argparse.Namespace):
    from femgear.physics.ltca.tool import LTCAOptions

    for key, value, lo, hi in (("--phases", args.phases, 8, 1024), ("--points", args.points, 2, 128)):
        if not lo <= value <= hi:
            raise ArgumentError(key, f"must be {lo}…{hi}, got {value}")
    return LTCAOptions(n_phases=args.phases, n_line=args.points, n_harmonics=args.harmonics,
                       refine_check=not args.no_check, helix_alone=not args.no_helix_te)


def _run(args: argparse.Namespace) -> int:
    from femgear.case import build_case
    from femgear.edge.io.paths import child_path, prepare_output_dir
    from femgear.levels.stiffness import body_options, body_order
    from femgear.physics.ltca.te import check_torques
    from femgear.physics.ltca.tool import run_ltca
    from femgear.scene import load_scene

    scene = load_scene(args.scene, args.overrides)
    case = build_case(scene)
    pair = case.pair
    E, nu, driver = scene.material.youngs_modulus, scene.material.poisson_ratio, scene.operating.driver
    design = scene.operating.torque
    given = [design] if args.torques is None else parse_torques(args.torques, "--torques")
    torques = check_torques(given, pair, E, nu, driver, "--torques")
    harris = check_torques(harris_torques(args.harris_range, design), pair, E, nu, driver, "--harris-range") \
        if args.harris else None
    options = replace(_options(args), level=case.numerics.level_of("ltca"), order=body_order(case.numerics.body_elements))
    if not 1 <= options.n_harmonics <= options.n_phases // 2 - 1:
        raise ArgumentError("--harmonics", f"must be 1…{options.n_phases // 2 - 1} for {options.n_phases} phases, "
                            f"got {options.n_harmonics}")
    out = prepare_output_dir(args.out if args.out is not None else
                             child_path("out", f"{scene.meta.name}/ltca", "meta.name"), "--out")
    t0 = time.perf_counter()
    result = run_ltca(pair, E, nu, scene.modifications, torques, design, driver, body_options(case), harris, options)
    files = _write(result, scene, pair, out, plots=not args.no_plots, vtk=not args.no_vtk)
    if args.json:
        from femgear.edge.io.ltca import ltca_summary

        summary = ltca_summary(result, scene.meta.name, math.cos(pair.beta_b))
        summary["outputs"] = {k: str(v) for k, v in files.items()}
        emit_json(summary)
    else:
        for name, path in files.items():
            print(f"{name}: {path}")
        _print_table(result, scene.meta.name, time.perf_counter() - t0)
    return 0


def _write(result, scene, pair, out: Path, plots: bool, vtk: bool) -> dict[str, Path]:
    from femgear.edge.io.ltca import torque_tag, write_ltca_results, write_maps

    files: dict[str, Path] = {}
    if plots:
        from femgear.edge.io.figures import save_figure
        from femgear.edge.plot.ltca import plot_harmonics, plot_harris, plot_load_distribution, plot_te_curves

        name = scene.meta.name
        files["te_curves_png"] = save_figure(
            plot_te_curves(result.analyses, f"{name}: loaded transmission error (TE), LTCA"), out / "te_curves.png")
        files["te_harmonics_png"] = save_figure(
            plot_harmonics(result.analyses, f"{name}: harmonics of the loaded transmission error (TE)"),
            out / "te_harmonics.png")
        for m in result.maps:
            files[f"load_{torque_tag(m.torque)}_png"] = save_figure(plot_load_distribution(m, name=name),
                                                                    out / f"load_{torque_tag(m.torque)}.png")
        if result.harris is not None:
            files["harris_png"] = save_figure(
                plot_harris(result.harris, f"{name}: Harris map, loaded transmission error against torque"),
                out / "harris.png")
    if vtk:
        for m in result.maps:
            files[f"maps_{torque_tag(m.torque)}_pvd"] = write_maps(out, m)
    files["results"] = out / "results.json"
    write_ltca_results(files["results"], result, scene, math.cos(pair.beta_b), files)
    return files


def _print_table(result, name: str, seconds: float) -> None:
    from femgear.edge.cli.report import print_key_figures

    rows = []
    for a in result.analyses:
        p = a.pressure
        tag = f"{a.torque:g} N m"
        rows.append((f"{tag}: loaded TE p-p (unloaded TE p-p)",
                     f"{a.peak_to_peak * 1e6:.4f} ({a.nlte_peak_to_peak * 1e6:.4f})", "µm"))
        rows.append((f"{tag}: TE harmonics 1…{a.harmonics.size}", " ".join(f"{x * 1e6:.4f}" for x in a.harmonics), "µm"))
        rows.append((f"{tag}: mesh stiffness mean (ripple)",
                     f"{a.stiffness_mean * 1e-9:.4g} ({a.stiffness_ripple * 100:.2f} %)", "kN/µm"))
        if a.n_helices == 2:
            rows.append((f"{tag}: load share left / right", f"{a.share_left:.4f} / {a.share_right:.4f}", ""))
        rows.append((f"{tag}: max pressure (away from edges)",
                     f"{p.pressure / 1e9:.3f} ({p.interior_pressure / 1e9:.3f}) at {p.where}"
                     + (", EDGE CONTACT" if p.edge else ""), "GPa"))
    h = result.harris
    if h is not None:
        i = int(h.peak_to_peak.argmin())
        rows.append(("Harris map: smallest TE p-p", f"{h.peak_to_peak[i] * 1e6:.4f} at {h.torque[i]:.4g} N m", "µm"))
    cache = "cached" if result.cached else "built"
    rows.append(("compliance (member bodies)", f"{result.model_seconds:.3g} s, {cache}", ""))
    rows.append(("wall time", f"{seconds:.3g}", "s"))
    print_key_figures(rows, title=f"{name}: LTCA")
