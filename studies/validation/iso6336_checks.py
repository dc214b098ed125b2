"""ISO 6336-2 method B against ISO/TR 6336-30 example 1, and FZG C14 Hertz against the single-pair hand calculation.

    python studies/validation/iso6336_checks.py

Prints two tables (femgear, reference, relative difference) and one JSON line.  The
reference values are those the tests use (tests/rating/test_iso6336_2.py,
tests/contact/test_sharing.py), where their sources are cited.
"""

from __future__ import annotations

import json
import math
import sys
from pathlib import Path

import numpy as np

from femgear.case import build_case
from femgear.case.pair import pair_from_scene
from femgear.levels.contact import contact_pass
from femgear.physics.contact.sharing import single_contact_bounds
from femgear.physics.geometry.gear import GearPair
from femgear.physics.rating import LoadFactors, MaterialLimits, contact_stress, pitting_rating
from femgear.scene import load_scene

ROOT = Path(__file__).resolve().parents[2]
MPA = 1e6
#: ISO/TR 6336-30:2017 example 1, printed values (N/mm² for stresses)
TR = {"z_n1": 18.905, "z_n2": 114.543, "Z_H": 2.39533, "Z_E": 189.81170, "Z_eps": 0.803, "Z_beta": 1.01944,
      "sigma_H0": 1206.58207, "sigma_H": 1301.35343, "Z_NT1": 0.91, "Z_NT2": 0.962, "Z_L": 1.04739, "Z_v": 0.96911,
      "Z_R": 0.96599, "sigma_HP1": 1338.48050, "sigma_HP2": 1414.52551, "S_H1": 1.02853, "S_H2": 1.08696}


def tr_example() -> dict:
    pair = GearPair.from_parameters(z1=17, z2=103, m_n=8e-3, alpha_n=math.radians(20), beta=math.radians(15.8),
                                    b=0.1, x1=0.145, x2=0.0, h_aP=1.0, h_fP=1.4, rho_fP=0.39, kind="single-helical")
    s = contact_stress(pair, 9000.0, 206e9, 0.3, LoadFactors(K_v=1.003, K_Hbeta=1.16))
    r = pitting_rating(pair, s, 360.0, MaterialLimits(sigma_Hlim=1500 * MPA, life_hours=50e3, nu40=320.0,
                                                      Rz=(6e-6, 6e-6)))
    ours = {"z_n1": s.z_n[0], "z_n2": s.z_n[1], "Z_H": s.Z_H, "Z_E": s.Z_E / math.sqrt(MPA), "Z_eps": s.Z_eps,
            "Z_beta": s.Z_beta, "sigma_H0": s.sigma_H0 / MPA, "sigma_H": s.sigma_H[0] / MPA, "Z_NT1": r.Z_NT[0],
            "Z_NT2": r.Z_NT[1], "Z_L": r.Z_L, "Z_v": r.Z_v, "Z_R": r.Z_R, "sigma_HP1": r.sigma_HP[0] / MPA,
            "sigma_HP2": r.sigma_HP[1] / MPA, "S_H1": r.S_H[0], "S_H2": r.S_H[1]}
    return {k: (ours[k], TR[k], ours[k] / TR[k] - 1) for k in TR}


def fzg_table(torque: float = 200.0) -> dict:
    scene = load_scene(ROOT / "studies" / "fzg_c14.toml", [f"operating.torque={torque}"])
    pair = pair_from_scene(scene)
    u_B = single_contact_bounds(pair)[0]
    c = contact_pass(build_case(scene, pair), u=np.array([u_B, pair.u_pitch]))
    # hand calculation from the drawing data (as in tests/contact/test_sharing.py)
    m, z1, z2, a_w, b, al = 4.5e-3, 16, 24, 91.5e-3, 14e-3, math.radians(20)
    rb1 = z1 * m / 2 * math.cos(al)
    aw = math.acos((z1 + z2) * m / 2 * math.cos(al) / a_w)
    T1T2, E_red, w = a_w * math.sin(aw), 206e9 / (1 - 0.09), torque / rb1 / b
    rows = {}
    for i, (name, rho1) in enumerate((("B", math.sqrt((82.456e-3 / 2) ** 2 - rb1**2) - math.pi * m * math.cos(al)),
                                      ("C", rb1 * math.tan(aw)))):
        R = rho1 * (T1T2 - rho1) / T1T2
        bh = math.sqrt(8 * w * R / (math.pi * E_red))
        rows[f"p_H {name} [MPa]"] = (c.hertz_pressure[i] / MPA, 2 * w / (math.pi * bh) / MPA,
                                     c.hertz_pressure[i] / (2 * w / (math.pi * bh)) - 1)
        rows[f"b_H {name} [um]"] = (c.hertz_half_width[i] * 1e6, bh * 1e6, c.hertz_half_width[i] / bh - 1)
    return rows


def _print(title: str, rows: dict) -> None:
    print(title)
    print(f"{'':16s}{'femgear':>14s}{'reference':>14s}{'diff %':>9s}")
    for k, (a, b, d) in rows.items():
        print(f"{k:16s}{a:14.6g}{b:14.6g}{100 * d:9.3f}")


def setup() -> dict:
    """The checks: ISO/TR 6336-30 example 1 and the FZG C14 table."""
    return {"tr": tr_example, "fzg": fzg_table}


def run() -> dict:
    """Each check's rows (femgear against the reference, difference)."""
    return {name: check() for name, check in setup().items()}


def main() -> int:
    res = run()
    tr, fzg = res["tr"], res["fzg"]
    _print("ISO/TR 6336-30 example 1 (ISO 6336-2 method B)", tr)
    print()
    _print("FZG C14, 200 N m: single-pair Hertz at the inner point of single contact B and the pitch point C", fzg)
    worst = {"tr_max_abs_diff": max(abs(d) for *_, d in tr.values()),
             "fzg_max_abs_diff": max(abs(d) for *_, d in fzg.values())}
    print(json.dumps({"study": "iso6336_checks", **worst}))
    return 0


if __name__ == "__main__":
    sys.exit(main())
