"""Named fidelity presets: ``physics.preset = "fast" | "balanced" | "accurate"``.

A preset fills in the fidelity levels and resolution knobs it names; any key a scene
(or ``--set``) gives explicitly wins.  Wear and coupling are physics choices, not
fidelity, and are left to the scene.  The choice of each preset comes from the
measured speed–accuracy trade (``studies/validation/speed_accuracy.py``, the table of docs/validation/speed-accuracy.md).
"""

from __future__ import annotations

from typing import Any

PRESETS: dict[str, dict[str, dict[str, Any]]] = {
    "fast": {
        "physics": {"stiffness": "pem", "lubrication": "formula", "thermal": "analytic", "dynamics": "lumped"},
        "stiffness": {"n_positions": 100},
        "numerics": {"path_points": 21, "steps_per_mesh_period": 100, "dynamics_cycles": 60.0,
                     "transient_cycles": 30.0},
    },
    "balanced": {
        "physics": {"stiffness": "pem", "lubrication": "formula", "thermal": "analytic", "dynamics": "lumped"},
        "stiffness": {"n_positions": 200},
        "numerics": {"path_points": 41, "steps_per_mesh_period": 200, "dynamics_cycles": 100.0,
                     "transient_cycles": 50.0},
    },
    "accurate": {
        "physics": {"stiffness": "fe", "lubrication": "ehl-line", "thermal": "fe", "dynamics": "timoshenko"},
        "stiffness": {"n_positions": 400},
        "numerics": {"path_points": 61, "steps_per_mesh_period": 400, "dynamics_cycles": 150.0,
                     "transient_cycles": 75.0, "ehl_tol": 0.005},
    },
}


def expand_preset(raw: dict[str, Any]) -> dict[str, Any]:
    """The raw scene with its preset's entries filled in under the explicit ones."""
    physics = raw.get("physics")
    if not isinstance(physics, dict) or "preset" not in physics:
        return raw
    name = physics["preset"]
    if name not in PRESETS:
        from femgear.errors import SceneError

        raise SceneError("physics.preset", f"unknown preset {name!r}; choose one of {', '.join(PRESETS)}")
    out = dict(raw)
    for table, values in PRESETS[name].items():
        given = out.get(table, {})
        out[table] = {**values, **given} if isinstance(given, dict) else given
    return out
