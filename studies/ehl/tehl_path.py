"""Thermal EHL along the baseline path of contact: the seed paper's Fig. 16 analogue.

    python studies/ehl/tehl_path.py [--n 21] [--level 5] [--vtk 0,pitch,-1]

At ``n`` positions of the path A→E of ``studies/paper_baseline.toml`` (static load
share per unit length, radii, entrainment speeds and SRR from
:func:`femgear.physics.contact.path.contact_along_path`) it solves the line-contact TEHL
(:func:`femgear.physics.tehl.solve_tehl_line`, oil at the ambient temperature) and writes to
``out/tehl_path/``: ``tehl_path.png`` (central film, maximum pressure, maximum film
temperature rise and μ along the path, with the ``formula`` level's μ for comparison),
``tehl_path.json`` (all figures) and VTK files of the film temperature at the chosen
positions (indices into the path; ``pitch`` = the pitch point).  Prints a table, the
position of the μ minimum against the pitch point and the maximum temperature rise
beside the paper's ≈ 35 K.
"""

from __future__ import annotations

import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import argparse
import json
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[2]


def setup(argv: list[str] | None = None) -> argparse.Namespace:
    """The command line ``argv`` parsed (defaults: 21 positions, level 5)."""
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, default=21)
    ap.add_argument("--level", type=int, default=5)
    ap.add_argument("--vtk", default="0,pitch,-1")
    ap.add_argument("--out", default=str(ROOT / "out" / "tehl_path"))
    return ap.parse_args(argv)


def run(args: argparse.Namespace) -> tuple:
    """TEHL at ``args.n`` positions of the baseline path and the formula level beside it: (path, formula, summary)."""
    from femgear.case import build_case
    from femgear.levels.contact import contact_pass
    from femgear.levels.lubrication import line_friction, tehl_setup
    from femgear.physics.tehl.path import tehl_along_path
    from femgear.scene import load_scene

    case = build_case(load_scene(ROOT / "studies" / "paper_baseline.toml"))
    T0 = case.operating.ambient_temperature
    contact = contact_pass(case, n=args.n)
    path = tehl_along_path(contact, tehl_setup(case), T0, level=args.level)
    formula = line_friction(case).along(contact, T0)
    s = path.s
    i_pitch = int(np.argmin(np.abs(s)))
    print(f"{'s [mm]':>8} {'SRR':>7} {'h_c [nm]':>9} {'p_max [GPa]':>11} {'dT [K]':>7} {'dT_s [K]':>8} "
          f"{'mu':>7} {'mu_P':>8} {'mu_formula':>10}")
    for i in range(s.size):
        print(f"{s[i]*1e3:8.2f} {path.srr[i]:7.3f} {path.hc[i]*1e9:9.1f} {path.pmax[i]/1e9:11.3f} "
              f"{path.dT_max[i]:7.1f} {path.dT_surface[i]:8.1f} {path.mu[i]:7.4f} {path.mu_poiseuille[i]:8.5f} "
              f"{formula.mu[i]:10.4f}")
    i_min = int(np.argmin(path.mu))
    summary = {"positions": int(s.size), "level": args.level, "seconds": path.seconds,
               "mu_min": float(path.mu.min()), "mu_min_at_s": float(s[i_min]), "pitch_s": float(s[i_pitch]),
               "mu_max": float(path.mu.max()), "mu_mean": float(path.mu.mean()),
               "max_temperature_rise": float(path.dT_max.max()), "max_surface_temperature_rise": float(path.dT_surface.max()),
               "paper_temperature_rise": 35.0}
    u_shaped = bool(np.all(np.diff(path.mu[: i_pitch + 1]) <= 1e-9) and np.all(np.diff(path.mu[i_pitch:]) >= -1e-9))
    summary["u_shaped"] = u_shaped
    print(f"μ minimum {summary['mu_min']:.4f} at s = {summary['mu_min_at_s']*1e3:.2f} mm (pitch at "
          f"{summary['pitch_s']*1e3:.2f} mm); U-shaped: {u_shaped}; μ max {summary['mu_max']:.4f}")
    print(f"max film temperature rise {summary['max_temperature_rise']:.1f} K, max surface (flash) "
          f"{summary['max_surface_temperature_rise']:.1f} K (paper ≈ 35 K); {path.seconds:.1f} s of TEHL solves")
    return path, formula, summary


def main(argv: list[str] | None = None) -> int:
    from femgear.edge.io.fields import write_tehl_vtu

    args = setup(argv)
    path, formula, summary = run(args)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    s = path.s
    i_pitch = int(np.argmin(np.abs(s)))
    for tok in filter(None, args.vtk.split(",")):
        i = i_pitch if tok == "pitch" else int(tok) % s.size
        f = write_tehl_vtu(out / f"thermal_{i:03d}.vtu", path.results[i])
        print("VTK", f)
    (out / "tehl_path.json").write_text(json.dumps({
        "summary": summary, "s": s.tolist(), "srr": path.srr.tolist(), "hc": path.hc.tolist(),
        "pmax": path.pmax.tolist(), "dT_max": path.dT_max.tolist(), "dT_surface": path.dT_surface.tolist(),
        "mu": path.mu.tolist(), "mu_poiseuille": path.mu_poiseuille.tolist(), "mu_formula": formula.mu.tolist()},
        indent=1))
    _plot(path, formula.mu, out / "tehl_path.png")
    print(json.dumps(summary))
    return 0


def _plot(path, mu_formula, file: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    s = path.s * 1e3
    fig, ax = plt.subplots(2, 2, figsize=(10, 7), sharex=True)
    ax[0, 0].plot(s, path.hc * 1e9, "o-")
    ax[0, 0].set_ylabel("central film h_c [nm]")
    ax[0, 1].plot(s, path.pmax / 1e9, "o-")
    ax[0, 1].set_ylabel("max pressure [GPa]")
    ax[1, 0].plot(s, path.dT_max, "o-", label="film (max)")
    ax[1, 0].plot(s, path.dT_surface, "s--", label="surface (flash)")
    ax[1, 0].axhline(35.0, color="k", lw=0.8, ls=":", label="paper ≈ 35 K")
    ax[1, 0].set_ylabel("temperature rise [K]")
    ax[1, 0].legend()
    ax[1, 1].plot(s, path.mu, "o-", label="TEHL (Couette)")
    ax[1, 1].plot(s, mu_formula, "--", label="formula level")
    ax[1, 1].set_ylabel("friction coefficient μ")
    ax[1, 1].legend()
    for a in ax[1]:
        a.set_xlabel("path coordinate s [mm] (0 = pitch point)")
    fig.suptitle("TEHL along the path of contact (paper baseline)")
    fig.tight_layout()
    fig.savefig(file, dpi=120)
    plt.close(fig)


if __name__ == "__main__":
    sys.exit(main())
