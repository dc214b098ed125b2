"""The recorded result of a time integration and the helpers all integrators share."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from femgear.docfields import document_fields
from femgear.system.dynamics.model import GearRotorModel


@document_fields
@dataclass(frozen=True)
class Simulation:
    """Recorded time history (reduced coordinates)."""

    model: GearRotorModel
    """the gear-rotor model that was integrated (built from the case; its inputs are the scene's) [-]"""
    method: str
    """the time integrator [-]"""
    dt: float
    """time step [s]"""
    t: np.ndarray
    """recorded times [s]"""
    q: np.ndarray
    """(n_rec, n) displacements in the model's reduced coordinates (full = T q: translations and rotations) [m, rad]"""
    v: np.ndarray
    """(n_rec, n) velocities in the reduced coordinates [m/s, rad/s]"""
    seconds: float
    """wall time of the integration loop [s]"""
    steps: int
    """time steps integrated [-]"""
    info: dict = field(default_factory=dict, compare=False)
    """the integrator's counters: steps per mesh period, set-up seconds, contact switches, solves … (by integrator) [-]"""


def inputs(model: GearRotorModel, t: np.ndarray):
    ph = model.mesh_phase(t)
    kL, kR = model.stiffness(ph)
    e, ed = model.errors(t)
    f = model.external_force(t)
    if model.mu > 0 and model.friction is not None:
        A, B = model.friction(ph)
    else:
        A = B = np.zeros((2,) + t.shape)
    return kL, kR, e, ed, f, A, B


def record_plan(steps: int, dt: float, record_every: int, record_from: float) -> np.ndarray:
    """The step indices recorded: every ``record_every``-th with t = idx·dt ≥ ``record_from``.  The
    tolerance (10⁻⁶ of a step) absorbs the rounding of idx·dt against a ``record_from`` that is a whole
    number of steps: n·(T/n) can fall ~10⁻¹⁴ T short of T, and with 10⁻¹² dt a transient ending exactly
    at ``record_from`` recorded nothing (its last state was then read from an empty array)."""
    idx = np.arange(0, steps + 1, record_every)
    return idx[idx * dt >= record_from - 1e-6 * dt]


