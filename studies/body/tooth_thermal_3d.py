"""Thermal flank deviation in 3-D (``fe3d``, the member body) against the 2-D section (``fe``) and ``analytic``.

    PYTHONPATH=$PWD python studies/body/tooth_thermal_3d.py [SCENE] [--levels 0,1,2] [--groove 0.012]

Unit responses ζ_n per kelvin along the normal line of action (ΔT_f = 1 K with the shaft at 0, and
ΔT_s = 1 K with the flank at 0) at the path positions of the 2-D level, for pinion and gear:
``analytic`` (free hollow disc), ``fe`` (3-tooth plane-stress section, P2) and, as a bracket for the
3-D constraint, the same section in plane strain; then the 3-D body (:mod:`femgear.physics.ltca.thermal`)
at mid-face of the left helix, near its outer end (ζ = 0), at the groove/apex end (ζ = b) and its
face mean (what ``physics.thermal = "fe3d"`` passes to the coupling loop), with the difference to
the 2-D ``fe`` in %.  Cost (cold seconds, DOF, peak RSS) and the mesh convergence over the body
levels; ``--groove`` adds a body with a groove of that width (the baseline has none).  Writes
``out/tooth_thermal_3d.png`` and prints one JSON line.
"""

from __future__ import annotations

import argparse
import json
import math
import resource
import sys
import time
from pathlib import Path

import numpy as np

from femgear.case.pair import pair_from_scene
from femgear.edge.io.figures import save_figure
from femgear.physics.body.thermal import (
    analytic_flank_deviation,
    fe_flank_deviation,
    flank_displacement,
    solve_temperature,
    thermo_elastic,
)
from femgear.physics.ltca.thermal import thermal_units_3d
from femgear.physics.mesh.section import gear_section
from femgear.physics.stiffness.pem import contact_geometry
from femgear.scene import load_scene

ROOT = Path(__file__).resolve().parents[2]
UNITS = (("flank", 1.0, 0.0), ("shaft", 0.0, 1.0))


def plane_strain_section(pair, member, mat, r, flank, shaft, bore):
    """The 2-D ``fe`` section in plane strain instead of plane stress (a bracket, not a level)."""
    rf = pair.rf1 if member == 1 else pair.rf2
    rbore = bore if bore > 0 else 0.5 * rf
    mesh = gear_section(pair, member, pair.m_n / 5, n_teeth=3, bore_radius=rbore)
    temp = solve_temperature(mesh, mat.conductivity, {"flank": flank, "fillet": flank, "tip": flank, "bore": shaft})
    res = thermo_elastic(mesh, temp, mat.youngs_modulus, mat.poisson_ratio, mat.thermal_expansion, "rollers",
                         plane="strain")
    return flank_displacement(res, pair, member, r) * math.cos(pair.beta_b)


def two_d(scene, pair, member, u):
    mat = scene.material
    bore = scene.pinion.bore_radius if member == 1 else scene.gear.bore_radius
    r, _, rho = contact_geometry(pair, member, u)
    out = {"rho": rho}
    for name, f, s in UNITS:
        t = time.perf_counter()
        out[f"fe_{name}"] = fe_flank_deviation(pair, member, u, f, s, mat.thermal_expansion, mat.youngs_modulus,
                                               mat.poisson_ratio, mat.conductivity, bore)
        out["fe_seconds"] = time.perf_counter() - t
        out[f"analytic_{name}"] = analytic_flank_deviation(pair, member, u, f, s, mat.thermal_expansion,
                                                           mat.poisson_ratio, bore)
        out[f"strain_{name}"] = plane_strain_section(pair, member, mat, r, f, s, bore)
    return out


def three_d(scene, pair, member, level, groove=None):
    mat = scene.material
    bore = scene.pinion.bore_radius if member == 1 else scene.gear.bore_radius
    g = scene.pair.groove_width if groove is None else groove
    units = thermal_units_3d(pair, member, mat.thermal_expansion, mat.youngs_modulus, mat.poisson_ratio, bore, g,
                             scene.pair.stagger, level=level, cache=False)
    units.info["peak_rss_mb"] = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    return units


def readings(units, rho, b):
    out = {}
    for name, f, s in UNITS:
        out[name] = {"mid": units.at(rho, 0.5 * b, 0, f, s), "end": units.at(rho, 0.0, 0, f, s),
                     "apex": units.at(rho, b, 0, f, s), "right_mid": units.at(rho, 0.5 * b, 1, f, s),
                     "face_mean": units.face_mean(rho, f, s)}
    return out


def print_member(name, d2, r3, units, level):
    print(f"\n== {name}, body level {level}: {units.info['ndofs']} DOF, {units.info['seconds']:.1f} s cold "
          f"(factor {units.info['factor_seconds']:.1f} s, L+U {units.info['factor_mb']:.0f} MB), "
          f"process peak RSS {units.info['peak_rss_mb']:.0f} MB")
    for unit, _, _ in UNITS:
        print(f"  unit {unit} rise, ζ_n [nm/K]:")
        print("   ρ[mm] analytic  2D-fe  2D-strain  3D-mid  3D-end(ζ=0)  3D-apex(ζ=b)  3D-right-mid  3D-face  "
              "mid/fe-1[%] face/fe-1[%]")
        fe = d2[f"fe_{unit}"]
        r = r3[unit]
        for i in range(0, fe.size, 4):
            print(f"  {d2['rho'][i] * 1e3:5.2f} {d2[f'analytic_{unit}'][i] * 1e9:8.2f} {fe[i] * 1e9:7.2f} "
                  f"{d2[f'strain_{unit}'][i] * 1e9:9.2f} {r['mid'][i] * 1e9:7.2f} {r['end'][i] * 1e9:11.2f} "
                  f"{r['apex'][i] * 1e9:12.2f} {r['right_mid'][i] * 1e9:12.2f} {r['face_mean'][i] * 1e9:8.2f} "
                  f"{(r['mid'][i] / fe[i] - 1) * 100:10.2f} {(r['face_mean'][i] / fe[i] - 1) * 100:12.2f}")


def setup(scene_path=ROOT / "studies" / "paper_baseline.toml"):
    """The scene of the study (default: the paper's pair)."""
    return load_scene(scene_path)


def run(scene, levels=(0, 1, 2), groove=0.0) -> dict:
    pair = pair_from_scene(scene)
    u = np.linspace(pair.u_start, pair.u_end, 21)
    out = {"u": u, "pair": pair, "members": {}}
    for member, name in ((1, "pinion"), (2, "gear")):
        d2 = two_d(scene, pair, member, u)
        per_level = {}
        for level in levels:
            units = three_d(scene, pair, member, level)
            per_level[level] = (units, readings(units, d2["rho"], pair.b))
            print_member(name, d2, per_level[level][1], units, level)
        grooved = None
        if groove > 0:
            units = three_d(scene, pair, member, levels[0], groove)
            grooved = (units, readings(units, d2["rho"], pair.b))
            print_member(f"{name} with a {groove * 1e3:.0f} mm groove", d2, grooved[1], units, levels[0])
        out["members"][name] = {"2d": d2, "3d": per_level, "grooved": grooved}
    return out


def convergence(res, levels) -> dict:
    """Largest relative change of the mid-face unit responses between successive body levels."""
    conv = {}
    for name, m in res["members"].items():
        for unit, _, _ in UNITS:
            vals = [m["3d"][lv][1][unit]["mid"] for lv in levels]
            conv[f"{name}_{unit}"] = [float(np.max(np.abs(b / a - 1))) for a, b in zip(vals, vals[1:])]
    print("\nmesh convergence (max |ζ_mid(level k+1)/ζ_mid(level k) − 1| along the path):")
    for k, v in conv.items():
        print(f"  {k}: " + ", ".join(f"{levels[i]}→{levels[i + 1]}: {x * 100:.2f} %" for i, x in enumerate(v)))
    return conv


def plot(res, level, path=ROOT / "out" / "tooth_thermal_3d.png") -> Path:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    pair, u = res["pair"], res["u"]
    s = (u - pair.u_pitch) * 1e3
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.2))
    for (name, m), c in zip(res["members"].items(), ("C0", "C3")):
        d2, r3 = m["2d"], m["3d"][level][1]
        for ax, unit in zip(axes[:2], ("flank", "shaft")):
            ax.plot(s, d2[f"analytic_{unit}"] * 1e9, color=c, ls=":", label=f"{name}, analytic")
            ax.plot(s, d2[f"fe_{unit}"] * 1e9, color=c, ls="--", label=f"{name}, 2-D fe (plane stress)")
            ax.plot(s, r3[unit]["mid"] * 1e9, color=c, label=f"{name}, 3-D mid-face")
            ax.plot(s, r3[unit]["end"] * 1e9, color=c, lw=0.8, marker=".", label=f"{name}, 3-D outer end")
            ax.set_title(f"unit {unit} rise")
            ax.set_xlabel("position from pitch point [mm]")
            ax.set_ylabel("ζ_n [nm/K]")
        units = m["3d"][level][0]
        ip = int(np.argmin(np.abs(units.rho - contact_geometry(pair, 1 if name == "pinion" else 2, pair.u_pitch)[2])))
        z = units.zeta * 1e3
        axes[2].plot(z, units.flank[0, ip] * 1e9, color=c, label=f"{name}, left helix")
        axes[2].plot(2 * pair.b * 1e3 - z, units.flank[1, ip] * 1e9, color=c, ls="--", label=f"{name}, right helix")
    axes[2].set_xlabel("axial position z [mm] (apex at b)")
    axes[2].set_ylabel("ζ_n near the pitch point, unit flank rise [nm/K]")
    axes[0].legend(fontsize=6)
    axes[2].legend(fontsize=7)
    fig.suptitle("Thermal flank deviation: 3-D member body vs 2-D section vs analytic disc")
    return save_figure(fig, path)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("scene", nargs="?", default=str(ROOT / "studies" / "paper_baseline.toml"))
    ap.add_argument("--levels", default="0,1,2")
    ap.add_argument("--groove", type=float, default=0.0)
    a = ap.parse_args(argv)
    levels = tuple(int(x) for x in a.levels.split(","))
    res = run(setup(a.scene), levels, a.groove)
    conv = convergence(res, levels) if len(levels) > 1 else {}
    print(f"figure: {plot(res, levels[-1])}")
    summary = {"levels": list(levels), "convergence": conv}
    ip = int(np.argmin(np.abs(res["u"] - res["pair"].u_pitch)))
    for name, m in res["members"].items():
        units, r3 = m["3d"][levels[-1]]
        summary[name] = {"seconds": {str(lv): m["3d"][lv][0].info["seconds"] for lv in levels},
                         "ndofs": {str(lv): m["3d"][lv][0].info["ndofs"] for lv in levels},
                         "factor_mb": {str(lv): m["3d"][lv][0].info["factor_mb"] for lv in levels},
                         "peak_rss_mb": units.info["peak_rss_mb"]}
        for unit, _, _ in UNITS:
            fe = m["2d"][f"fe_{unit}"]
            summary[name][f"{unit}_pitch_nm_per_K"] = {
                "analytic": m["2d"][f"analytic_{unit}"][ip] * 1e9, "fe2d": fe[ip] * 1e9,
                "fe2d_strain": m["2d"][f"strain_{unit}"][ip] * 1e9, "mid": r3[unit]["mid"][ip] * 1e9,
                "end": r3[unit]["end"][ip] * 1e9, "apex": r3[unit]["apex"][ip] * 1e9,
                "face_mean": r3[unit]["face_mean"][ip] * 1e9}
            summary[name][f"{unit}_mid_vs_fe_percent"] = [float(x) for x in
                                                          np.percentile((r3[unit]["mid"] / fe - 1) * 100, [0, 100])]
    print(json.dumps(summary, default=float))
    return 0


if __name__ == "__main__":
    sys.exit(main())
