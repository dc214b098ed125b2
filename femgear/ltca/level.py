"""The ``ltca`` stiffness level: one LTCA mesh cycle for :func:`femgear.stiffness.tvms.mesh_stiffness`.

tvms wraps the result as a ``MeshStiffness``: ``k_left``/``k_right`` are the secant
stiffnesses F_h/(δ − NLTE_h) of each helix along the normal line of action at the
operating load; ``info['ltca']`` is the whole :class:`femgear.ltca.analysis.LTCAResult`
and ``info['excitation']`` its per-helix tables (loaded/unloaded TE, tangent stiffness,
e_s = LTE − F_s/k_s).  (This module does not import tvms: no import cycle.)
"""

from __future__ import annotations

from femgear.geometry.gear import GearPair


def ltca_cycle(pair: GearPair, force: float, modifications=None, n_positions: int = 64, stagger: float = 0.0,
               youngs_modulus: float = 210e9, poisson_ratio: float = 0.3, level: int = 1, n_line: int = 16,
               extra=None):
    """(LTCAResult, info) of one mesh cycle at the total normal force ``force`` [N]."""
    from femgear.ltca.analysis import build_model, mesh_cycle

    model = build_model(pair, youngs_modulus, poisson_ratio, level=level)
    res = mesh_cycle(model, force, modifications, n_phases=n_positions, stagger=stagger, n_line=n_line, extra=extra,
                     keep_lines=False)
    info = {"ltca": res, "excitation": res.excitation(), "model_seconds": model.seconds,
            "lte_peak_to_peak": res.lte_peak_to_peak(), "force": force}
    return res, info


def ltca_options_from_scene(scene) -> dict:
    """Force and modifications of a scene for :func:`ltca_cycle`."""
    from femgear.ltca.analysis import normal_force

    pair = GearPair.from_scene(scene)
    return {"force": normal_force(pair, scene.operating.torque, scene.operating.driver),
            "modifications": scene.modifications}
