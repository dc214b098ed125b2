"""Thermal flank deviations of the coupling loop: unit responses per member and the bulk temperature.

:class:`ThermalUnits` holds ζ_T(u) of both members for a unit flank and a unit shaft rise of the
case's thermal level (linear problems: any rise is a combination), and with ``thermal = "fe3d"``
the 3-D unit solutions for the face-resolved growth; :func:`bulk_temperature_rise` is the body
temperature the expansion follows.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from femgear.case import Case


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


def thermal_units(case: Case) -> ThermalUnits | None:
    """The unit responses of the case's thermal level (None for ``thermal = "none"``)."""
    if case.levels.thermal == "none":
        return None
    from femgear.physics.body.thermal import flank_deviation

    m = case.material
    members = ((1, case.bore_radii[0]), (2, case.bore_radii[1]))
    if case.levels.thermal == "fe3d":
        return _thermal_units_3d(case, members)

    def unit(member: int, bore: float, flank: float, shaft: float) -> np.ndarray:
        return flank_deviation(case.pair, member, case.path.u, case.levels.thermal, flank, shaft, m.thermal_expansion,
                               m.youngs_modulus, m.poisson_ratio, m.conductivity, bore, case.thermal.mesh_size,
                               case.groove_width, case.stagger)

    return ThermalUnits(flank=np.array([unit(j, b, 1.0, 0.0) for j, b in members]),
                        shaft=np.array([unit(j, b, 0.0, 1.0) for j, b in members]))


def _thermal_units_3d(case: Case, members) -> ThermalUnits:
    """``fe3d``: the members' 3-D unit solutions and their face means along the path (the values of
    :func:`femgear.physics.body.thermal.flank_deviation`, which reads the same cached solutions)."""
    from femgear.physics.ltca.thermal import thermal_units_3d

    m = case.material
    bodies = tuple(thermal_units_3d(case.pair, j, m.thermal_expansion, m.youngs_modulus, m.poisson_ratio, b,
                                    case.groove_width, case.stagger, level=case.numerics.body_level)
                   for j, b in members)
    return ThermalUnits.from_bodies(bodies, roll_distances(case.pair, case.path.u))


def roll_distances(pair, u: np.ndarray) -> np.ndarray:
    """(2, n) roll distances of the flank points at the path positions ``u``: pinion ρ₁ = u, gear ρ₂ = T₁T₂ − u."""
    u = np.asarray(u, float)
    return np.array([u, pair.line_of_action - u])


def bulk_temperature_rise(case: Case, contact_rise: np.ndarray) -> float:
    """Bulk (body) temperature rise of the flanks over the oil [K].

    ``thermal.flank_temperature_rise`` when given (> 0); otherwise the integral-
    temperature estimate of ISO/TS 6336-21 (formerly ISO/TR 13989-2):
    θ_M − θ_oil = C_1 X_mp θ_fla,int, with θ_fla,int the mean contact temperature rise
    along the path of contact, C_1 = ``thermal.bulk_fraction`` (ISO: 0.7) and X_mp = 1
    (one mesh per member).  The flash temperature itself reaches only some tens of µm
    into the tooth; the body's expansion follows this bulk temperature.
    """
    given = case.thermal.flank_temperature_rise
    return float(given) if given > 0 else case.thermal.bulk_fraction * float(np.mean(contact_rise))
