"""Point TEHL along the baseline path of the paper's pair with crowned flanks, against the paper's claims.

    python studies/ehl/tehl_point_path.py [--crowning 10e-6] [--level 1]

Scene: studies/paper_baseline.toml with ``modifications.crowning`` = 10 um on both members
(chosen before any run), ``physics.lubrication = "tehl-point"``; the lubrication level's
thermal point EHL (:mod:`femgear.physics.tehl.point_level`) at every position of the case's path
under the line load of the load sharing. Writes out/tehl_point_path.png (central and minimum
film, maximum pressure, maximum film temperature rise, mu against the position along the
path) and out/tehl_point_path.json, and prints the paper's claims (Wang et al. 2026, §5:
"the minimum film thickness and maximum pressure occur near the pitch point, with a
temperature rise of approximately 35 K"; "the friction coefficient exhibits a U-shaped
distribution along the meshing line") beside what the model gives.
"""

from __future__ import annotations

import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import argparse
import json
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
from tehl_point import crowned_scene

from femgear.case import build_case
from femgear.levels.contact import contact_pass
from femgear.levels.lubrication import crowning, tehl_point_solver
from femgear.physics.contact.crowning import crowned_contact


def along_path(scene, level: int) -> dict:
    case = build_case(scene)
    k = case.path
    cp = contact_pass(case)
    det: list = []
    solver = tehl_point_solver(case, level=level, details=det)
    mu, dT = solver(w=cp.line_load, R=k.R, ue=k.ue, srr=np.abs(k.srr), T=case.operating.ambient_temperature)
    geo = crowned_contact(case.pair, crowning(case))
    Rx, Ry = geo.radii(k.R)
    pitch = int(np.argmin(np.abs(k.srr)))
    return {"u_mm": (k.u - k.u[pitch]) * 1e3, "mu": mu, "dT": dT, "srr": k.srr, "load_N": geo.load(cp.line_load),
            "hc_um": np.array([r.hc for r in det]) * 1e6, "hmin_um": np.array([r.hmin for r in det]) * 1e6,
            "pmax_GPa": np.array([r.pmax for r in det]) / 1e9, "ratio": Rx / Ry, "pitch": pitch,
            "single": [float((u - k.u[pitch]) * 1e3) for u in cp.single_contact]}


def claims(d: dict) -> list[tuple[str, str]]:
    u, p = d["u_mm"], d["pitch"]
    i_h, i_p = int(np.argmin(d["hmin_um"])), int(np.argmax(d["pmax_GPa"]))
    mu = d["mu"]
    ends = 0.5 * (mu[0] + mu[-1])
    return [
        ("minimum film near the pitch point",
         f"h_min smallest at u = {u[i_h]:+.2f} mm from the pitch point ({d['hmin_um'][i_h]:.3f} um; "
         f"at the pitch point {d['hmin_um'][p]:.3f} um); path {u[0]:+.1f} .. {u[-1]:+.1f} mm"),
        ("maximum pressure near the pitch point",
         f"p_max largest at u = {u[i_p]:+.2f} mm ({d['pmax_GPa'][i_p]:.3f} GPa; pitch {d['pmax_GPa'][p]:.3f} GPa)"),
        ("U-shaped mu", f"mu {mu[p]:.4f} at the pitch point (SRR 0), {mu[0]:.4f} / {mu[-1]:.4f} at the ends "
                        f"(mean of the ends {ends:.4f}); V with a cusp at the pitch point"),
        ("temperature rise ~35 K", f"max film temperature rise {d['dT'].max():.1f} K "
                                   f"(at the pitch point {d['dT'][p]:.1f} K)"),
    ]


def plot(d: dict, path: Path, crowning: float, level: int) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    u = d["u_mm"]
    fig, ax = plt.subplots(2, 2, figsize=(10, 7), sharex=True)
    ax[0, 0].plot(u, d["hc_um"], "o-", ms=3, label="h_c")
    ax[0, 0].plot(u, d["hmin_um"], "s-", ms=3, label="h_min")
    ax[0, 0].set_ylabel("film [um]")
    ax[0, 0].set_title("paper: minimum film near the pitch point", fontsize=9)
    ax[0, 1].plot(u, d["pmax_GPa"], "o-", ms=3)
    ax[0, 1].set_ylabel("p_max [GPa]")
    ax[0, 1].set_title("paper: maximum pressure near the pitch point", fontsize=9)
    ax[1, 0].plot(u, d["dT"], "o-", ms=3, label="femgear")
    ax[1, 0].axhline(35.0, color="k", ls="--", label="paper ~35 K")
    ax[1, 0].set_ylabel("max film temperature rise [K]")
    ax[1, 0].legend(fontsize=8)
    ax[1, 1].plot(u, d["mu"], "o-", ms=3)
    ax[1, 1].set_ylabel("mu")
    ax[1, 1].set_title("paper: U-shaped along the path", fontsize=9)
    for a in ax.ravel():
        a.axvline(0.0, color="grey", lw=0.8)
        for s in d["single"]:
            if np.isfinite(s):
                a.axvline(s, color="grey", lw=0.5, ls=":")
        a.grid(alpha=0.3)
    for a in ax[1]:
        a.set_xlabel("position along the path from the pitch point [mm]")
    ax[0, 0].legend(fontsize=8)
    fig.suptitle(f"tehl-point along the paper's path, crowning {crowning * 1e6:g} um both members, "
                 f"grid level {level}", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def setup(argv: list[str] | None = None) -> argparse.Namespace:
    """The command line ``argv`` parsed (defaults: the documented study)."""
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--crowning", type=float, default=10e-6)
    ap.add_argument("--level", type=int, default=1)
    return ap.parse_args(argv)


def run(args: argparse.Namespace) -> tuple:
    """The point TEHL along the crowned baseline path; the data and the start time."""
    t0 = time.perf_counter()
    d = along_path(crowned_scene(args.crowning), args.level)
    return d, t0


def main(argv: list[str] | None = None) -> int:
    args = setup(argv)
    d, t0 = run(args)
    sec = time.perf_counter() - t0
    out = Path("out")
    out.mkdir(exist_ok=True)
    plot(d, out / "tehl_point_path.png", args.crowning, args.level)
    print(f"{d['u_mm'].size} positions in {sec:.1f} s; lambda = R_x/R_y {d['ratio'].min():.4f} .. "
          f"{d['ratio'].max():.4f}; load per contact {d['load_N'].min():.0f} .. {d['load_N'].max():.0f} N")
    for claim, got in claims(d):
        print(f"  {claim:40s} | {got}")
    (out / "tehl_point_path.json").write_text(json.dumps({k: (v.tolist() if isinstance(v, np.ndarray) else v)
                                                          for k, v in d.items()}))
    print(json.dumps({"study": "tehl_point_path", "positions": int(d["u_mm"].size), "seconds": round(sec, 1),
                      "png": "out/tehl_point_path.png"}))
    return 0


if __name__ == "__main__":
    sys.exit(main())
