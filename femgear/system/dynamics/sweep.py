"""Time-domain speed sweeps of the gear-rotor model (resonance search).

For each driver speed a fresh model is assembled (speed sets the mesh frequency, the
friction tables and the error phases), integrated from the static state over
``cycles`` mesh periods and measured over the last ``measure`` ones.  The dynamic
transmission error RMS against the mesh frequency peaks where a mesh harmonic meets a
natural frequency with mesh strain energy (compare :func:`femgear.system.dynamics.modal.modal_analysis`).
Each speed starts from the static state, so sweeps up and down coincide here; the
hysteresis of contact loss is shown with :mod:`femgear.system.dynamics.sdof`.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from femgear.case import Case
from femgear.system.dynamics.build import build_model
from femgear.system.dynamics.integrate import simulate
from femgear.system.dynamics.response import analyse


@dataclass(frozen=True)
class SpeedSweep:
    speed_rpm: np.ndarray        #: driver speeds [rev/min]
    mesh_frequency: np.ndarray   #: [Hz]
    dte_rms: np.ndarray          #: RMS of the dynamic transmission error [m]
    amplitudes: dict = field(default_factory=dict)  #: key -> array over speeds (see response.analyse)


def speed_sweep(case: Case, speeds_rpm, *, cycles: int = 100, measure: int = 40, steps_per_cycle: int | None = None,
                method: str | None = None, **build_kw) -> SpeedSweep:
    """DTE RMS and amplitudes over ``speeds_rpm`` (``build_kw`` go to :func:`build_model`).

    ``method`` and the step default to the dynamics' defaults at each speed
    (:func:`femgear.system.dynamics.run.default_step`: converged at low speed too);
    ``steps_per_cycle`` fixes the steps per mesh period instead.
    """
    from femgear.system.dynamics.run import default_method, default_step

    if measure >= cycles:
        raise ValueError(f"measure ({measure}) must be smaller than cycles ({cycles})")
    speeds = np.asarray(speeds_rpm, dtype=float)
    fm, dte = np.empty(speeds.size), np.empty(speeds.size)
    amps: dict = {}
    for i, rpm in enumerate(speeds):
        model = build_model(case.at_speed(rpm), **build_kw)
        T = model.mesh_period
        m = method or default_method(model)
        dt = T / steps_per_cycle if steps_per_cycle else default_step(model, m)
        sim = simulate(model, cycles * T, dt, m)
        res = analyse(sim, transient_cycles=cycles - measure)
        fm[i], dte[i] = model.mesh_frequency, res.amplitudes["dte_rms"]
        for k, v in res.amplitudes.items():
            amps.setdefault(k, np.empty(speeds.size))[i] = v
    return SpeedSweep(speed_rpm=speeds, mesh_frequency=fm, dte_rms=dte, amplitudes=amps)


def peak_frequency(x: np.ndarray, y: np.ndarray) -> float:
    """Location of the maximum of y(x) refined by a parabola through the three highest samples."""
    i = int(np.argmax(y))
    if i == 0 or i == y.size - 1:
        return float(x[i])
    x0, x1, x2 = x[i - 1:i + 2]
    y0, y1, y2 = y[i - 1:i + 2]
    den = (x0 - x1) * (x0 - x2) * (x1 - x2)
    a = (x2 * (y1 - y0) + x1 * (y0 - y2) + x0 * (y2 - y1)) / den
    b = (x2**2 * (y0 - y1) + x1**2 * (y2 - y0) + x0**2 * (y1 - y2)) / den
    return float(-b / (2 * a)) if a < 0 else float(x1)
