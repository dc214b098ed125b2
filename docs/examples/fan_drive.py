"""The "Your own gear" walkthrough from Python: load the fan drive, run it, print key figures.

    python docs/examples/fan_drive.py [--coarse]

``--coarse``: 20 simulated mesh periods (5 transient), 11 path points (what the test runs).
The files (results.json, figures, ParaView) are what ``femgear run docs/examples/fan_drive.toml`` writes.
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np

from femgear.case import build_case
from femgear.pipeline import run_case
from femgear.scene import load_scene

SCENE = Path(__file__).with_name("fan_drive.toml")
COARSE = ["numerics.dynamics_cycles=20.0", "numerics.transient_cycles=5.0", "numerics.path_points=11",
          "stiffness.n_positions=40"]


def run(coarse: bool = False):
    """The RunResult of the fan drive."""
    scene = load_scene(SCENE, COARSE if coarse else [])
    return run_case(build_case(scene))


def main(argv: list[str] | None = None) -> dict[str, float]:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--coarse", action="store_true", help="coarse numerics (seconds)")
    args = p.parse_args(argv)
    result = run(args.coarse)
    mu = result.tribology.friction_coefficient
    figures = {
        "mesh stiffness, mean [N/m]": result.stiffness.mean,
        "mesh stiffness ripple [-]": result.stiffness.ripple(),
        "friction coefficient, max along the path [-]": float(np.max(mu)),
        "contact temperature rise, max [K]": float(np.max(result.tribology.temperature_rise)),
        "coupling passes [-]": float(len(result.coupled.history.iteration)),
    }
    for name, value in figures.items():
        print(f"{name:48s} {value:.4g}")
    return figures


if __name__ == "__main__":
    main()
