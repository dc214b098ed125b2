"""Gear-rotor dynamics: seconds per 100 mesh periods of the baseline at converged step size.

    python studies/benchmarks/dynamics.py [SCENE] [--quick]

Case: the baseline pair (500 rpm, f_m = 258 Hz, 100 mesh periods = 0.387 s), lumped
24-DOF model, contact-line TVMS, friction μ = 0.05, profile error 1 µm (3 mesh
orders) and 20 µm eccentricity on both members.  Reference: RK4 at 1/1600 of the mesh
period.  For each integrator the step is halved from a coarse value until every
amplitude (pinion and gear x/y displacement and velocity, mesh-force amplitude of
both helices) is within 0.5 % of the reference — each from its own samples, the
extremes refined by a parabola, so sampling is part of the error; that
step is then timed over 100 mesh periods (median of 3 repeats after one warm-up run;
``expo``'s propagators are built once per structure and step — their set-up time is
reported separately, and a new structure pays it once).  Prints a table
and one JSON line.  ``--quick``: 40 mesh periods, one repeat.
"""

from __future__ import annotations

import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")   # many small dense products: threads only contend

import json
import statistics
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
KEYS = [f"{m}.{k}.{a}" for m in ("pinion", "gear") for k in ("displacement", "velocity") for a in "xy"] + \
       ["mesh_force.L.amplitude", "mesh_force.R.amplitude"]
OVERRIDES = ["errors.profile_error=1e-6", "pinion.eccentricity=20e-6", "gear.eccentricity=20e-6"]


def setup(scene_path: str | Path = ROOT / "studies" / "paper_baseline.toml"):
    from femgear.case import build_case
    from femgear.scene import load_scene
    from femgear.system.dynamics import build_model

    return build_model(build_case(load_scene(scene_path, OVERRIDES)), "lumped", stiffness="contact-line")


def _amplitudes(model, periods, dt, method, record_every=1):
    from femgear.system.dynamics import simulate
    from femgear.system.dynamics.response import analyse

    sim = simulate(model, periods * model.mesh_period, dt, method, record_every=record_every)
    return analyse(sim, transient_cycles=periods / 2).amplitudes, sim


def max_error(model, periods, dt, method, reference=None) -> tuple[float, float]:
    """Largest relative amplitude error against RK4 at T_m/1600 (its own fine sampling); the step used.

    Each method's amplitudes come from its own samples (extremes refined by a parabola), so
    the error includes what a user sees: integration and sampling together.
    """
    from femgear.system.dynamics.integrate import expo_step

    if method == "expo":
        dt = expo_step(model, dt)[0]
    ref = reference if reference is not None else _amplitudes(model, periods, model.mesh_period / 1600, "rk4")[0]
    got, sim = _amplitudes(model, periods, dt, method)
    return max(abs(got[k] / ref[k] - 1) for k in KEYS), sim.dt


def converged_step(model, method, periods, start, reference, tol=5e-3) -> tuple[float, list]:
    from femgear.system.dynamics import stability_limit

    dt, history = start, []
    limit = stability_limit(model) if method == "rk4" else float("inf")
    while True:
        if dt <= limit:
            err, used = max_error(model, periods, dt, method, reference)
            history.append((used, err))
            if err < tol:
                return used, history
        dt /= 2
        if dt < model.mesh_period / 1600:
            raise RuntimeError(f"{method}: no step down to T_m/1600 reaches {tol:.1%}")


def time_run(model, method, dt, periods, repeats) -> tuple[float, float]:
    """Median wall time per 100 mesh periods of the integration loop, and the one-off set-up [s]."""
    from femgear.system.dynamics import simulate
    from femgear.system.dynamics.expo import clear_propagator_cache

    clear_propagator_cache()                   # measure expo's set-up once, from scratch
    wall, setup = [], 0.0
    for r in range(repeats + 1):
        t = time.perf_counter()
        sim = simulate(model, periods * model.mesh_period, dt, method)
        if r == 0:
            setup = sim.info.get("setup_seconds", 0.0)
            continue                           # first run: builds expo's propagators
        wall.append(time.perf_counter() - t)
    return statistics.median(wall) * 100 / periods, setup


def run(model, quick: bool = False) -> list[dict]:
    periods_conv = 40 if quick else 60
    periods = 40 if quick else 100
    repeats = 1 if quick else 3
    starts = {"rk4": model.mesh_period / 50, "expo": model.mesh_period / 25, "newmark": model.mesh_period / 100}
    reference = _amplitudes(model, periods_conv, model.mesh_period / 1600, "rk4")[0]
    rows = []
    for method in ("rk4", "expo", "newmark"):
        dt, hist = converged_step(model, method, periods_conv, starts[method], reference)
        total, setup = time_run(model, method, dt, periods, repeats)
        rows.append({"method": method, "dt": dt, "steps_per_mesh_period": model.mesh_period / dt,
                     "max_amplitude_error": hist[-1][1], "seconds_per_100_periods": total,
                     "setup_seconds": setup, "history": hist})
    return rows


def main(argv: list[str]) -> int:
    quick = "--quick" in argv
    args = [a for a in argv if not a.startswith("--")]
    model = setup(args[0]) if args else setup()
    rows = run(model, quick)
    print(f"baseline, lumped 24-DOF, f_m = {model.mesh_frequency:.1f} Hz; tolerance 0.5 % on {len(KEYS)} amplitudes")
    print(f"{'method':8s} {'dt [s]':>10s} {'steps/T_m':>9s} {'max err':>8s} {'s/100 T_m':>10s} {'set-up once [s]':>15s}")
    for r in rows:
        print(f"{r['method']:8s} {r['dt']:10.3g} {r['steps_per_mesh_period']:9.1f} {r['max_amplitude_error']:8.2%} "
              f"{r['seconds_per_100_periods']:10.3f} {r['setup_seconds']:15.3f}")
    print("step-size convergence (steps per mesh period: max amplitude error):")
    for r in rows:
        print(f"  {r['method']:8s} " + ", ".join(f"{model.mesh_period / dt:.0f}: {err:.2%}" for dt, err in r["history"]))
    print(json.dumps({"benchmark": "dynamics", "quick": quick, **{
        f"{r['method']}_s_per_100_periods": round(r["seconds_per_100_periods"], 4) for r in rows}, **{
        f"{r['method']}_dt": r["dt"] for r in rows}, "expo_setup_s": round(rows[1]["setup_seconds"], 4)}))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
