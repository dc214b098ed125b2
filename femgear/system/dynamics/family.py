"""The gear-rotor models of one case at many driver speeds, built once and re-speeded cheaply.

A speed sweep, a harmonic-balance continuation or a run-up needs the model at many speeds.
:func:`femgear.system.dynamics.build.build_model` at each speed re-assembles what does not
depend on speed (the structure, the mesh-stiffness level, the Rayleigh fit on the modes, the
contact lines of the friction tables, the static contact pass that shares the load): 44 ms a
speed on the baseline.  :class:`SpeedFamily` builds those once and, per speed, replaces only
what the speed sets:

- the mesh frequency, the member speeds and the nominal rotation rate;
- the excitations that run with the members (eccentricity, unbalance, profile and pitch errors);
- the friction: μ of the lubrication level at that speed (``static_friction`` on the cached
  line load) and the sliding-sign tables on the cached contact-line points.

``family.at(rpm)`` equals ``build_model(case.at_speed(rpm), ...)`` field by field (tested).
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from femgear.case import Case
from femgear.system.dynamics.build import Friction, build_model, excitations, with_friction
from femgear.system.dynamics.layout import NDOF
from femgear.system.dynamics.mesh import FrictionLines, friction_lines
from femgear.system.dynamics.model import GearRotorModel


class SpeedFamily:
    """The models of ``case`` at any driver speed [rpm]; ``build_kw`` as for :func:`build_model`
    (``friction`` given: that μ at every speed, else the lubrication level's at each speed)."""

    def __init__(self, case: Case, level: str | None = None, *, friction: Friction | None = None, **build_kw):
        self.case = case
        self._friction = friction
        self._base = build_model(case, level, friction=0.0, **build_kw)
        self._lines: FrictionLines | None = None
        self._line_load: np.ndarray | None = None

    @property
    def base(self) -> GearRotorModel:
        """The model at the case's own speed, without friction [-]."""
        return self._base

    def _mu(self, case: Case) -> Friction:
        if self._friction is not None:
            return self._friction
        from femgear.levels.lubrication import lubrication_solver, static_friction

        if lubrication_solver(case).uniform is None and self._line_load is None:
            from femgear.levels.contact import contact_pass

            self._line_load = contact_pass(case).line_load
        return static_friction(case, self._line_load)

    def at(self, rpm: float) -> GearRotorModel:
        """The model at the driver speed ``rpm`` [rev/min]."""
        case = self.case.at_speed(float(rpm))
        omega, fm = case.omega, case.operating.mesh_frequency
        rate = np.zeros(NDOF)
        for side in range(2):
            rate[6 * side + 5], rate[6 * (2 + side) + 5] = omega
        profile, rnd, ecc, unb = excitations(case, omega, fm)
        model = replace(self._base, mesh_frequency=fm, omega=omega, nominal_rate=rate, profile_errors=profile,
                        random_errors=rnd, eccentricities=ecc, unbalances=unb)
        mu = self._mu(case)
        if callable(mu) or mu > 0:
            if self._lines is None:
                self._lines = friction_lines(model.pair, model.stagger)
            return with_friction(model, mu, self._lines)
        return with_friction(model, mu)
