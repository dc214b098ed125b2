"""Thermal flank deviations of the coupling loop: unit responses per member and the bulk temperature.

:class:`ThermalUnits` (:mod:`femgear.physics.body.thermal_units`) holds ζ_T(u) of both members for a
unit flank and a unit shaft rise of the case's thermal level, built by the level's factory in
:mod:`femgear.levels.thermal`; :func:`bulk_temperature_rise` is the body temperature the expansion follows.
"""

from __future__ import annotations

import numpy as np

from femgear.case import Case
from femgear.levels import thermal as thermal_levels
from femgear.physics.body.thermal_units import ThermalUnits, roll_distances

__all__ = ["ThermalUnits", "bulk_temperature_rise", "roll_distances", "thermal_units"]


def thermal_units(case: Case) -> ThermalUnits | None:
    """The unit responses of the case's thermal level (None for ``thermal = "none"``)."""
    return thermal_levels.of(case)


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
