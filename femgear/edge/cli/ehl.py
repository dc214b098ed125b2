"""``femgear ehl point|line``: isothermal EHL from Moes dimensionless inputs.

Prints a short table, or with ``--json`` one JSON object as the last stdout line with
``Hc``, ``Hmin`` (Moes units), ``Pmax`` (p/p_h), ``converged``, ``iterations``, ``nodes``,
``seconds`` and more. A non-converged case prints ``converged: false`` and exits 1.
"""

from __future__ import annotations

import argparse
import time


def register(sub) -> None:
    p = sub.add_parser("ehl", help="isothermal EHL (Moes inputs): point or line contact")
    ehl_sub = p.add_subparsers(dest="ehl_kind", required=True, metavar="KIND")
    pt = ehl_sub.add_parser("point", help="circular / elliptical contact (FE + DC-FFT)")
    _common(pt)
    pt.add_argument("--level", type=int, default=3, help="finest grid: 16*2^level intervals (3)")
    pt.add_argument("--ellipticity", type=float, default=1.0, help="lambda = Rx/Ry (1)")
    pt.add_argument("--method", choices=("auto", "fas", "newton"), default="auto",
                    help="solver: full multigrid (FD), Newton (FE), or auto = multigrid inside its "
                         "validated range (output: method, fallback)")
    pt.set_defaults(func=_point)
    ln = ehl_sub.add_parser("line", help="line contact: FD on graded grids converged to --tol (default), or FE")
    _common(ln)
    ln.add_argument("--level", type=int, default=None,
                    help="grid: 16*2^level intervals; fd: the finest level instead of --tol's choice (unset: the "
                         "solver picks it, up to level 7); fe: the grid (default 6)")
    ln.add_argument("--method", choices=("fd", "fe"), default="fd",
                    help="fd: finite differences on graded grids, levels refined until the Richardson estimates of "
                         "Hc and Hmin meet --tol (default 1 %%); fe: the Galerkin solver on uniform grids")
    ln.set_defaults(func=_line)


def _common(p: argparse.ArgumentParser) -> None:
    p.add_argument("--M", type=float, required=True, help="Moes load parameter")
    p.add_argument("--L", type=float, required=True, help="Moes lubricant parameter")
    p.add_argument("--roelands", action="store_true", help="Roelands viscosity (default Barus)")
    p.add_argument("--dowson-higginson", action="store_true", help="compressible oil")
    p.add_argument("--ph", type=float, default=1.0e9, help="Hertz pressure [Pa] for Roelands/DH")
    p.add_argument("--z", type=float, default=0.68, help="Roelands pressure index")
    p.add_argument("--out", default=None, help="folder for VTK/PNG/JSON output")
    p.add_argument("--json", action="store_true", help="print one JSON object as the last line")
    p.add_argument("--tol", type=float, default=None,
                   help="relative error of Hc and Hmin: stop at the cheapest level up to "
                        "--level whose Richardson estimate meets it (output: error_estimate, "
                        "flags, warning; line --method fd: 0.01 by default)")


def _options(args) -> dict:
    return {"viscosity": "roelands" if args.roelands else "barus",
            "compressible": bool(args.dowson_higginson), "ph": args.ph, "z": args.z}


def _check_arguments(args, lowest_level: int) -> None:
    """Refuse bad numbers, a level over the memory budget and an unwritable --out, before solving."""
    from femgear.edge.cli.limits import finite, level_in

    finite("--M", args.M, positive=True)
    finite("--L", args.L, nonnegative=True)
    finite("--ph", args.ph, positive=True)
    finite("--z", args.z, positive=True)
    if getattr(args, "ellipticity", None) is not None:
        finite("--ellipticity", args.ellipticity, positive=True)
    level_in("--level", args.level, lowest_level, args.ehl_kind)
    if args.out:
        from femgear.edge.io.paths import prepare_output_dir

        prepare_output_dir(args.out, "--out")


def _point(args) -> int:
    _check_arguments(args, lowest_level=1)
    from femgear.physics.ehl.point import solve_point

    return _run(args, lambda: solve_point(args.M, args.L, level=args.level, tol=args.tol,
                                          ratio=args.ellipticity, method=args.method, **_options(args)))


def _line(args) -> int:
    from femgear.physics.ehl.line import DEFAULT_TOL, solve_line

    if args.method == "fe" and args.level is None:
        args.level = 6
    if args.level is not None:
        _check_arguments(args, lowest_level=2)
    else:
        args.level = 7
        _check_arguments(args, lowest_level=2)
        args.level = None
    tol = args.tol if args.tol is not None or args.method == "fe" else DEFAULT_TOL
    return _run(args, lambda: solve_line(args.M, args.L, method=args.method, level=args.level, tol=tol,
                                         **_options(args)))


def _run(args, solve) -> int:
    from femgear.edge.cli.common import emit_json
    from femgear.errors import ConvergenceError

    t0 = time.perf_counter()
    try:
        res = solve()
    except ConvergenceError as exc:
        payload = {"Hc": None, "Hmin": None, "Pmax": None, "converged": False,
                   "iterations": len(exc.history.get("residual", [])), "nodes": None,
                   "seconds": time.perf_counter() - t0, "error": str(exc)}
        if args.json:
            emit_json(payload)
        else:
            print(f"not converged: {exc}")
        return 1
    out = res.summary()
    if args.out:
        from femgear.edge.io.ehl import write_all

        out["files"] = write_all(res, args.out, stem=f"ehl_{res.kind}")
    if args.json:
        emit_json(out)
    else:
        for k in ("Hc", "Hmin", "Pmax", "Pmax_at", "outlet_x", "load_error", "iterations",
                  "nodes", "seconds", "error_estimate", "warning", "method"):
            print(f"{k:>11}: {out[k]}")
    return 0
