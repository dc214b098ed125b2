"""``femgear dynamics SCENE``: gear-rotor dynamics of a scene (time histories, amplitudes, modes)."""

from __future__ import annotations

import argparse
from pathlib import Path

from femgear.edge.cli.campbell import add_campbell_arguments, campbell_speeds, check_campbell_arguments, run_campbell
from femgear.edge.cli.common import add_scene_arguments, emit_json, load_case_arg
from femgear.edge.cli.dynamics_nvh import add_nvh_arguments, print_modes, sweep_speeds
from femgear.edge.cli.levels import level_choices

#: a mesh stiffness of the dynamics only (not a scene level): c_γ times the contact-line length
DYNAMICS_ONLY_STIFFNESS = ("contact-line",)


def register(sub) -> None:
    p = sub.add_parser("dynamics", help="simulate the gear-rotor dynamics of a scene")
    add_scene_arguments(p)
    levels = level_choices("dynamics", exclude=("none",))
    p.add_argument("--level", choices=levels, default=None,
                   help=f"dynamics level: {', '.join(levels)} (default: physics.dynamics, or {levels[0]})")
    stiffness = level_choices("stiffness")
    p.add_argument("--stiffness", choices=stiffness + DYNAMICS_ONLY_STIFFNESS, default=None, metavar="LEVEL",
                   help=f"mesh stiffness level: {', '.join(stiffness)} (the physics.stiffness levels), or "
                        "contact-line (c_γ times the length of the lines in contact; dynamics only) "
                        "(default: physics.stiffness)")
    p.add_argument("--method", choices=("expo", "rk4", "newmark"), default=None,
                   help="integrator (default: expo for lumped, rk4 for timoshenko)")
    p.add_argument("--dt", type=float, default=None, help="time step [s] (default per integrator)")
    p.add_argument("--cycles", type=float, default=100.0, help="mesh periods to simulate")
    p.add_argument("--transient", type=float, default=50.0, help="mesh periods dropped as transient")
    p.add_argument("--out", type=Path, default=None, help="output folder (default: out/<meta.name>/dynamics)")
    p.add_argument("--no-plots", action="store_true", help="skip PNG figures")
    p.add_argument("--json", action="store_true", help="print one JSON summary as the last line")
    p.add_argument("--modes", action="store_true", help="print the natural frequencies and modal energies")
    p.add_argument("--sweep", metavar="RPM0:RPM1:N", default=None,
                   help="instead of one run: speed sweep of the driver speed (harmonic balance where it applies, see "
                        "--sweep-method); plots the RMS of the dynamic transmission error (DTE) against mesh "
                        "frequency with the natural frequencies (≥ 5 %% mesh strain energy) marked where the mesh "
                        "frequency or its 2nd-4th harmonic meets them, the mesh-order amplitudes of the mesh and "
                        "bearing forces against speed, and the dynamic factor K_v per helix beside ISO 6336-1 "
                        "method B with the resonance ratio N (writes dynamics_sweep.png, dynamics_orders.png, "
                        "dynamics_K_v.png, dynamics_sweep.json, dynamics_sweep.npz)")
    p.add_argument("--kahraman-singh", action="store_true",
                   help="instead of one run: up/down frequency sweeps of the Kahraman-Singh backlash oscillator "
                        "and its harmonic-balance continuation through the folds (writes kahraman_singh.png, "
                        "kahraman_singh_hb.png)")
    add_nvh_arguments(p)
    add_campbell_arguments(p)
    p.set_defaults(func=_run)


def _run(args: argparse.Namespace) -> int:
    from femgear.edge.cli.limits import finite
    from femgear.edge.io.paths import child_path, prepare_output_dir
    from femgear.errors import ArgumentError

    if args.dt is not None:
        finite("--dt", args.dt, positive=True)
    finite("--cycles", args.cycles, positive=True)
    finite("--transient", args.transient, nonnegative=True)
    if args.transient >= args.cycles:
        raise ArgumentError("--transient", f"must be less than --cycles ({args.transient:g} ≥ {args.cycles:g})")
    from femgear.edge.cli import dynamics_nvh as nvh

    nvh.check_nvh_arguments(args)
    check_campbell_arguments(args)
    case = load_case_arg(args)
    if args.sweep:
        _check_sweep_speeds(case, sweep_speeds(args.sweep))
    if args.runup:
        ramp = nvh.runup_ramp(args.runup)
        _check_sweep_speeds(case, (ramp.rpm0, ramp.rpm1), "--runup")
        nvh.check_runup_blocks(case, ramp, args.revolutions)
    if args.campbell:
        _check_sweep_speeds(case, [s for s in campbell_speeds(args.campbell)[[0, -1]] if s > 0], "--campbell")
    if args.out is None:
        out = prepare_output_dir(child_path("out", case.name, "meta.name") / "dynamics", "meta.name")
    else:
        out = prepare_output_dir(args.out, "--out")
    if args.campbell:
        return run_campbell(case, args, out)
    if args.sweep:
        return nvh.run_sweep(case, args, out)
    if args.runup:
        return nvh.run_runup(case, args, out)
    if args.kahraman_singh:
        return nvh.run_kahraman_singh(args, out)
    from femgear.edge.io.dynamics import dynamics_summary, write_dynamics
    from femgear.system.dynamics import build_model, run_dynamics

    model = build_model(case, args.level, stiffness=args.stiffness)
    run = run_dynamics(model, method=args.method or case.numerics.dynamics_method, dt=args.dt, cycles=args.cycles,
                       transient_cycles=args.transient, steps_per_period=case.numerics.steps_per_mesh_period)
    files = write_dynamics(run, out, plots=not args.no_plots, name=case.name)
    summary = dynamics_summary(run)
    if args.json:
        emit_json({**summary, "files": {k: str(v) for k, v in files.items()}})
    else:
        a = summary["amplitudes"]
        print(f"mesh frequency {summary['mesh_frequency']:.1f} Hz, {summary['method']} dt = "
              f"{summary['dt']:.3g} s, {summary['seconds']:.2f} s")
        for member in ("pinion", "gear"):
            print(f"{member}: displacement x/y {a[member + '.displacement.x'] * 1e6:.4f}/"
                  f"{a[member + '.displacement.y'] * 1e6:.4f} µm, velocity x/y "
                  f"{a[member + '.velocity.x'] * 1e3:.4f}/{a[member + '.velocity.y'] * 1e3:.4f} mm/s (half peak-to-peak)")
        for name, path in files.items():
            print(f"{name}: {path}")
    if args.modes and not args.json:
        print_modes(run.modal)
    return 0


def _check_sweep_speeds(case, speeds, argument: str = "--sweep") -> None:
    """The sweep's end speeds pass the scene's speed checks (:mod:`femgear.scene.ranges`, the burst
    speed of the case's pair), before any computing; a refusal names ``argument``."""
    from femgear.errors import ArgumentError, SceneError
    from femgear.scene.load import scene_from_dict
    from femgear.scene.plausibility import check_operating_limits

    data = case.scene.model_dump(exclude_none=True)
    for rpm in {float(speeds[0]), float(speeds[-1])} if len(speeds) else ():
        try:
            check_operating_limits(scene_from_dict(data, [f"operating.speed_rpm={rpm!r}"], warn=False), case.pair)
        except SceneError as exc:
            if exc.key != "operating.speed_rpm":
                raise
            raise ArgumentError(argument, exc.message) from None
