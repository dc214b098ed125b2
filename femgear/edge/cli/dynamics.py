"""``femgear dynamics SCENE``: gear-rotor dynamics of a scene (time histories, amplitudes, modes)."""

from __future__ import annotations

import argparse
from pathlib import Path

from femgear.edge.cli.campbell import add_campbell_arguments, campbell_speeds, check_campbell_arguments, run_campbell
from femgear.edge.cli.common import add_scene_arguments, emit_json, load_case_arg
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
                   help="instead of one run: time-domain speed sweep of the driver speed; plots the RMS of the "
                        "dynamic transmission error (DTE) against mesh frequency with the natural frequencies "
                        "(≥ 5 %% mesh strain energy) marked where the mesh frequency or its 2nd-4th harmonic "
                        "meets them (writes dynamics_sweep.png), and the dynamic factor K_v per helix beside ISO "
                        "6336-1 method B with the resonance ratio N (dynamics_K_v.png)")
    p.add_argument("--kahraman-singh", action="store_true",
                   help="instead of one run: up/down frequency sweeps of the Kahraman-Singh backlash oscillator "
                        "(writes kahraman_singh.png)")
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
    if args.campbell:
        check_campbell_arguments(args)
    case = load_case_arg(args)
    if args.sweep:
        _check_sweep_speeds(case, sweep_speeds(args.sweep))
    if args.campbell:
        _check_sweep_speeds(case, [s for s in campbell_speeds(args.campbell)[[0, -1]] if s > 0], "--campbell")
    if args.out is None:
        out = prepare_output_dir(child_path("out", case.name, "meta.name") / "dynamics", "meta.name")
    else:
        out = prepare_output_dir(args.out, "--out")
    if args.campbell:
        return run_campbell(case, args, out)
    if args.sweep:
        return _sweep(case, args, out)
    if args.kahraman_singh:
        return _kahraman_singh(args, out)
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
        _print_modes(run.modal)
    return 0


def _print_modes(modal) -> None:
    print(f"{'mode':>4s} {'f [Hz]':>9s} {'mesh energy':>11s}  dominant kinetic-energy group")
    for i, f in enumerate(modal.frequencies):
        print(f"{i:4d} {f:9.1f} {modal.energy['mesh'][i]:11.2f}  {modal.dominant_group(i)}")


def sweep_speeds(text: str):
    """``RPM0:RPM1:N`` as N speeds [rpm]; :class:`ArgumentError` naming ``--sweep`` otherwise."""
    import numpy as np

    from femgear.errors import ArgumentError

    try:
        a, b, n = text.split(":")
        lo, hi, count = float(a), float(b), int(n)
    except ValueError:
        raise ArgumentError("--sweep", f"expected RPM0:RPM1:N, got {text!r}") from None
    if not (np.isfinite(lo) and np.isfinite(hi) and 0 < lo <= hi and count >= 1):
        raise ArgumentError("--sweep", f"need finite 0 < RPM0 ≤ RPM1 and N ≥ 1, got {text!r}")
    return np.linspace(lo, hi, count)


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


def _sweep(case, args, out: Path) -> int:
    import numpy as np

    from femgear.system.dynamics import build_model
    from femgear.system.dynamics.modal import modal_analysis, resonance_marks
    from femgear.system.dynamics.sweep import speed_sweep

    rpm = sweep_speeds(args.sweep)
    kw = {"level": args.level, "stiffness": args.stiffness}
    sw = speed_sweep(case, rpm, method=args.method, **kw)
    model = build_model(case, **kw)
    modal = modal_analysis(model)
    marks = resonance_marks(modal.frequencies, modal.energy["mesh"], float(sw.mesh_frequency.min()),
                            float(sw.mesh_frequency.max()))
    files = {}
    if not args.no_plots:
        from femgear.edge.io.figures import save_figure
        from femgear.edge.plot.dynamics import plot_sweep

        files["sweep"] = save_figure(plot_sweep(sw, modal, name=f"{case.name} ({model.level}, {model.stiffness.label} stiffness)"),
                                     out / "dynamics_sweep.png")
    kv = _dynamic_factor(case, sw, out, files, plots=not args.no_plots)
    if args.json:
        from femgear.edge.cli.common import emit_json

        emit_json({"speed_rpm": sw.speed_rpm, "mesh_frequency": sw.mesh_frequency, "dte_rms": sw.dte_rms,
                   "natural_frequencies_hz": modal.frequencies, "mesh_energy": modal.energy["mesh"],
                   "resonances": [{"mesh_frequency": x, "harmonic": k, "natural_frequency": f}
                                  for x, k, f in marks],
                   "dynamic_factor": {"pinion_speed_rpm": kv.speed_rpm, "femgear": kv.femgear,
                                      "iso_method_b": kv.iso, "resonance_ratio": kv.N,
                                      "resonance_speed_rpm": kv.n_E1, "N_S": kv.N_S},
                   "files": {k: str(v) for k, v in files.items()}})
        return 0
    print(f"{'rpm':>8s} {'f_m [Hz]':>9s} {'DTE RMS [µm]':>12s} {'K_v femgear':>11s} {'K_v ISO B':>9s} {'N':>6s}"
          "  (DTE: dynamic transmission error)")
    for i, (r, f, d) in enumerate(zip(sw.speed_rpm, sw.mesh_frequency, sw.dte_rms)):
        print(f"{r:8.1f} {f:9.1f} {d * 1e6:12.5f} {np.nanmax(kv.femgear[:, i]):11.4f} {kv.iso[i]:9.4f} {kv.N[i]:6.3f}")
    _print_modes(modal)
    for x, k, f in marks:
        print(f"resonance in range: f_m = {x:.1f} Hz, mesh harmonic {k} meets the natural frequency {f:.1f} Hz")
    for name, path in files.items():
        print(f"{name}: {path}")
    return 0


def _dynamic_factor(case, sw, out: Path, files: dict, plots: bool):
    """K_v over the sweep, femgear's beside ISO 6336-1 method B (:func:`femgear.rate.dynamic_factor_curve`); with
    ``plots`` its figure ``dynamics_K_v.png`` goes into ``files``."""
    from femgear.rate import dynamic_factor_curve

    kv = dynamic_factor_curve(case, sw.speed_rpm, sw.amplitudes)
    if plots:
        from femgear.edge.io.figures import save_figure
        from femgear.edge.plot.rating import plot_dynamic_factor

        files["dynamic_factor"] = save_figure(plot_dynamic_factor(kv, f"{case.name}: dynamic factor K_v, femgear's "
                                                                      "dynamics beside ISO 6336-1 method B"),
                                              out / "dynamics_K_v.png")
    return kv


def _kahraman_singh(args, out: Path) -> int:
    import numpy as np

    from femgear.system.dynamics.sdof import kahraman_singh_sweep

    w = np.linspace(0.6, 1.3, 36)
    up, down = kahraman_singh_sweep(w, direction="up"), kahraman_singh_sweep(w, direction="down")
    files = {}
    if not args.no_plots:
        from femgear.edge.io.figures import save_figure
        from femgear.edge.plot.dynamics import plot_branches

        files["branches"] = save_figure(plot_branches(up, down), out / "kahraman_singh.png")
    a_down, loss_down = down.amplitude[::-1], down.contact_loss[::-1]
    if args.json:
        from femgear.edge.cli.common import emit_json

        emit_json({"frequency": up.frequency, "amplitude_up": up.amplitude, "amplitude_down": a_down,
                   "contact_loss_up": up.contact_loss, "contact_loss_down": loss_down,
                   "files": {k: str(v) for k, v in files.items()}})
        return 0
    print("Kahraman-Singh oscillator, ζ = 0.05, F_m = 0.1, F_a = 0.02 (lengths over the backlash b)")
    print(f"{'Ω':>6s} {'amp up':>8s} {'amp down':>9s} {'loss up':>8s} {'loss down':>9s}")
    for i, om in enumerate(up.frequency):
        print(f"{om:6.3f} {up.amplitude[i]:8.4f} {a_down[i]:9.4f} {up.contact_loss[i]:8.2f} {loss_down[i]:9.2f}")
    for name, path in files.items():
        print(f"{name}: {path}")
    return 0
