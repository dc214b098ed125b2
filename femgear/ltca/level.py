"""The ``ltca`` stiffness level: LTCA mesh stiffness tables in the :class:`MeshStiffness` form.

``k_left``/``k_right`` are the secant stiffnesses F_h/(δ − NLTE_h) of each helix along the
normal line of action at the operating load (the tvms convention); ``info['ltca']`` holds
the whole :class:`femgear.ltca.analysis.LTCAResult` and ``info['excitation']`` its
per-helix tables (loaded/unloaded TE, tangent stiffness, e_s = LTE − F_s/k_s).
"""

from __future__ import annotations

import time

from femgear.geometry.gear import GearPair


def ltca_mesh_stiffness(pair: GearPair, force: float, modifications=None, n_positions: int = 64,
                        stagger: float = 0.0, youngs_modulus: float = 210e9, poisson_ratio: float = 0.3,
                        level: int = 1, n_line: int = 16, extra=None):
    """:class:`femgear.stiffness.tvms.MeshStiffness` from one LTCA mesh cycle at normal force ``force`` [N]."""
    from femgear.ltca.analysis import build_model, mesh_cycle
    from femgear.stiffness.tvms import MeshStiffness

    t0 = time.perf_counter()
    model = build_model(pair, youngs_modulus, poisson_ratio, level=level)
    res = mesh_cycle(model, force, modifications, n_phases=n_positions, stagger=stagger, n_line=n_line, extra=extra,
                     keep_lines=False)
    info = {"ltca": res, "excitation": res.excitation(), "model_seconds": model.seconds,
            "lte_peak_to_peak": res.lte_peak_to_peak(), "force": force}
    return MeshStiffness("ltca", res.phase, res.k_secant_left, res.k_secant_right, stagger, 0,
                         time.perf_counter() - t0, info)


def ltca_options_from_scene(scene) -> dict:
    """Force, modifications and material of a scene for :func:`ltca_mesh_stiffness`."""
    from femgear.ltca.analysis import normal_force

    pair = GearPair.from_scene(scene)
    return {"force": normal_force(pair, scene.operating.torque, scene.operating.driver),
            "modifications": scene.modifications}
