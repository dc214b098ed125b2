"""The thermal fixed point outside the EHL Newton (Habchi 2008; Habchi 2018, ch. 5).

energy(θ) solves the energy equation with viscosities frozen at the film temperatures
T_b + θ and returns (state, θ_new); resolve(θ) re-solves the EHL with the Reynolds
viscosity and density at θ (raising :class:`ConvergenceError` on failure) and returns its
Newton iteration count.  The fixed point is θ = G(θ), G(θ) = θ_new; converged when
max |G(θ) − θ| < tol [K]; θ_new is then the returned field, so with the heat sources off
(θ_new ≡ 0 at once) the EHL is never re-solved and the isothermal solution is returned
unchanged.

Iteration: Anderson acceleration of depth ``depth`` with damping ``relax`` (Anderson
1965; Walker & Ni, SIAM J. Numer. Anal. 49 (2011) 1715, "Algorithm AA" with mixing
β = relax): with the residuals f_k = G(θ_k) − θ_k and the differences ΔΘ, ΔF of the last
iterates, γ = argmin ‖f_k − ΔF γ‖₂ and θ_{k+1} = θ_k + β f_k − (ΔΘ + β ΔF) γ
(``depth`` = 0 is plain relaxation).  Safeguards: when the residual grows, the history
is dropped and β halved (the layer shear rates of a hot Eyring film, or a very viscous
cold film, can oscillate); steps are capped at ``max_step`` K (the first energy solve
sees the cold bulk viscosities and overshoots by hundreds of K at high sliding); while
the residual exceeds ``max_step`` the iteration is damped Picard without history
(Anderson's secant model is local, Walker & Ni §1; from the cold start at 1 GPa,
10 m/s, SRR 1 the extrapolated steps drove the residual from 1495 K up to 2208 K);
a Newton stall (cavitation active-set cycling) is retried with half the step;
``max_rise`` guards against thermal runaway.  The residual "grows" when it exceeds
``growth`` x the previous one (default 1: any growth).  An iteration whose energy solve saw
a predicted EHL state (``solved`` = False) adds no secant pair: G there is another map.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from femgear.errors import ConvergenceError


class ThermalRunaway(ConvergenceError):
    """No steady state below the loop's ``max_rise``: a physical limit (the film would heat beyond it), which
    neither a finer grid nor a continuation removes."""


def anderson_step(res: np.ndarray, d_theta: list, d_res: list, beta: float) -> np.ndarray:
    """Walker & Ni's Anderson update θ_{k+1} − θ_k from the residual and the history."""
    step = beta * res
    if not d_res:
        return step
    dF = np.stack([d.ravel() for d in d_res], axis=1)
    dT = np.stack([d.ravel() for d in d_theta], axis=1)
    gamma = np.linalg.lstsq(dF, res.ravel(), rcond=None)[0]
    return step - ((dT + beta * dF) @ gamma).reshape(res.shape)


def thermal_loop(energy: Callable, resolve: Callable, theta: np.ndarray, *, tol: float, relax: float,
                 max_step: float, max_rise: float, max_iter: int, case: str, depth: int = 5,
                 solved: bool = True, growth: float = 1.0, history: list | None = None, bulk: float | None = None):
    """Returns (state, θ, thermal iterations, Newton iterations).  ``solved`` = False: the
    EHL state that ``energy`` sees is only a prediction (a prolonged coarse-grid solution),
    not yet re-solved at θ; the loop then does not stop before one ``resolve``.  ``history``: a
    list the temperature changes are appended to (the caller's record across loops); the
    ConvergenceError of a failed loop carries the changes of this loop; ``bulk``: the inlet temperature [K], which
    the runaway's message turns into the film temperature it would pass."""
    record = history if history is not None else []
    history = []
    d_theta: list[np.ndarray] = []
    d_res: list[np.ndarray] = []
    beta, newton_its, previous = relax, 0, None
    for it in range(1, max_iter + 1):
        st, new = energy(theta)
        res = new - theta
        change = float(np.max(np.abs(res))) if res.size else 0.0
        history.append(change)
        record.append(change)
        if not np.isfinite(change):
            raise ConvergenceError(case, "non-finite temperatures", {"temperature_change": history})
        if change < tol and solved:
            return st, new, it, newton_its
        if len(history) > 1 and change > growth * history[-2]:
            beta = max(0.5 * beta, 0.05)
            d_theta.clear(), d_res.clear()
        elif previous is not None and depth > 0:
            d_theta.append(theta - previous[0]), d_res.append(res - previous[1])
            del d_theta[:-depth], d_res[:-depth]
        if change > max_step or not solved:  # far from the fixed point, or G evaluated on a predicted
            d_theta.clear(), d_res.clear()    # (not re-solved) EHL state: damped Picard, no secant history
            previous = None
        else:
            previous = (theta, res)
        step = np.clip(anderson_step(res, d_theta, d_res, beta), -max_step, max_step)
        if float(np.max(np.abs(theta + step))) > max_rise:
            hot = "" if bulk is None else (f": the film would pass {bulk + max_rise - 273.15:.0f} °C, beyond the flash "
                                           "and decomposition temperatures of lubricating oils")
            raise ThermalRunaway(case, f"temperatures run away (max rise > {max_rise} K){hot}",
                                 {"temperature_change": history})
        for attempt in range(4):
            try:
                newton_its += resolve(theta + step)
                solved = True
                break
            except ConvergenceError as exc:
                if attempt == 3:
                    raise ConvergenceError(case, f"EHL re-solve failed in the thermal loop: {exc}",
                                           {"temperature_change": history}) from exc
                step = 0.5 * step
        theta = theta + step
    raise ConvergenceError(case, f"thermal loop: no convergence in {max_iter} iterations",
                           {"temperature_change": history})
