"""Kahraman–Singh jump of a spur pair with backlash: slow up/down sweeps of the mesh frequency.

    python studies/dynamics/spur_jump.py [SCENE] [--torque T] [--backlash B] [--points N]

The spur pair of SCENE (default FZG C14) reduced to its dynamic transmission error
(:func:`femgear.system.dynamics.one_mesh.torsional_sweep`) with its PEM mesh stiffness over one
mesh period; prints amplitude / static deflection and the contact-loss fraction for
both sweep directions, and one JSON line (also ``out/spur_jump.json``).
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path

import numpy as np

from femgear.physics.geometry import GearPair
from femgear.physics.stiffness.tvms import mesh_stiffness_from_scene
from femgear.scene import load_scene
from femgear.system.dynamics.one_mesh import torsional_mode_hand, torsional_sweep

ROOT = Path(__file__).resolve().parents[2]


def setup(scene_path: str | Path = ROOT / "studies" / "fzg_c14.toml"):
    scene = load_scene(scene_path, ["physics.stiffness=pem"])
    return scene, GearPair.from_scene(scene), mesh_stiffness_from_scene(scene).k_left


def run(scene, pair, k, torque: float = 20.0, backlash: float = 50e-6, points: int = 36) -> dict:
    I1, I2 = scene.pinion.inertia, scene.gear.inertia
    fn = torsional_mode_hand(pair, I1, I2, float(k.mean()))
    ratios = np.linspace(0.6, 1.3, points)
    out = {"natural_frequency": fn, "ratio": ratios, "torque": torque, "backlash": backlash}
    for d in ("up", "down"):
        sw = torsional_sweep(pair, k, I1, I2, torque, ratios * fn, backlash, direction=d)
        o = np.argsort(sw.mesh_frequency)
        out[d] = {"amplitude": sw.amplitude[o] / (sw.static_deflection - backlash), "contact_loss": sw.contact_loss[o]}
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("scene", nargs="?", default=str(ROOT / "studies" / "fzg_c14.toml"))
    ap.add_argument("--torque", type=float, default=20.0)
    ap.add_argument("--backlash", type=float, default=50e-6)
    ap.add_argument("--points", type=int, default=36)
    args = ap.parse_args()
    res = run(*setup(args.scene), torque=args.torque, backlash=args.backlash, points=args.points)
    print(f"torsional mesh mode (rigid supports) f_n = {res['natural_frequency']:.1f} Hz; "
          f"T1 = {res['torque']} N m, b0 = {res['backlash'] * 1e6:.0f} µm")
    print(f"{'f_m/f_n':>8s}{'A_up/x_s':>10s}{'A_down/x_s':>11s}{'loss_up':>9s}{'loss_down':>10s}")
    for i, r in enumerate(res["ratio"]):
        print(f"{r:8.3f}{res['up']['amplitude'][i]:10.3f}{res['down']['amplitude'][i]:11.3f}"
              f"{res['up']['contact_loss'][i]:9.2f}{res['down']['contact_loss'][i]:10.2f}")
    payload = json.loads(json.dumps(res, default=lambda a: np.asarray(a).tolist()))
    payload["study"] = "spur_jump"
    (ROOT / "out").mkdir(exist_ok=True)
    (ROOT / "out" / "spur_jump.json").write_text(json.dumps(payload))
    print(json.dumps({"study": "spur_jump", "natural_frequency": res["natural_frequency"],
                      "max_branch_ratio": float(np.max(res["down"]["amplitude"] / res["up"]["amplitude"]))}))


if __name__ == "__main__":
    main()
