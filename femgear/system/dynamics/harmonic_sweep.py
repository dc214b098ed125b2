"""Whine against speed: a speed sweep by harmonic balance, handing contact loss to the time integration.

For each driver speed the model comes from one :class:`~femgear.system.dynamics.family.SpeedFamily`
(built once) and is solved by :func:`femgear.system.dynamics.harmonic.harmonic_response`.  In contact
the problem at each speed is linear (one solve, no iteration), so the sweep needs no predictor; where
it is not linear the harmonic balance does not answer:

- the flanks may separate (:attr:`HarmonicSolution.contact_kept` False: the backlash nonlinearity), or
- an excitation lies outside it (:func:`femgear.system.dynamics.harmonic.applies`: random pitch errors);

those speeds run in the time domain (:func:`femgear.system.dynamics.run.run_dynamics`, the default
integrator and step) and the sweep says so in :attr:`OrderSweep.warnings` — a linear answer is never
returned where the flanks separate.  The time-domain order amplitudes are the least-squares lines over
whole mesh periods (:func:`femgear.system.dynamics.orders.mesh_orders`), the quantities the harmonic
balance reports, so the two methods' rows read alike.

``method``: ``"harmonic"`` (hand-off as above), ``"time"`` (every speed in the time domain, as
:func:`femgear.system.dynamics.sweep.speed_sweep`) or ``"auto"`` (``"harmonic"`` where it applies).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from femgear.case import Case
from femgear.docfields import document_fields
from femgear.system.dynamics.family import SpeedFamily
from femgear.system.dynamics.harmonic import applies, harmonic_responses
from femgear.system.dynamics.orders import ORDERS, mesh_orders

METHODS = ("auto", "harmonic", "time")
#: speeds solved together by the harmonic balance (one batch of numpy calls)
BATCH = 50


@document_fields
@dataclass(frozen=True)
class OrderSweep:
    """Mesh-order amplitudes of the mesh and bearing forces over a speed sweep, per speed by either method."""

    speed_rpm: np.ndarray
    """driver speeds [rpm]"""
    mesh_frequency: np.ndarray
    """mesh frequency at each speed [Hz]"""
    dte_rms: np.ndarray
    """RMS of the dynamic transmission error [m]"""
    method: tuple[str, ...]
    """per speed: ``harmonic`` (harmonic balance) or ``time`` (time integration) [-]"""
    orders: np.ndarray
    """the mesh orders k reported (1 … K) [-]"""
    mesh_force_mean: np.ndarray
    """(speeds, 2) mean dynamic mesh force per helix [N]"""
    mesh_force_max: np.ndarray
    """(speeds, 2) largest dynamic mesh force per helix over the steady state (K_v: its ratio to the static one) [N]"""
    mesh_force: np.ndarray
    """(speeds, 2, K) amplitude of mesh order k of the dynamic mesh force per helix (left, right) [N]"""
    bearing_force: np.ndarray
    """(speeds, 4, 3, K) amplitude of mesh order k of the bearing-station loads (pinion-L/R, gear-L/R; x, y, z) [N]"""
    contact_margin: np.ndarray
    """(speeds, 2) the harmonic balance's lower bound of min(δ_s − b̄_s) (NaN where it did not apply) [m]"""
    warnings: tuple[str, ...]
    """what ran in the time domain and why [-]"""


def _ranges(speeds: np.ndarray, mask: np.ndarray) -> list[tuple[float, float, int]]:
    """(first, last, count) of the runs of consecutive True in ``mask``."""
    out, i = [], 0
    while i < mask.size:
        if mask[i]:
            j = i
            while j + 1 < mask.size and mask[j + 1]:
                j += 1
            out.append((float(speeds[i]), float(speeds[j]), j - i + 1))
            i = j
        i += 1
    return out


def harmonic_sweep(case: Case, speeds_rpm, *, method: str = "auto", orders: int = ORDERS,
                   harmonics: int | None = None, integrator: str | None = None, cycles: float = 100.0,
                   transient_cycles: float = 50.0, progress: Callable[[int], None] | None = None,
                   **build_kw) -> OrderSweep:
    """The sweep over ``speeds_rpm`` (module docstring); ``build_kw`` as for the model (``level``, ``stiffness``);
    ``integrator``, ``cycles``, ``transient_cycles``: the time-domain runs'; ``progress(done)`` after each speed."""
    from femgear.system.dynamics.run import run_dynamics

    if method not in METHODS:
        raise ValueError(f"method must be one of {', '.join(METHODS)} (got {method!r})")
    speeds = np.asarray(speeds_rpm, dtype=float)
    family = SpeedFamily(case, **build_kw)
    k = np.arange(1, orders + 1)
    S = speeds.size
    fm, dte = np.empty(S), np.empty(S)
    mean, peak = np.empty((S, 2)), np.empty((S, 2))
    force, bearing = np.empty((S, 2, orders)), np.empty((S, 4, 3, orders))
    margin = np.full((S, 2), np.nan)
    models = [family.at(rpm) for rpm in speeds]
    fm[:] = [m.mesh_frequency for m in models]
    reasons: list[str | None] = ["time integration asked for" if method == "time" else applies(m) for m in models]
    hb_idx = [i for i, r in enumerate(reasons) if r is None]
    done = 0
    for c in range(0, len(hb_idx), BATCH):
        chunk = hb_idx[c:c + BATCH]
        for i, hb in zip(chunk, harmonic_responses([models[i] for i in chunk], harmonics)):
            margin[i] = hb.contact_margin
            if not hb.contact_kept:
                reasons[i] = "the loaded flanks separate (backlash): the linear answer does not hold"
                continue
            dte[i], mean[i], peak[i] = hb.dte_rms, hb.mesh_force_mean, hb.mesh_force_peak()
            force[i] = hb.order_amplitudes(hb.mesh_force, k)
            bearing[i] = hb.order_amplitudes(hb.bearing_force, k)
            done += 1
        if progress is not None:
            progress(done)
    for i, reason in enumerate(reasons):
        if reason is None:
            continue
        model = models[i]
        run = run_dynamics(model, method=integrator, cycles=cycles, transient_cycles=transient_cycles)
        res = run.response
        dte[i], mean[i], peak[i] = res.amplitudes["dte_rms"], res.mesh_force.mean(axis=0), res.mesh_force.max(axis=0)
        force[i] = mesh_orders(res.mesh_force, res.t, model.mesh_frequency, orders).T
        bearing[i] = np.moveaxis(mesh_orders(res.bearings.force, res.t, model.mesh_frequency, orders), 0, -1)
        done += 1
        if progress is not None:
            progress(done)
    used = ["harmonic" if r is None else "time" for r in reasons]
    why_not = np.array(reasons, dtype=object)
    warnings = []
    if method != "time":
        for reason in sorted({r for r in why_not if r is not None}):
            for lo, hi, n in _ranges(speeds, np.array([r == reason for r in why_not])):
                span = f"{lo:.6g} rpm" if n == 1 else f"{lo:.6g}–{hi:.6g} rpm ({n} speeds)"
                warnings.append(f"{span}: time integration, harmonic balance does not apply: {reason}")
    return OrderSweep(speed_rpm=speeds, mesh_frequency=fm, dte_rms=dte, method=tuple(used), orders=k.astype(float),
                      mesh_force_mean=mean, mesh_force_max=peak, mesh_force=force, bearing_force=bearing, contact_margin=margin, warnings=tuple(warnings))
