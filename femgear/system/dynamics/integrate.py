"""Time integration of a :class:`GearRotorModel`: one entry point, three integrators.

- ``rk4`` (:mod:`femgear.system.dynamics.rk4`): classical fixed-step RK4 as the paper uses
  (dt = 1e-5 s); explicit, so a step above its stability limit is refused.
- ``expo`` (:mod:`femgear.system.dynamics.expo`): exponential integrator with exact
  propagators per mesh phase and contact state — the fast one.
- ``newmark`` (:mod:`femgear.system.dynamics.newmark`): implicit HHT-α / Newmark with exact Newton
  on the gap, unconditionally stable.

All return a :class:`Simulation` with the recorded states.
"""

from __future__ import annotations

import math

import numpy as np

from femgear.system.dynamics.expo import expo, expo_step  # noqa: F401  (re-exported)
from femgear.system.dynamics.model import GearRotorModel
from femgear.system.dynamics.newmark import newmark
from femgear.system.dynamics.rk4 import first_order_matrix, rk4, stability_limit  # noqa: F401  (re-exported)
from femgear.system.dynamics.simulation import Simulation

METHODS = ("rk4", "newmark", "expo")


def simulate(
    model: GearRotorModel,
    duration: float,
    dt: float,
    method: str = "rk4",
    *,
    q0: np.ndarray | None = None,
    v0: np.ndarray | None = None,
    record_every: int = 1,
    record_from: float = 0.0,
    alpha: float = 0.0,
    max_iter: int = 20,
    check_stability: bool = True,
    substeps: int | None = None,
    t_start: float = 0.0,
) -> Simulation:
    """Integrate from t = ``t_start`` (default 0) over ``duration`` [s] with the fixed step ``dt`` [s].

    Initial state: the static equilibrium of the mean system (``q0``/``v0`` override).
    States at t ≥ ``record_from`` are recorded every ``record_every`` steps.
    ``alpha`` ∈ [−1/3, 0]: HHT numerical damping (``newmark`` only).
    ``t_start``: the time of the initial state (``expo`` only; a whole number of mesh periods).
    ``substeps``: stiffness sub-steps inside one ``expo`` step (default: :func:`femgear.system.dynamics.expo.default_substeps`).
    """
    if method not in METHODS:
        raise ValueError(f"method must be one of {', '.join(METHODS)} (got {method!r})")
    if not (math.isfinite(dt) and dt > 0):
        raise ValueError(f"dt must be positive (got {dt!r})")
    if not duration > 0:
        raise ValueError(f"duration must be positive (got {duration!r})")
    if not isinstance(record_every, int) or record_every < 1:
        raise ValueError(f"record_every must be a positive integer (got {record_every!r})")
    steps = int(round(duration / dt))
    q = model.static_state() if q0 is None else np.asarray(q0, dtype=float).copy()
    v = np.zeros(model.n) if v0 is None else np.asarray(v0, dtype=float).copy()
    if method == "rk4":
        if check_stability:
            limit = stability_limit(model)
            if dt > limit:
                raise ValueError(
                    f"dt = {dt:.3g} s exceeds the RK4 stability limit {limit:.3g} s of this model "
                    f"(stiffest mode {1 / (2 * math.pi) * 2.785 / limit:.0f} Hz); lower dt or use method='expo' or 'newmark'"
                )
        return rk4(model, steps, dt, q, v, record_every, record_from)
    if method == "expo":
        return expo(model, steps, dt, q, v, record_every, record_from, substeps, t_start)
    if t_start != 0.0:
        raise ValueError(f"t_start is supported by method='expo' only (got {method!r})")
    if not -1 / 3 <= alpha <= 0:
        raise ValueError(f"alpha must be in [-1/3, 0] (got {alpha!r})")
    return newmark(model, steps, dt, q, v, record_every=record_every, record_from=record_from, alpha=alpha,
                   max_iter=max_iter)


