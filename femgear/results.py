"""Typed results of a run (:func:`femgear.pipeline.run_case`), read by every writer and plot.

:class:`RunResult` is the one object a run produces: the case, the quasi-static contact
pass, the mesh stiffness, the tribology along the case's path grid and, with dynamics,
the coupled result.  The JSON layout written from it (:mod:`femgear.edge.io.run`) is the
documented contract of ``results.json``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from femgear.case import Case
from femgear.levels.lubrication import LevelFilm
from femgear.physics.contact.path import ContactPath
from femgear.physics.ltca.te import TEAnalysis
from femgear.physics.rating.suite import PairRating
from femgear.physics.stiffness.tvms import MeshStiffness
from femgear.system.coupling.loop import CoupledResult


@dataclass(frozen=True)
class Tribology:
    """Lubrication, thermal expansion and wear along the case's path grid (None: level off)."""

    load_per_length: np.ndarray                 #: w̄' [N/m] (static: the time-mean w')
    friction_coefficient: np.ndarray | None     #: μ [-]
    temperature_rise: np.ndarray | None         #: contact temperature rise [K]
    flank_temperature_rise: float               #: bulk temperature rise driving the expansion [K]
    thermal_deviation: np.ndarray | None        #: (2, n) ζ_T pinion, gear [m]
    wear: np.ndarray | None                     #: (2, n) wear depth pinion, gear [m]
    wear_cycles: float = 0.0                    #: pinion revolutions of accumulated wear
    wear_steps: int = 0                         #: update steps of the wear integration
    #: face grid ζ (m,) of each helix [m] of the face-resolved fields (``wear.field = "face"`` or ``thermal = "fe3d"``)
    face_grid: np.ndarray | None = None
    wear_face: np.ndarray | None = None         #: (member, helix, n, m) wear depth, ``wear.field = "face"`` [m]
    thermal_face: np.ndarray | None = None      #: (member, helix, n, m) ζ_T of ``thermal = "fe3d"`` [m]
    #: the film of the lubrication level that ran, at ``load_per_length`` (:meth:`femgear.levels.lubrication.Lubrication.film`)
    film: LevelFilm | None = None


@dataclass(frozen=True)
class RunResult:
    """Everything one run computed."""

    case: Case
    contact: ContactPath
    stiffness: MeshStiffness
    tribology: Tribology
    coupled: CoupledResult | None = None        #: with a dynamics level
    seconds: float = 0.0
    #: ``stiffness = "ltca"``: loaded TE, its harmonics, stiffness, load share and peak pressure of the LTCA
    #: cycle of the stiffness level (new flanks with the scene's modifications, operating torque)
    transmission_error: TEAnalysis | None = None
    #: ISO 6336-2/-3, ISO/TS 6336-20/21/22 ratings beside femgear's own figures (:func:`femgear.rate.rate_case`);
    #: None when the rating could not be computed (logged)
    rating: PairRating | None = None
