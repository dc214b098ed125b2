"""The wear load map of the ``ltca`` level against the Winkler layer, and a pinion tip relief's effect on wear.

    python studies/ltca/ltca_wear_load.py

On the baseline pair at 200 N·m, for the coarse test model (level 0, 16 phases) and the
``ltca`` level's model (level 1, 64 phases): the largest equilibrium error of the LTCA
load map over the phases (:func:`femgear.physics.wear.load_sharing.reference_loads`, both helices),
the grid map's force error (each line scaled to its LTCA load, and the plain interpolation onto
61 path positions), the passage-mean
load intensity against the uniform Winkler map (inside the path and at its ends A and E,
:func:`femgear.physics.wear.load_sharing.load_map`), and the unworn Archard rate of the pinion at
its tip (path end E) with a 10 µm × 3 mm linear pinion tip relief against none.  Prints a
table and a JSON line; writes ``out/ltca_wear_load/ltca_wear_load.json``.
"""

from __future__ import annotations

import math
import sys
from dataclasses import replace

import numpy as np

from femgear.case import build_case
from femgear.case.pair import pair_from_scene
from femgear.levels.wear import static_setup

try:
    from studies import _common as C
except ImportError:
    import pathlib
    import sys

    sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2]))
    from studies import _common as C

MODELS = {"level 0 (tests)": ({"level": 0, "order": 1, "n_rho": 5, "n_z": 5, "n_teeth": 3}, 16, 8),
          "level 1 (ltca level)": ({"level": 1}, 64, 16)}


def _model_rows(pair, scene, kw: dict, n_phases: int, n_line: int) -> dict:
    from femgear.physics.geometry import kinematics, path_positions
    from femgear.physics.ltca.analysis import build_model, mesh_cycle, normal_force
    from femgear.physics.ltca.cycle import LTCACycle
    from femgear.physics.wear import WearState, wear_rates
    from femgear.physics.wear.load_sharing import load_map, reference_load_map, reference_loads, trapezoid_weights
    from femgear.scene.schema import FlankModification, Modifications
    from femgear.system.coupling.setup import ltca_reference

    F = normal_force(pair, 200.0)
    u = path_positions(pair, 61)
    dl = trapezoid_weights(u) / math.sin(pair.beta_b)
    model = build_model(pair, 210e9, 0.3, **kw)
    mods = Modifications(pinion=FlankModification(tip_relief=10e-6, tip_relief_length=3e-3), gear=FlankModification())
    out, refs = {}, {}
    for name, m in (("plain", None), ("relief", mods)):
        res = mesh_cycle(model, F, m, n_phases=n_phases, stagger=scene.pair.stagger, n_line=n_line)
        refs[name] = ltca_reference(pair, u, LTCACycle.from_result(res, model, m), np.zeros(u.size))
        if name == "plain":
            own = np.array([res.force_left, res.force_right])
            w = reference_loads(pair, u, own, np.zeros(u.size), 1.5e10, refs[name])
            out["equilibrium_error"] = float(np.max(np.abs(w @ dl - own) / own))
            out["line_scaled_grid_force_error"] = float(np.max(np.abs(refs[name].load @ dl / own - 1)))
            out["raw_grid_force_error"] = float(np.max(np.abs(res.path_load(pair, u) @ dl / own - 1)))
    kin = kinematics(pair, u, 500 * 2 * math.pi / 60)
    base = static_setup(build_case(scene), kin, n_phase=n_phases)
    ltca = reference_load_map(pair, u, base.force, np.zeros(u.size), base.c_l, refs["plain"])
    wink = load_map(pair, u, base.force, np.zeros(u.size), base.c_l, n_phases)
    inner = (wink.loaded_fraction > 0.2) & (np.abs(u - u.mean()) < 0.4 * np.ptp(u))
    ratio = ltca.mean_load / wink.mean_load - 1
    out.update({"inner_mean_percent": 100 * float(ltca.mean_load[inner].mean() / wink.mean_load[inner].mean() - 1),
                "inner_min_percent": 100 * float(ratio[inner].min()), "inner_max_percent": 100 * float(ratio[inner].max()),
                "end_A_percent": 100 * float(ratio[0]), "end_E_percent": 100 * float(ratio[-1])})
    zero = WearState.zero(u.size)
    r_plain = wear_rates(replace(base, reference=refs["plain"]), zero)[0]
    r_relief = wear_rates(replace(base, reference=refs["relief"]), zero)[0]
    tip = u > u[-1] - 1.5e-3
    out["tip_rate_ratio_max"] = float(np.max(r_relief[tip] / r_plain[tip]))
    out["tip_rate_ratio_mean"] = float(np.mean(r_relief[tip]) / np.mean(r_plain[tip]))
    return out


def setup():
    """The baseline scene and its pair."""
    from femgear.scene import load_scene

    scene = load_scene(C.BASELINE)
    return scene, pair_from_scene(scene)


def run() -> dict:
    scene, pair = setup()
    return {name: _model_rows(pair, scene, *args) for name, args in MODELS.items()}


def main(argv: list[str]) -> int:
    res = run()
    for name, r in res.items():
        print(f"{name}: equilibrium {r['equilibrium_error']:.1e}, grid force: lines scaled "
              f"{r['line_scaled_grid_force_error']:.1e}, plain interpolation {100 * r['raw_grid_force_error']:.1f} %; "
              f"LTCA vs Winkler mean w': inside {r['inner_mean_percent']:+.1f} % "
              f"({r['inner_min_percent']:+.1f} … {r['inner_max_percent']:+.1f} %), A {r['end_A_percent']:+.0f} %, "
              f"E {r['end_E_percent']:+.0f} %; pinion tip wear rate with relief / without: "
              f"mean {r['tip_rate_ratio_mean']:.2f}, max {r['tip_rate_ratio_max']:.2f}")
    print("json:", C.write_results("ltca_wear_load", res))
    print(C.json.dumps({"study": "ltca_wear_load", **res}))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
