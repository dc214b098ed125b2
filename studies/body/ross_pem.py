"""femgear's PEM mesh stiffness against ROSS's published 62/62 spur test gear, side by side.

    python studies/body/ross_pem.py [--plane strain|stress]

ROSS's curve (ROSS 2.3.0, its ``test_gear_element.py`` gear: m 2 mm, z 62/62, b 20 mm,
bore Ø35 mm, E 206 GPa, ν 0.3) is read from ``tests/stiffness/data/ross_62_62_tvms.json``.
Prints min/mean/max and the two curves over one mesh period, and one JSON line (also
written to ``out/ross_pem.json``).
"""

from __future__ import annotations

import argparse
import json
import math
from pathlib import Path

import numpy as np

from femgear.physics.geometry.gear import GearPair
from femgear.physics.stiffness.pem import pem_mesh_stiffness

ROOT = Path(__file__).resolve().parents[2]
DATA = ROOT / "tests" / "stiffness" / "data" / "ross_62_62_tvms.json"


def setup() -> tuple[GearPair, dict]:
    pair = GearPair.from_parameters(z1=62, z2=62, m_n=2e-3, alpha_n=math.radians(20), beta=0.0, b=0.02, x1=0.0,
                                    x2=0.0, kind="spur")
    return pair, json.loads(DATA.read_text())


def run(pair: GearPair, ross: dict, plane: str = "strain") -> dict:
    ms = pem_mesh_stiffness(pair, 206e9, 0.3, 400,
                        bore_radius=(0.0175, 0.0175), plane=plane)
    phase = np.array(ross["phase"])
    ours = ms.at(phase, "left")
    stats = {name: {"femgear": float(f(ms.k_left)), "ross": ross[name], "ratio": float(f(ms.k_left)) / ross[name]}
             for name, f in (("min", np.min), ("mean", np.mean), ("max", np.max))}
    return {"plane": plane, "stats": stats, "phase": phase, "k_femgear": ours, "k_ross": np.array(ross["k"]),
            "seconds": ms.seconds}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--plane", choices=("strain", "stress"), default="strain")
    args = ap.parse_args()
    res = run(*setup(), plane=args.plane)
    print(f"62/62 spur test gear of ROSS, PEM plane {res['plane']}  [N/m]")
    print(f"{'':6s}{'femgear':>14s}{'ROSS':>14s}{'ratio':>9s}")
    for name, s in res["stats"].items():
        print(f"{name:6s}{s['femgear']:14.5e}{s['ross']:14.5e}{s['ratio']:9.4f}")
    print(f"\n{'phase':>7s}{'femgear':>14s}{'ROSS':>14s}{'diff %':>9s}")
    for ph, a, b in list(zip(res["phase"], res["k_femgear"], res["k_ross"], strict=True))[::5]:
        print(f"{ph:7.3f}{a:14.5e}{b:14.5e}{100 * (a / b - 1):9.2f}")
    payload = {"study": "ross_pem", "plane": res["plane"], "stats": res["stats"], "seconds": res["seconds"],
               "phase": res["phase"].tolist(), "k_femgear": res["k_femgear"].tolist(), "k_ross": res["k_ross"].tolist()}
    out = ROOT / "out"
    out.mkdir(exist_ok=True)
    (out / "ross_pem.json").write_text(json.dumps(payload))
    print(json.dumps({k: payload[k] for k in ("study", "plane", "stats")}))


if __name__ == "__main__":
    main()
