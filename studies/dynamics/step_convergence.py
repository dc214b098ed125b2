"""Time-step convergence of the dynamics with the default step, at low and nominal speed.

    python studies/dynamics/step_convergence.py [--coarse] [--rpm 100 500]

For each driver speed the baseline model (lumped, PEM stiffness, the formula level's
μ(u)) runs with its default integrator and step (:func:`femgear.system.dynamics.run.default_step`)
and with the step halved and quartered; the table prints the largest relative change
of the member amplitudes (x, y, displacement and velocity) and of the mesh-force
amplitude.  Target (issue 13): < 1 % between the default and the halved step at every
speed.  Writes ``out/step_convergence/step_convergence.json``.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[2]
KEYS = [f"{m}.{q}.{a}" for m in ("pinion", "gear") for q in ("displacement", "velocity") for a in "xy"] + \
       ["mesh_force.L.amplitude"]


def setup(rpm: float):
    from femgear.case import build_case
    from femgear.scene import load_scene

    return build_case(load_scene(ROOT / "studies" / "paper_baseline.toml", [f"operating.speed_rpm={rpm!r}"]))


def run(speeds=(100.0, 500.0), coarse: bool = False) -> dict:
    from femgear.system.dynamics import build_model, run_dynamics
    from femgear.system.dynamics.run import default_method, default_step

    cycles, transient = (40.0, 20.0) if coarse else (100.0, 50.0)
    rows = []
    for rpm in speeds:
        model = build_model(setup(rpm))
        method = default_method(model)
        h = default_step(model, method)
        amps, seconds = [], []
        for f in (1, 2, 4):
            t0 = time.perf_counter()
            a = run_dynamics(model, method=method, dt=h / f, cycles=cycles, transient_cycles=transient).amplitudes
            seconds.append(time.perf_counter() - t0)
            amps.append(np.array([a[k] for k in KEYS]))
        change = [float(np.max(np.abs(amps[i] / amps[i + 1] - 1))) for i in range(2)]
        rows.append({"rpm": rpm, "method": method, "dt": h, "steps_per_mesh_period": model.mesh_period / h,
                     "change_default_vs_half": change[0], "change_half_vs_quarter": change[1],
                     "worst_key": KEYS[int(np.argmax(np.abs(amps[0] / amps[1] - 1)))], "seconds": seconds})
    return {"rows": rows, "coarse": coarse}


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--coarse", action="store_true")
    p.add_argument("--rpm", type=float, nargs="+", default=[100.0, 500.0])
    args = p.parse_args(argv)
    res = run(tuple(args.rpm), args.coarse)
    print(f"{'rpm':>6s} {'method':>6s} {'dt [s]':>9s} {'steps/T_m':>9s} {'h vs h/2':>9s} {'h/2 vs h/4':>10s}  worst")
    for r in res["rows"]:
        print(f"{r['rpm']:6.0f} {r['method']:>6s} {r['dt']:9.3g} {r['steps_per_mesh_period']:9.0f} "
              f"{100 * r['change_default_vs_half']:8.3f}% {100 * r['change_half_vs_quarter']:9.3f}%  {r['worst_key']}")
    from femgear.edge.io.results import write_json

    print(write_json(ROOT / "out" / "step_convergence" / "step_convergence.json", res))
    return 0


if __name__ == "__main__":
    sys.exit(main())
