"""``femgear dynamics SCENE``: gear-rotor dynamics of a scene (time histories, amplitudes, modes)."""

from __future__ import annotations

import argparse
from pathlib import Path

from femgear.cli.common import add_scene_arguments, emit_json


def register(sub) -> None:
    p = sub.add_parser("dynamics", help="simulate the gear-rotor dynamics of a scene")
    add_scene_arguments(p)
    p.add_argument("--level", choices=("lumped", "timoshenko"), default=None,
                   help="dynamics level (default: physics.dynamics, or lumped)")
    p.add_argument("--stiffness", default=None,
                   help="mesh stiffness: constant, contact-line, iso6336, pem, fe (default: physics.stiffness)")
    p.add_argument("--method", choices=("expo", "rk4", "newmark"), default=None,
                   help="integrator (default: expo for lumped, rk4 for timoshenko)")
    p.add_argument("--dt", type=float, default=None, help="time step [s] (default per integrator)")
    p.add_argument("--cycles", type=float, default=100.0, help="mesh periods to simulate")
    p.add_argument("--transient", type=float, default=50.0, help="mesh periods dropped as transient")
    p.add_argument("--out", type=Path, default=None, help="output folder (default: out/<meta.name>/dynamics)")
    p.add_argument("--no-plots", action="store_true", help="skip PNG figures")
    p.add_argument("--json", action="store_true", help="print one JSON summary as the last line")
    p.set_defaults(func=_run)


def _run(args: argparse.Namespace) -> int:
    from femgear.dynamics.run import run_dynamics
    from femgear.scene import load_scene

    scene = load_scene(args.scene, args.overrides)
    out = args.out or Path("out") / scene.meta.name / "dynamics"
    run = run_dynamics(scene, out, level=args.level, stiffness=args.stiffness, method=args.method, dt=args.dt,
                       cycles=args.cycles, transient_cycles=args.transient, plots=not args.no_plots)
    if args.json:
        emit_json({**run.summary, "files": {k: str(v) for k, v in run.files.items()}})
    else:
        a = run.summary["amplitudes"]
        print(f"mesh frequency {run.summary['mesh_frequency']:.1f} Hz, {run.summary['method']} dt = "
              f"{run.summary['dt']:.3g} s, {run.summary['seconds']:.2f} s")
        for member in ("pinion", "gear"):
            print(f"{member}: displacement x/y {a[member + '.displacement.x'] * 1e6:.4f}/"
                  f"{a[member + '.displacement.y'] * 1e6:.4f} µm, velocity x/y "
                  f"{a[member + '.velocity.x'] * 1e3:.4f}/{a[member + '.velocity.y'] * 1e3:.4f} mm/s (half peak-to-peak)")
        for name, path in run.files.items():
            print(f"{name}: {path}")
    return 0
