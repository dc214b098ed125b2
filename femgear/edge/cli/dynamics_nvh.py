"""The whine options of ``femgear dynamics``: the frequency-domain sweep (``--sweep`` with ``--sweep-method``), the
run-up (``--runup RPM0:RPM1:SECONDS``) and the Kahraman–Singh continuation (``--kahraman-singh``)."""

from __future__ import annotations

import argparse
import math
import sys
from pathlib import Path

import numpy as np

from femgear.errors import ArgumentError


def add_nvh_arguments(p: argparse.ArgumentParser) -> None:
    """The options of this module on the ``dynamics`` parser."""
    p.add_argument("--sweep-method", choices=("auto", "harmonic", "time"), default="auto",
                   help="with --sweep: harmonic (harmonic balance per speed, flanks in contact; speeds where the "
                        "flanks separate run in the time domain, with a warning), time (time integration at every "
                        "speed) or auto (harmonic where it applies: default)")
    p.add_argument("--harmonics", type=int, default=None, metavar="H",
                   help="with --sweep: mesh harmonics of the harmonic balance (default: 24, doubled until the lines "
                        "of mesh orders up to H/4 change less than 1e-3)")
    p.add_argument("--runup", metavar="RPM0:RPM1:SECONDS", default=None,
                   help="instead of one run: a speed ramp from RPM0 to RPM1 over SECONDS in the time domain, order-"
                        "tracked (writes runup.png, runup_bearing.png, runup.json, runup.npz)")
    p.add_argument("--revolutions", type=int, default=4, metavar="N",
                   help="with --runup: pinion revolutions per order-tracking block (order resolution 1/N; default 4)")


def print_modes(modal) -> None:
    """The natural frequencies, mesh strain energies and dominant groups of ``modal``, one line each."""
    print(f"{'mode':>4s} {'f [Hz]':>9s} {'mesh energy':>11s}  dominant kinetic-energy group")
    for i, f in enumerate(modal.frequencies):
        print(f"{i:4d} {f:9.1f} {modal.energy['mesh'][i]:11.2f}  {modal.dominant_group(i)}")


def sweep_speeds(text: str):
    """``RPM0:RPM1:N`` as N speeds [rpm]; :class:`ArgumentError` naming ``--sweep`` otherwise."""
    import numpy as np

    try:
        a, b, n = text.split(":")
        lo, hi, count = float(a), float(b), int(n)
    except ValueError:
        raise ArgumentError("--sweep", f"expected RPM0:RPM1:N, got {text!r}") from None
    if not (np.isfinite(lo) and np.isfinite(hi) and 0 < lo <= hi and count >= 1):
        raise ArgumentError("--sweep", f"need finite 0 < RPM0 ≤ RPM1 and N ≥ 1, got {text!r}")
    return np.linspace(lo, hi, count)


def runup_ramp(text: str):
    """``RPM0:RPM1:SECONDS`` as a :class:`~femgear.system.dynamics.runup.Ramp`; :class:`ArgumentError` naming
    ``--runup`` otherwise (end speed not above the start speed, duration not positive, speeds not positive)."""
    from femgear.system.dynamics.runup import Ramp

    try:
        a, b, s = text.split(":")
        lo, hi, seconds = float(a), float(b), float(s)
    except ValueError:
        raise ArgumentError("--runup", f"expected RPM0:RPM1:SECONDS, got {text!r}") from None
    if not all(math.isfinite(x) for x in (lo, hi, seconds)):
        raise ArgumentError("--runup", f"need finite numbers, got {text!r}")
    if lo <= 0:
        raise ArgumentError("--runup", f"the start speed RPM0 must be positive (got {lo:g} rpm)")
    if hi <= lo:
        raise ArgumentError("--runup", f"the end speed RPM1 must exceed the start speed RPM0 (got {hi:g} ≤ {lo:g} rpm)")
    if seconds <= 0:
        raise ArgumentError("--runup", f"the duration SECONDS must be positive (got {seconds:g} s)")
    return Ramp(lo, hi, seconds)


def check_nvh_arguments(args: argparse.Namespace) -> None:
    """Argument checks before any computing."""
    chosen = [name for name, on in (("--sweep", args.sweep), ("--runup", args.runup), ("--campbell", args.campbell),
                                    ("--kahraman-singh", args.kahraman_singh)) if on]
    if len(chosen) > 1:
        raise ArgumentError(chosen[1], f"choose one of {', '.join(chosen)}")
    if args.harmonics is not None and args.harmonics < 2:
        raise ArgumentError("--harmonics", f"must be an integer ≥ 2 (got {args.harmonics})")
    if args.revolutions < 1:
        raise ArgumentError("--revolutions", f"must be a positive integer (got {args.revolutions})")
    if args.runup:
        runup_ramp(args.runup)


def check_runup_blocks(case, ramp, revolutions: int) -> None:
    """The ramp turns the pinion through at least one order-tracking block (and its overlap); else an
    :class:`ArgumentError` naming ``--runup``, before any computing."""
    pinion_per_driver = case.operating.pinion_rpm / case.scene.operating.speed_rpm
    turns = 0.5 * (ramp.rpm0 + ramp.rpm1) * ramp.duration / 60.0 * pinion_per_driver
    if math.floor(2 * turns / revolutions) - 1 < 1:
        raise ArgumentError("--runup", f"the ramp turns the pinion {turns:.3g} revolutions, fewer than the "
                                       f"{1.5 * revolutions:g} that one block of --revolutions {revolutions} and its "
                                       "overlap need: lengthen the ramp or shorten the blocks")


def _progress(stage: str, total: int, expected: float):
    from femgear.perf import Progress

    return Progress(stage, total, expected)


def run_sweep(case, args: argparse.Namespace, out: Path) -> int:
    """``--sweep``: the order sweep by the chosen method; files and summary."""
    from femgear.edge.cli.common import emit_json
    from femgear.edge.io.nvh import order_sweep_summary, write_order_sweep
    from femgear.system.dynamics.family import SpeedFamily
    from femgear.system.dynamics.harmonic_sweep import harmonic_sweep
    from femgear.system.dynamics.modal import modal_analysis

    rpm = sweep_speeds(args.sweep)
    kw = {"level": args.level, "stiffness": args.stiffness}
    progress = _progress("speed sweep", rpm.size, 0.5 * rpm.size if args.sweep_method == "time" else 0.0)
    sw = harmonic_sweep(case, rpm, method=args.sweep_method, harmonics=args.harmonics, integrator=args.method,
                        progress=progress, **kw)
    model = SpeedFamily(case, **kw).base
    modal = modal_analysis(model)
    label = f"{case.name} ({model.level}, {model.stiffness.label} stiffness)"
    files = write_order_sweep(sw, modal, out, plots=not args.no_plots, name=label)
    kv = _dynamic_factor(case, sw, out, files, plots=not args.no_plots)
    for w in sw.warnings:
        print(f"warning: {w}", file=sys.stderr)
    if args.json:
        emit_json({**order_sweep_summary(sw, modal),
                   "dynamic_factor": {"pinion_speed_rpm": kv.speed_rpm, "femgear": kv.femgear, "iso_method_b": kv.iso,
                                      "resonance_ratio": kv.N, "resonance_speed_rpm": kv.n_E1, "N_S": kv.N_S},
                   "files": {k: str(v) for k, v in files.items()}})
        return 0
    print(f"{'rpm':>8s} {'f_m [Hz]':>9s} {'DTE RMS [µm]':>12s} {'N_L order 1..3 [N]':>26s} {'K_v femgear':>11s} "
          f"{'K_v ISO B':>9s} {'N':>6s}  method")
    for i, (r, f, d) in enumerate(zip(sw.speed_rpm, sw.mesh_frequency, sw.dte_rms)):
        orders = " ".join(f"{x:8.4g}" for x in sw.mesh_force[i, 0, :3])
        print(f"{r:8.1f} {f:9.1f} {d * 1e6:12.5f} {orders:>26s} {np.nanmax(kv.femgear[:, i]):11.4f} {kv.iso[i]:9.4f} "
              f"{kv.N[i]:6.3f}  {sw.method[i]}")
    print_modes(modal)
    for r in order_sweep_summary(sw, modal)["resonances"]:
        print(f"resonance in range: f_m = {r['mesh_frequency']:.1f} Hz, mesh harmonic {r['harmonic']} meets the "
              f"natural frequency {r['natural_frequency']:.1f} Hz")
    for name, path in files.items():
        print(f"{name}: {path}")
    return 0


def _dynamic_factor(case, sw, out: Path, files: dict, plots: bool):
    """K_v over the sweep, femgear's (the largest over the mean mesh force of each helix) beside ISO 6336-1 method B
    (:func:`femgear.rate.dynamic_factor_curve`); with ``plots`` its figure ``dynamics_K_v.png`` goes into
    ``files``."""
    from femgear.rate import dynamic_factor_curve

    amplitudes = {f"mesh_force.{side}.{what}": values[:, j] for j, side in enumerate("LR")
                  for what, values in (("mean", sw.mesh_force_mean), ("max", sw.mesh_force_max))}
    kv = dynamic_factor_curve(case, sw.speed_rpm, amplitudes)
    if plots:
        from femgear.edge.io.figures import save_figure
        from femgear.edge.plot.rating import plot_dynamic_factor

        files["dynamic_factor"] = save_figure(plot_dynamic_factor(kv, f"{case.name}: dynamic factor K_v, femgear's "
                                                                      "dynamics beside ISO 6336-1 method B"),
                                              out / "dynamics_K_v.png")
    return kv


def run_runup(case, args: argparse.Namespace, out: Path) -> int:
    """``--runup``: the ramp, its order tracking and the stepped steady state at the blocks' speeds."""
    from femgear.edge.cli.common import emit_json
    from femgear.edge.io.nvh import runup_summary, write_runup
    from femgear.system.dynamics.family import SpeedFamily
    from femgear.system.dynamics.harmonic_sweep import harmonic_sweep
    from femgear.system.dynamics.runup import order_track, simulate_runup

    ramp = runup_ramp(args.runup)
    family = SpeedFamily(case, args.level, stiffness=args.stiffness)
    est = (ramp.duration + ramp.settle_cycles / family.at(ramp.rpm0).mesh_frequency) * 5.0   # ~5 s per second run
    progress = _progress("run-up", 100, est)
    run = simulate_runup(family, ramp, progress=lambda f: progress(round(100 * f)))
    maps = {key: order_track(run, sig, revolutions=args.revolutions)
            for key, sig in (("mesh_force", run.mesh_force), ("dte", run.dte), ("bearing_force", run.bearing_force))}
    steady = harmonic_sweep(case, maps["mesh_force"].speed, level=args.level, stiffness=args.stiffness)
    cuts = steady.mesh_force[:, 0, :maps["mesh_force"].mesh_orders.size]
    model = family.base
    label = f"{case.name} ({model.level}, {model.stiffness.label} stiffness)"
    files = write_runup(run, maps, cuts, out, plots=not args.no_plots, name=label)
    if args.json:
        emit_json({**runup_summary(run, maps, cuts), "files": {k: str(v) for k, v in files.items()}})
        return 0
    m = maps["mesh_force"]
    print(f"run-up {ramp.rpm0:g} → {ramp.rpm1:g} rpm in {ramp.duration:g} s: {run.steps} RK4 steps of "
          f"{run.dt:.3g} s, {run.seconds:.1f} s")
    print(f"{'rpm':>8s}  mesh force L, mesh orders 1..{m.mesh_orders.size} [N] (run-up | steady state)")
    for i, r in enumerate(m.speed):
        print(f"{r:8.1f}  " + " ".join(f"{x:8.4g}" for x in m.cuts[i, :, 0]) + "  | "
              + " ".join(f"{x:8.4g}" for x in cuts[i]))
    for name, path in files.items():
        print(f"{name}: {path}")
    return 0


def run_kahraman_singh(args: argparse.Namespace, out: Path) -> int:
    """``--kahraman-singh``: the swept time integration up and down and the harmonic-balance continuation."""
    import numpy as np

    from femgear.edge.cli.common import emit_json
    from femgear.system.dynamics.sdof import kahraman_singh_sweep
    from femgear.system.dynamics.sdof_hb import kahraman_singh_hb

    w = np.linspace(0.6, 1.3, 36)
    up, down = kahraman_singh_sweep(w, direction="up"), kahraman_singh_sweep(w, direction="down")
    hb = kahraman_singh_hb(float(w[0]), float(w[-1]), at=w)
    files = {}
    if not args.no_plots:
        from femgear.edge.io.figures import save_figure
        from femgear.edge.plot.dynamics import plot_branches
        from femgear.edge.plot.nvh import plot_ks_continuation

        files["branches"] = save_figure(plot_branches(up, down), out / "kahraman_singh.png")
        files["continuation"] = save_figure(plot_ks_continuation(up, down, hb), out / "kahraman_singh_hb.png")
    a_down, loss_down = down.amplitude[::-1], down.contact_loss[::-1]
    if args.json:
        emit_json({"frequency": up.frequency, "amplitude_up": up.amplitude, "amplitude_down": a_down,
                   "contact_loss_up": up.contact_loss, "contact_loss_down": loss_down,
                   "hb_frequency": hb.frequency, "hb_amplitude": hb.amplitude, "hb_stable": hb.stable,
                   "hb_folds": list(hb.folds), "hb_stable_at_frequency": hb.stable_at,
                   "files": {k: str(v) for k, v in files.items()}})
        return 0
    print("Kahraman-Singh oscillator, ζ = 0.05, F_m = 0.1, F_a = 0.02 (lengths over the backlash b)")
    print(f"{'Ω':>6s} {'amp up':>8s} {'amp down':>9s} {'loss up':>8s} {'loss down':>9s} {'HB stable':>17s}")
    for i, om in enumerate(up.frequency):
        stable = " ".join(f"{x:.4f}" for x in hb.stable_at[i] if np.isfinite(x))
        print(f"{om:6.3f} {up.amplitude[i]:8.4f} {a_down[i]:9.4f} {up.contact_loss[i]:8.2f} {loss_down[i]:9.2f} "
              f"{stable:>17s}")
    print("harmonic-balance folds (jumps of a slow sweep) at Ω = " + ", ".join(f"{f:.4f}" for f in hb.folds))
    for name, path in files.items():
        print(f"{name}: {path}")
    return 0
