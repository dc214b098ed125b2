"""Thermal flank deformation vs temperature rise, pinion and gear (paper Fig. 14 analogue).

    python studies/body/tooth_thermal.py [SCENE] [--coarse]

For flank temperature rises ΔT_f = 0…60 K (shaft at ``thermal.shaft_temperature_rise``)
computes ζ_T along the normal line of action at the pitch point and its range over
the path of contact, by the ``analytic`` level (paper eqs. 3–5, consistent form) and
the ``fe`` level (conduction + plane-stress thermo-elasticity on a 3-tooth section).
Writes ``out/tooth_thermal.png`` and ``out/tooth_thermal_pinion.vtu`` (the hottest
case, fields for ParaView); prints a table and one JSON line.
"""

from __future__ import annotations

import json
import sys
import time
from pathlib import Path

import numpy as np

from femgear.case.pair import pair_from_scene
from femgear.edge.io.figures import save_figure
from femgear.physics.body.thermal import analytic_radial_displacement, flank_displacement, gear_thermo_elastic
from femgear.physics.stiffness.pem import contact_geometry
from femgear.scene import load_scene

ROOT = Path(__file__).resolve().parents[2]


def setup(scene_path: str | Path = ROOT / "studies" / "paper_baseline.toml"):
    return load_scene(scene_path)


def run(scene, rises=(0.0, 10.0, 20.0, 30.0, 40.0, 50.0, 60.0), coarse: bool = False) -> dict:
    pair = pair_from_scene(scene)
    mat = scene.material
    dTs = scene.thermal.shaft_temperature_rise
    u = np.linspace(pair.u_start, pair.u_end, 21)
    cb = np.cos(pair.beta_b)
    out = {"rises": list(rises), "u": u, "members": {}}
    h = pair.m_n / (3 if coarse else 5)
    last = None
    for member, name in ((1, "pinion"), (2, "gear")):
        bore = scene.pinion.bore_radius if member == 1 else scene.gear.bore_radius
        r, alpha, _ = contact_geometry(pair, member, u)
        rows = {"analytic": [], "fe": [], "fe_seconds": []}
        for dT in rises:
            ua = analytic_radial_displacement(pair, member, r, dT, dTs, mat.thermal_expansion, mat.poisson_ratio, bore)
            rows["analytic"].append(ua * np.sin(alpha) * cb)
            t = time.perf_counter()
            res = gear_thermo_elastic(pair, member, dT, dTs, mat.thermal_expansion, mat.youngs_modulus,
                                      mat.poisson_ratio, mat.conductivity, bore, h)
            rows["fe"].append(flank_displacement(res, pair, member, r) * cb)
            rows["fe_seconds"].append(time.perf_counter() - t)
            if member == 1:
                last = res
        out["members"][name] = {k: np.array(v) for k, v in rows.items()}
    out["pair"], out["last_pinion"] = pair, last
    return out


def plot(res: dict, path: str | Path = ROOT / "out" / "tooth_thermal.png") -> Path:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    pair, u = res["pair"], res["u"]
    ip = int(np.argmin(np.abs(u - pair.u_pitch)))
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for (name, m), c in zip(res["members"].items(), ("C0", "C3")):
        axes[0].plot(res["rises"], m["analytic"][:, ip] * 1e6, color=c, ls="--", marker="o", label=f"{name}, analytic")
        axes[0].plot(res["rises"], m["fe"][:, ip] * 1e6, color=c, marker="s", label=f"{name}, FE")
        s = (u - pair.u_pitch) * 1e3
        axes[1].plot(s, m["analytic"][-1] * 1e6, color=c, ls="--", label=f"{name}, analytic")
        axes[1].plot(s, m["fe"][-1] * 1e6, color=c, label=f"{name}, FE")
    axes[0].set_xlabel("flank temperature rise ΔT_f [K]")
    axes[0].set_ylabel("ζ_T at the pitch point [µm]")
    axes[1].set_xlabel("position from pitch point [mm]")
    axes[1].set_ylabel(f"ζ_T at ΔT_f = {res['rises'][-1]:g} K [µm]")
    for ax in axes:
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle("Thermal flank deviation along the normal line of action")
    return save_figure(fig, path)


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    from femgear.edge.io.fields import write_body_vtu
    from femgear.physics.body.fields import section_fields

    args = [a for a in argv if not a.startswith("--")]
    scene = setup(*args[:1])
    res = run(scene, coarse="--coarse" in argv)
    png = plot(res)
    mat = scene.material
    vtu = write_body_vtu(ROOT / "out" / "tooth_thermal_pinion.vtu",
                         section_fields(res["last_pinion"], 1, mat.youngs_modulus, mat.poisson_ratio,
                                        mat.thermal_expansion))
    pair, u = res["pair"], res["u"]
    ip = int(np.argmin(np.abs(u - pair.u_pitch)))
    print(f"{'member':>7} {'ΔT_f K':>7} {'analytic µm':>12} {'FE µm':>8} {'FE/an−1':>8} {'FE s':>6}")
    js = {"study": "tooth_thermal", "rises_K": res["rises"], "png": str(png), "vtu": str(vtu)}
    for name, m in res["members"].items():
        for i, dT in enumerate(res["rises"]):
            a, f = m["analytic"][i, ip], m["fe"][i, ip]
            rel = (f / a - 1) if a else 0.0
            print(f"{name:>7} {dT:>7.0f} {a * 1e6:>12.3f} {f * 1e6:>8.3f} {100 * rel:>7.2f}% {m['fe_seconds'][i]:>6.2f}")
        js[name] = {"pitch_analytic_um": (m["analytic"][:, ip] * 1e6).tolist(),
                    "pitch_fe_um": (m["fe"][:, ip] * 1e6).tolist(), "fe_seconds": m["fe_seconds"].tolist()}
    print(json.dumps(js))
    return 0


if __name__ == "__main__":
    sys.exit(main())
