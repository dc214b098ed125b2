"""The thermal fixed point outside the EHL Newton (Habchi 2008; Habchi 2018, ch. 5).

energy(θ) solves the energy equation with viscosities frozen at the film temperatures
T_b + θ and returns (state, θ_new); resolve(θ) re-solves the EHL with the Reynolds
viscosity and density at θ (raising :class:`ConvergenceError` on failure) and returns its
Newton iteration count.  Converged when max |θ_new − θ| < tol [K]; θ_new is then the
returned field, so with the heat sources off (θ_new ≡ 0 at once) the EHL is never
re-solved and the isothermal solution is returned unchanged.

Safeguards: relaxation ``relax``, halved whenever the change grows (the layer shear rates
of a hot Eyring film can oscillate between layers), steps capped at ``max_step`` K (the
first energy solve sees the cold bulk viscosities and overshoots by hundreds of K at high
sliding), a Newton stall (cavitation active-set cycling) retried with half the step,
and ``max_rise`` against thermal runaway.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from femgear.errors import ConvergenceError


def thermal_loop(energy: Callable, resolve: Callable, theta: np.ndarray, *, tol: float, relax: float,
                 max_step: float, max_rise: float, max_iter: int, case: str):
    """Returns (state, θ, thermal iterations, Newton iterations)."""
    history: list[float] = []
    omega, newton_its = relax, 0
    for it in range(1, max_iter + 1):
        st, new = energy(theta)
        change = float(np.max(np.abs(new - theta))) if new.size else 0.0
        history.append(change)
        if not np.isfinite(change):
            raise ConvergenceError(case, "non-finite temperatures", {"temperature_change": history})
        if change < tol:
            return st, new, it, newton_its
        if len(history) > 1 and change > history[-2]:
            omega = max(0.5 * omega, 0.05)
        step = np.clip(omega * (new - theta), -max_step, max_step)
        if float(np.max(np.abs(theta + step))) > max_rise:
            raise ConvergenceError(case, f"temperatures run away (max rise > {max_rise} K)",
                                   {"temperature_change": history})
        for attempt in range(4):
            try:
                newton_its += resolve(theta + step)
                break
            except ConvergenceError as exc:
                if attempt == 3:
                    raise ConvergenceError(case, f"EHL re-solve failed in the thermal loop: {exc}",
                                           {"temperature_change": history}) from exc
                step = 0.5 * step
        theta = theta + step
    raise ConvergenceError(case, f"thermal loop: no convergence in {max_iter} iterations",
                           {"temperature_change": history})
