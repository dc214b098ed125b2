"""The contact-line integral of the mesh stiffness against a midpoint sum over face slices, on every zoo pair.

    python studies/body/stiffness_slices.py [--slices 100,1000] [--phases 2000]

The ``pem`` level's tooth-pair stiffness per width k'(u) of each pair (the baseline and ``studies/zoo/*.toml``) is
turned into the left helix's table k(φ) two ways, at ``--phases`` phases of one mesh period:

- femgear's :func:`femgear.physics.stiffness.tvms.helix_stiffness`: every contact line's k'(u) integrated exactly
  over its part on the path;
- the midpoint sum over N slices of width Δb = b/N that femgear used before (each slice a spur pair at its
  centre ζ_j = (j + ½)Δb), for each N of ``--slices``.

Per pair and method: the mean, the ripple (peak-to-peak over mean) and the largest step between neighbouring
phases over the mean (a continuous table moves by at most its slope × the phase step; the slice sum jumps by a
slice's k'(u_A) Δb or k'(u_E) Δb whenever a slice enters or leaves).  Prints a table and one JSON line (also
written to ``out/stiffness_slices.json``).
"""

from __future__ import annotations

import argparse
import json
import math
from pathlib import Path

import numpy as np

from femgear.case import build_case
from femgear.physics.geometry.gear import GearPair
from femgear.physics.stiffness.pem import pair_stiffness_per_width
from femgear.physics.stiffness.tvms import helix_stiffness, path_samples, tabulated
from femgear.scene import load_scene

ROOT = Path(__file__).resolve().parents[2]


def slice_sum(pair: GearPair, u: np.ndarray, k: np.ndarray, phases: np.ndarray, n: int) -> np.ndarray:
    """The midpoint sum over ``n`` face slices of k'(u) (the method replaced by the contact-line integral)."""
    spline = tabulated(pair, u, k)
    tb = math.tan(pair.beta_b)
    span = pair.b * tb
    zeta = (np.arange(n) + 0.5) * pair.b / n
    lines = np.arange(-1, int(math.ceil((pair.g_alpha + span) / pair.p_bt)) + 3)
    pos = (pair.u_start - span + (phases % 1.0)[:, None, None] * pair.p_bt + lines[None, :, None] * pair.p_bt
           + zeta[None, None, :] * tb)
    inside = (pos >= pair.u_start) & (pos <= pair.u_end)
    return np.where(inside, spline(pos), 0.0).sum(axis=(1, 2)) * (pair.b / n) / math.cos(pair.beta_b) ** 2


def figures(k: np.ndarray) -> dict:
    mean = float(np.mean(k))
    return {"mean": mean, "ripple": float(np.ptp(k) / mean),
            "max_step": float(np.max(np.abs(np.diff(np.append(k, k[0])))) / mean)}


def setup(argv: list[str] | None = None) -> argparse.Namespace:
    """The command line ``argv`` parsed: the slice counts and the phases per mesh period."""
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--slices", default="100,1000")
    ap.add_argument("--phases", type=int, default=2000)
    return ap.parse_args(argv)


def run(args: argparse.Namespace) -> dict:
    """Per helical pair: ε_β and the figures of the integral and of each slice count."""
    slices = [int(n) for n in args.slices.split(",")]
    phases = np.arange(args.phases) / args.phases
    out = {}
    for path in [ROOT / "studies" / "paper_baseline.toml", *sorted((ROOT / "studies" / "zoo").glob("*.toml"))]:
        case = build_case(load_scene(path), warn=False)
        pair, m = case.pair, case.material
        if pair.beta_b == 0:
            continue                                        # spur: one position per line, both methods agree
        u = path_samples(pair)
        k = pair_stiffness_per_width(pair, u, m.youngs_modulus, m.poisson_ratio, case.bore_radii, "strain")
        row = {"eps_beta": pair.eps_beta, "integral": figures(helix_stiffness(pair, u, k, phases))}
        row.update({f"slices_{n}": figures(slice_sum(pair, u, k, phases, n)) for n in slices})
        out[path.stem] = row
    return out


def main(argv: list[str] | None = None) -> int:
    args = setup(argv)
    out = run(args)
    methods = ["integral"] + [f"slices_{n}" for n in args.slices.split(",")]
    print(f"{'pair':16} {'ε_β':>5}  " + "  ".join(f"{m:>30}" for m in methods))
    print(f"{'':16} {'':>5}  " + "  ".join(f"{'mean [N/m]   ripple   max step':>30}" for _ in methods))
    for name, row in out.items():
        cells = [f"{row[m]['mean']:.5e} {100 * row[m]['ripple']:7.3f}% {100 * row[m]['max_step']:7.3f}%" for m in methods]
        print(f"{name:16} {row['eps_beta']:5.2f}  " + "  ".join(f"{c:>30}" for c in cells))
    (ROOT / "out").mkdir(exist_ok=True)
    text = json.dumps({"phases": args.phases, "pairs": out})
    (ROOT / "out" / "stiffness_slices.json").write_text(text)
    print(text)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
