"""Gear body: speed–accuracy of the mesh-stiffness and thermal-deviation levels.

    python studies/benchmarks/body.py [SCENE] [--quick]

Mesh stiffness: tooth-pair stiffness per unit width k'(u) at 7 path positions by
ISO 6336 (c'_th as a flat value — ISO has no profile), PEM and FE at mesh sizes
h = m_n/2.5 … m_n/6.5 (P2); the error of each is the max relative difference from
the finest FE.  Thermal: ζ_T along the path at ΔT_f = 50 K by the analytic level and
FE at h = m_n/2.5 … m_n/8, error vs the finest FE.  Times are medians of repeats
(femgear.perf.measure; 1 repeat for the finest/reference runs).  Prints a table and
one JSON line.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

import numpy as np

from femgear.case.pair import pair_from_scene
from femgear.perf import measure
from femgear.physics.body.compliance import fe_pair_stiffness_per_width
from femgear.physics.body.thermal import analytic_flank_deviation, fe_flank_deviation
from femgear.physics.stiffness import iso6336_stiffness
from femgear.physics.stiffness.pem import pair_stiffness_per_width
from femgear.scene import load_scene

ROOT = Path(__file__).resolve().parents[2]


def setup(scene_path: str | Path = ROOT / "studies" / "paper_baseline.toml"):
    scene = load_scene(scene_path)
    return scene, pair_from_scene(scene)


def stiffness_rows(scene, pair, quick: bool = False) -> list[dict]:
    E, nu = scene.material.youngs_modulus, scene.material.poisson_ratio
    u = np.linspace(pair.u_start, pair.u_end, 7)
    divs = (2.5, 4.0) if quick else (2.5, 4.0, 6.5)
    fe = {}
    for d in divs:
        rep = 1 if d == divs[-1] else 3
        m = measure(lambda d=d: fe_pair_stiffness_per_width(pair, u, E, nu, h=pair.m_n / d, refine_ratio=0.3), rep)
        fe[d] = m
    ref = fe[divs[-1]].value[0]
    rows = []
    iso = measure(lambda: iso6336_stiffness(pair, youngs_modulus=E), 5)
    k_iso = np.full(u.shape, iso.value.c_th * 1e9)
    rows.append({"level": "iso6336 (c'_th)", "dofs": 0, "h_mm": None, "seconds": iso.seconds,
                 "error": float(np.max(np.abs(k_iso / ref - 1)))})
    pem = measure(lambda: pair_stiffness_per_width(pair, u, E, nu), 5)
    rows.append({"level": "pem", "dofs": 0, "h_mm": None, "seconds": pem.seconds,
                 "error": float(np.max(np.abs(pem.value / ref - 1)))})
    for d, m in fe.items():
        k, info = m.value
        rows.append({"level": f"fe h=m/{d:g}", "dofs": int(sum(info["ndofs"])), "h_mm": pair.m_n / d * 1e3,
                     "seconds": m.seconds, "error": float(np.max(np.abs(k / ref - 1))),
                     "reference": d == divs[-1]})
    return rows


def thermal_rows(scene, pair, quick: bool = False) -> list[dict]:
    mat = scene.material
    u = np.linspace(pair.u_start, pair.u_end, 9)
    rises = (50.0, scene.thermal.shaft_temperature_rise, mat.thermal_expansion)
    bore = scene.pinion.bore_radius
    divs = (2.5, 4.0) if quick else (2.5, 4.0, 8.0)
    fe = {}
    for d in divs:
        rep = 1 if d == divs[-1] else 3
        fe[d] = measure(lambda d=d: fe_flank_deviation(pair, 1, u, *rises, mat.youngs_modulus,
                                                               mat.poisson_ratio, mat.conductivity, bore,
                                                               h=pair.m_n / d), rep)
    ref = fe[divs[-1]].value
    an = measure(lambda: analytic_flank_deviation(pair, 1, u, *rises, mat.poisson_ratio, bore), 5)
    rows = [{"level": "analytic", "dofs": 0, "h_mm": None, "seconds": an.seconds,
             "error": float(np.max(np.abs(an.value / ref - 1)))}]
    for d, m in fe.items():
        rows.append({"level": f"fe h=m/{d:g}", "dofs": None, "h_mm": pair.m_n / d * 1e3, "seconds": m.seconds,
                     "error": float(np.max(np.abs(m.value / ref - 1))), "reference": d == divs[-1]})
    return rows


def _table(title, rows):
    print(title)
    print(f"  {'level':>16} {'DOFs':>8} {'h mm':>6} {'median s':>9} {'max rel err vs finest FE':>25}")
    for r in rows:
        h = f"{r['h_mm']:.2f}" if r["h_mm"] else "-"
        dofs = str(r["dofs"]) if r["dofs"] else "-"
        tag = " (reference)" if r.get("reference") else ""
        print(f"  {r['level']:>16} {dofs:>8} {h:>6} {r['seconds']:>9.4f} {r['error']:>25.2e}{tag}")


if __name__ == "__main__":
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    quick = "--quick" in sys.argv
    scene, pair = setup(*args[:1])
    srows = stiffness_rows(scene, pair, quick)
    trows = thermal_rows(scene, pair, quick)
    _table("tooth-pair stiffness per width k'(u), 7 positions (pinion + gear FE models):", srows)
    _table("thermal flank deviation ζ_T(u) of the pinion at ΔT_f = 50 K, 9 positions:", trows)
    print(json.dumps({"benchmark": "body", "stiffness": srows, "thermal": trows}))
