"""``femgear dynamics SCENE --campbell RPM0:RPM1[:N]``: the Campbell diagram of a scene's gear-rotor model.

Writes ``campbell.png`` and ``campbell.json`` (:mod:`femgear.edge.io.campbell`) into the dynamics output folder;
``--json`` prints the summary as the last stdout line.  ``--orders`` / ``--shaft-orders`` choose the mesh and
shaft orders drawn and searched for critical speeds.  Progress goes to stderr on long sweeps.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

from femgear.errors import ArgumentError

#: speeds of a Campbell sweep when N is not given, and the most it takes
DEFAULT_SPEEDS, MAX_SPEEDS = 61, 20000


#: the order lists of :func:`add_campbell_arguments` and their defaults
ORDER_ARGUMENTS = {"--orders": ("orders", "1,2,3,4"), "--shaft-orders": ("shaft_orders", "1,2")}


def add_campbell_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("--campbell", metavar="RPM0:RPM1[:N]", default=None,
                   help="instead of one run: the Campbell diagram, natural frequencies (with the gear bodies' "
                        "gyroscopic moments, tracked by MAC) against the driver speed from RPM0 ≥ 0 to RPM1 at N "
                        f"speeds (default {DEFAULT_SPEEDS}), with the mesh and shaft orders and the critical speeds "
                        "(writes campbell.png, campbell.json)")
    p.add_argument("--orders", default=ORDER_ARGUMENTS["--orders"][1], metavar="K,K,...",
                   help="mesh orders of --campbell (positive; default 1,2,3,4)")
    p.add_argument("--shaft-orders", default=ORDER_ARGUMENTS["--shaft-orders"][1], metavar="J,J,...",
                   help="shaft orders of --campbell, of pinion and gear (positive; default 1,2)")


def campbell_speeds(text: str):
    """``RPM0:RPM1[:N]`` as N ascending driver speeds [rpm], 0 ≤ RPM0 < RPM1; :class:`ArgumentError` naming
    ``--campbell`` otherwise."""
    import numpy as np

    parts = text.split(":")
    try:
        if len(parts) not in (2, 3):
            raise ValueError
        lo, hi = float(parts[0]), float(parts[1])
        count = int(parts[2]) if len(parts) == 3 else DEFAULT_SPEEDS
    except ValueError:
        raise ArgumentError("--campbell", f"expected RPM0:RPM1 or RPM0:RPM1:N, got {text!r}") from None
    if not (np.isfinite(lo) and np.isfinite(hi)):
        raise ArgumentError("--campbell", f"speeds must be finite numbers, got {text!r}")
    if hi <= 0:
        raise ArgumentError("--campbell", f"the sweep must reach above 0 rpm (got RPM1 = {hi:g})")
    if lo < 0:
        raise ArgumentError("--campbell", f"RPM0 must be ≥ 0 (got {lo:g})")
    if hi <= lo:
        raise ArgumentError("--campbell", f"RPM1 must exceed RPM0 (got {lo:g}:{hi:g})")
    if not 2 <= count <= MAX_SPEEDS:
        raise ArgumentError("--campbell", f"N must be 2…{MAX_SPEEDS} (got {count})")
    return np.linspace(lo, hi, count)


def order_list(argument: str, text: str) -> tuple[float, ...]:
    """A comma-separated list of positive orders; :class:`ArgumentError` naming ``argument`` otherwise."""
    try:
        values = tuple(float(x) for x in text.split(",") if x.strip())
    except ValueError:
        raise ArgumentError(argument, f"expected positive numbers separated by commas, got {text!r}") from None
    bad = [v for v in values if not (v > 0 and v < 1e6)]
    if not values or bad:
        raise ArgumentError(argument, f"orders must be positive (got {text!r})")
    return tuple(int(v) if v == int(v) else v for v in values)


def check_campbell_arguments(args: argparse.Namespace) -> None:
    """Every argument of a Campbell run checked before anything is loaded or computed; without ``--campbell`` an
    order list given is refused (it would be ignored: the sweep and run-up report their own orders)."""
    if not args.campbell:
        for flag, (name, default) in ORDER_ARGUMENTS.items():
            if getattr(args, name) != default:
                order_list(flag, getattr(args, name))
                raise ArgumentError(flag, "applies to --campbell only (the --sweep and --runup outputs hold every "
                                          "mesh order they resolve)")
        return
    if args.sweep or args.kahraman_singh:
        raise ArgumentError("--campbell", "give one of --campbell, --sweep, --kahraman-singh")
    campbell_speeds(args.campbell)
    order_list("--orders", args.orders)
    order_list("--shaft-orders", args.shaft_orders)


class _Progress:
    """``campbell: i/n speeds`` on stderr, at most every 2 s, once the sweep has run 2 s."""

    def __init__(self):
        self.start = self.last = time.perf_counter()

    def __call__(self, i: int, n: int) -> None:
        now = time.perf_counter()
        if now - self.last >= 2.0 or (i == n and now - self.start >= 2.0):
            print(f"campbell: {i}/{n} speeds, {now - self.start:.0f} s", file=sys.stderr, flush=True)
            self.last = now


def run_campbell(case, args: argparse.Namespace, out: Path) -> int:
    from femgear.edge.cli.common import emit_json
    from femgear.edge.io.campbell import campbell_summary, write_campbell
    from femgear.system.dynamics import build_model
    from femgear.system.dynamics.campbell import campbell

    model = build_model(case, args.level, stiffness=args.stiffness)
    d = campbell(model, campbell_speeds(args.campbell), driver=case.operating.driver,
                 mesh_orders=order_list("--orders", args.orders),
                 shaft_orders=order_list("--shaft-orders", args.shaft_orders), progress=_Progress())
    files = write_campbell(d, out, plots=not args.no_plots,
                           name=f"{case.name} ({model.level}, {model.stiffness.label} stiffness)")
    if args.json:
        emit_json({**campbell_summary(d), "files": {k: str(v) for k, v in files.items()}})
        return 0
    print(f"Campbell diagram, {d.speed_rpm[0]:g}–{d.speed_rpm[-1]:g} rpm ({case.operating.driver} speed), "
          f"{d.frequency.shape[1]} modes ({model.level})")
    print(f"{'mode':>4s} {'f(0) [Hz]':>10s} {'f(end) [Hz]':>11s} {'mesh L':>7s} {'mesh R':>7s} {'bearings':>8s}")
    for m in range(d.frequency.shape[1]):
        e = {k: v[0, m] for k, v in d.energy.items()}
        bearings = sum(v for k, v in e.items() if k.startswith("bearing"))
        print(f"{m:4d} {d.frequency[0, m]:10.1f} {d.frequency[-1, m]:11.1f} {e['mesh_L']:7.3f} {e['mesh_R']:7.3f} "
              f"{bearings:8.3f}")
    for c in d.critical:
        print(f"critical speed {c['speed_rpm']:.1f} rpm: {c['order']} meets mode {c['mode']} at "
              f"{c['frequency_hz']:.1f} Hz ({100 * (c['energy']['mesh_L'] + c['energy']['mesh_R']):.0f} % mesh "
              "strain energy)")
    for name, path in files.items():
        print(f"{name}: {path}")
    return 0
