"""Thermal flank deviation ζ_T(u) of both members for a unit flank and a unit shaft rise (linear problems:
any rise is a combination), the product of the thermal levels (:mod:`femgear.levels.thermal`)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class ThermalUnits:
    """Thermal flank deviation ζ_T(u) of both members for a unit flank and a unit shaft rise [m/K].

    The conduction and thermo-elastic problems are linear, so ζ_T = ΔT_flank z_flank +
    ΔT_shaft z_shaft: one solve per member and unit load, however many passes follow.
    """

    flank: np.ndarray   #: (2, n) pinion, gear
    shaft: np.ndarray   #: (2, n)
    #: ``thermal = "fe3d"``: the 3-D unit solutions of pinion and gear
    #: (:class:`femgear.physics.ltca.thermal.Thermal3DUnits`), whose face means are ``flank`` and ``shaft``; None otherwise
    bodies: tuple | None = None

    def deviation(self, flank_rise: float, shaft_rise: float) -> np.ndarray:
        return flank_rise * self.flank + shaft_rise * self.shaft

    @classmethod
    def from_bodies(cls, bodies: tuple, rho: np.ndarray) -> ThermalUnits:
        """From the 3-D unit solutions of pinion and gear: their face means at the roll distances ``rho`` (2, n)."""
        return cls(flank=np.array([body.face_mean(r, 1.0, 0.0) for body, r in zip(bodies, rho)]),
                   shaft=np.array([body.face_mean(r, 0.0, 1.0) for body, r in zip(bodies, rho)]), bodies=tuple(bodies))

    def face(self, rho: np.ndarray, grid: np.ndarray, flank_rise: float, shaft_rise: float) -> np.ndarray | None:
        """Face-resolved ζ_T (member, helix, u, ζ) [m] at the members' roll distances ``rho`` (2, n) (pinion
        ρ₁ = u, gear ρ₂ = T₁T₂ − u) and face coordinates ``grid`` (m,) of each helix, from the 3-D unit
        solutions (:meth:`femgear.physics.ltca.thermal.Thermal3DUnits.face_field`); None without them.

        Its face mean over both helices (trapezoid on ``grid``) is :meth:`deviation` up to the bilinear
        reading of the units' ζ grid on ``grid`` (the same ρ interpolation: both are linear in ρ)."""
        if self.bodies is None:
            return None
        return np.array([body.face_field(r, grid, flank_rise, shaft_rise) for body, r in zip(self.bodies, rho)])


def roll_distances(pair, u: np.ndarray) -> np.ndarray:
    """(2, n) roll distances of the flank points at the path positions ``u``: pinion ρ₁ = u, gear ρ₂ = T₁T₂ − u."""
    u = np.asarray(u, float)
    return np.array([u, pair.line_of_action - u])
