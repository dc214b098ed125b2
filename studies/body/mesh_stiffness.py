"""Time-varying mesh stiffness of the baseline pair: every level on one plot, with its cost.

    python studies/body/mesh_stiffness.py [SCENE] [--coarse]

Plots ``out/mesh_stiffness.png``: left helix, right helix and their sum over two mesh
periods for ISO 6336, PEM (sliced) and FE (sliced, FE tooth compliance), and the
tooth-pair stiffness per unit width along the path, PEM vs FE, with their difference.
Prints a table (mean, ripple, cost per level; PEM vs FE per position) and one JSON line.
``--coarse`` is the CI setting (fewer FE positions, coarser mesh).
"""

from __future__ import annotations

import json
import math
import sys
from pathlib import Path

import numpy as np

from femgear.case import build_case
from femgear.case.pair import pair_from_scene
from femgear.edge.io.figures import save_figure
from femgear.levels import stiffness as stiffness_levels
from femgear.physics.stiffness import iso6336_stiffness
from femgear.scene import load_scene

ROOT = Path(__file__).resolve().parents[2]


def setup(scene_path: str | Path = ROOT / "studies" / "paper_baseline.toml"):
    return load_scene(scene_path)


def run(scene, coarse: bool = False) -> dict:
    pair = pair_from_scene(scene)
    fe_opts = {"n_fe": 5, "h": pair.m_n / 2.5, "refine_ratio": 0.5} if coarse else \
        {"n_fe": 11, "h": pair.m_n / 2.5, "refine_ratio": 0.3}
    levels = {
        "iso6336": stiffness_levels.of(build_case(scene), level="iso6336"),
        "pem": stiffness_levels.of(build_case(scene), level="pem"),
        "fe": stiffness_levels.of(build_case(scene), level="fe", fe_options=fe_opts),
    }
    fe = {"u_fe": levels["fe"].fe.u, "k_fe": levels["fe"].fe.k}
    from femgear.physics.stiffness.pem import pair_stiffness_per_width

    k_pem = pair_stiffness_per_width(pair, fe["u_fe"], scene.material.youngs_modulus, scene.material.poisson_ratio)
    single = (fe["u_fe"] >= pair.u_end - pair.p_bt - 1e-12) & (fe["u_fe"] <= pair.u_start + pair.p_bt + 1e-12)
    iso = iso6336_stiffness(pair, youngs_modulus=scene.material.youngs_modulus)
    half = stiffness_levels.of(build_case(scene.model_copy(update={"pair": scene.pair.model_copy(update={"stagger": 0.5})})),
                                     level="pem")
    return {"pair": pair, "levels": levels, "pem_half_stagger": half, "u_fe": fe["u_fe"], "k_fe": fe["k_fe"], "k_pem": k_pem,
            "single": single, "iso": iso}


def plot(res: dict, path: str | Path = ROOT / "out" / "mesh_stiffness.png") -> Path:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    pair = res["pair"]
    fig, axes = plt.subplots(2, 2, figsize=(11, 7))
    ph = np.linspace(0, 2, 401)
    styles = {"iso6336": ("k", "--"), "pem": ("C0", "-"), "fe": ("C3", "-")}
    for ax, helix in zip(axes.flat[:3], ("left", "right", "total")):
        for name, ms in res["levels"].items():
            c, ls = styles[name]
            ax.plot(ph, ms.at(ph, helix) / 1e6, color=c, ls=ls, label=f"{name} ({ms.seconds:.2g} s)")
        ax.set_title(f"{helix} helix" if helix != "total" else f"sum (stagger {res['levels']['pem'].stagger:g})")
        ax.set_xlabel("mesh phase [base pitches]")
        ax.set_ylabel("k along normal LoA [N/µm]")
        ax.grid(alpha=0.3)
    if "pem_half_stagger" in res:
        axes[1, 0].plot(ph, res["pem_half_stagger"].at(ph, "total") / 1e6, color="C0", ls=":", label="pem, stagger ½")
        axes[1, 0].legend(fontsize=8)
    axes[0, 0].legend(fontsize=8)
    ax = axes[1, 1]
    s = (res["u_fe"] - pair.u_pitch) * 1e3
    ax.plot(s, res["k_pem"] / 1e9, "C0o-", label="PEM")
    ax.plot(s, res["k_fe"] / 1e9, "C3s-", label="FE (2-D, P2)")
    ax2 = ax.twinx()
    ax2.plot(s, 100 * (res["k_pem"] / res["k_fe"] - 1), "C2:", label="PEM/FE − 1")
    ax2.set_ylabel("PEM vs FE [%]", color="C2")
    lo, hi = (pair.u_end - pair.p_bt - pair.u_pitch) * 1e3, (pair.u_start + pair.p_bt - pair.u_pitch) * 1e3
    ax.axvspan(lo, hi, color="0.9", label="single-pair zone")
    ax.set_xlabel("position from pitch point [mm]")
    ax.set_ylabel("tooth-pair k' per width [N/(mm µm)]")
    ax.legend(fontsize=8, loc="lower center")
    ax.grid(alpha=0.3)
    fig.suptitle(f"Mesh stiffness, z = {pair.z1}/{pair.z2}, β = {math.degrees(pair.beta):.0f}°, b = {pair.b * 1e3:g} mm per helix")
    return save_figure(fig, path)


def summary(res: dict) -> dict:
    pair, iso = res["pair"], res["iso"]
    rows = []
    for name, ms in res["levels"].items():
        rows.append({"level": name, "seconds": ms.seconds, "mean_left_N_per_m": ms.mean_left,
                     "mean_total_N_per_m": ms.mean, "ripple_left": ms.ripple("left"), "ripple_total": ms.ripple("total")})
    dev = res["k_pem"] / res["k_fe"] - 1
    k_iso_t = iso.k("c_gamma_alpha")
    pem_t = res["levels"]["pem"].mean_left * math.cos(pair.beta_b) ** 2
    return {"study": "mesh_stiffness", "rows": rows,
            "pem_vs_fe_per_position": dev.tolist(), "u_mm_from_pitch": ((res["u_fe"] - pair.u_pitch) * 1e3).tolist(),
            "pem_vs_fe_single_pair_max_abs": float(np.max(np.abs(dev[res["single"]]))) if res["single"].any() else None,
            "iso_c_gamma_alpha": iso.c_gamma_alpha, "iso_c_prime": iso.c_prime,
            "pem_mean_transverse_over_iso_c_gamma_alpha": pem_t / k_iso_t}


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    args = [a for a in argv if not a.startswith("--")]
    res = run(setup(*args[:1]), coarse="--coarse" in argv)
    out = plot(res)
    s = summary(res)
    print(f"{'level':>8} {'seconds':>8} {'mean L [N/m]':>13} {'mean L+R':>11} {'ripple L':>9} {'ripple L+R':>10}")
    for r in s["rows"]:
        print(f"{r['level']:>8} {r['seconds']:>8.3f} {r['mean_left_N_per_m']:>13.4e} {r['mean_total_N_per_m']:>11.4e} "
              f"{r['ripple_left']:>9.4f} {r['ripple_total']:>10.4f}")
    print("PEM vs FE per position (s from pitch [mm]: PEM/FE − 1):")
    for x, d in zip(s["u_mm_from_pitch"], s["pem_vs_fe_per_position"]):
        print(f"  {x:+7.3f}: {100 * d:+6.2f} %")
    print(f"PEM mean (transverse) / ISO c_γα b = {s['pem_mean_transverse_over_iso_c_gamma_alpha']:.3f};  plot: {out}")
    print(json.dumps(s))
    return 0


if __name__ == "__main__":
    sys.exit(main())
