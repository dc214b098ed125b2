"""Kahraman–Singh jump of a spur pair with backlash: slow up/down sweeps of the mesh frequency.

    python studies/dynamics/spur_jump.py [SCENE] [--torque T] [--backlash B] [--points N]

The spur pair of SCENE (default FZG C14) reduced to its dynamic transmission error
(:func:`femgear.system.dynamics.one_mesh.torsional_sweep`) with its PEM mesh stiffness over one
mesh period; prints amplitude / static deflection and the contact-loss fraction for
both sweep directions, beside the stable solutions of the harmonic-balance continuation of the same
oscillator (:func:`femgear.system.dynamics.sdof_hb.spur_torsional_hb`, AFT with the time-varying stiffness,
through both folds), and one JSON line (also ``out/spur_jump.json``).
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path

import numpy as np

from femgear.case import build_case
from femgear.case.pair import pair_from_scene
from femgear.levels import stiffness as stiffness_levels
from femgear.scene import load_scene
from femgear.system.dynamics.one_mesh import torsional_mode_hand, torsional_sweep
from femgear.system.dynamics.sdof_hb import spur_torsional_hb

ROOT = Path(__file__).resolve().parents[2]


def setup(scene_path: str | Path = ROOT / "studies" / "fzg_c14.toml"):
    scene = load_scene(scene_path, ["physics.stiffness=pem"])
    return scene, pair_from_scene(scene), stiffness_levels.of(build_case(scene)).k_left


def run(scene, pair, k, torque: float = 20.0, backlash: float = 50e-6, points: int = 36, coarse: bool = False) -> dict:
    I1, I2 = scene.pinion.inertia, scene.gear.inertia
    fn = torsional_mode_hand(pair, I1, I2, float(k.mean()))
    ratios = np.linspace(0.6, 1.3, 9 if coarse else points)
    out = {"natural_frequency": fn, "ratio": ratios, "torque": torque, "backlash": backlash}
    for d in ("up", "down"):
        sw = torsional_sweep(pair, k, I1, I2, torque, ratios * fn, backlash, direction=d)
        o = np.argsort(sw.mesh_frequency)
        out[d] = {"amplitude": sw.amplitude[o] / (sw.static_deflection - backlash), "contact_loss": sw.contact_loss[o]}
    hb = spur_torsional_hb(pair, k, I1, I2, torque, backlash, harmonics=16 if coarse else 32,
                           samples=256 if coarse else 512, at=ratios)
    out["hb"] = {"ratio": hb.frequency, "amplitude": hb.amplitude, "stable": hb.stable, "folds": list(hb.folds),
                 "stable_at_ratio": hb.stable_at}
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
    print(f"{'f_m/f_n':>8s}{'A_up/x_s':>10s}{'A_down/x_s':>11s}{'loss_up':>9s}{'loss_down':>10s}  HB stable A/x_s")
    for i, r in enumerate(res["ratio"]):
        stable = " ".join(f"{a:.3f}" for a in res["hb"]["stable_at_ratio"][i] if np.isfinite(a))
        print(f"{r:8.3f}{res['up']['amplitude'][i]:10.3f}{res['down']['amplitude'][i]:11.3f}"
              f"{res['up']['contact_loss'][i]:9.2f}{res['down']['contact_loss'][i]:10.2f}  {stable}")
    print("harmonic-balance folds at f_m/f_n = " + ", ".join(f"{f:.4f}" for f in res["hb"]["folds"]))
    payload = json.loads(json.dumps(res, default=lambda a: np.asarray(a).tolist()))
    payload["study"] = "spur_jump"
    (ROOT / "out").mkdir(exist_ok=True)
    (ROOT / "out" / "spur_jump.json").write_text(json.dumps(payload))
    print(json.dumps({"study": "spur_jump", "natural_frequency": res["natural_frequency"],
                      "max_branch_ratio": float(np.max(res["down"]["amplitude"] / res["up"]["amplitude"])),
                      "hb_folds": res["hb"]["folds"]}))


if __name__ == "__main__":
    main()
