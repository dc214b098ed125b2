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
from femgear.docfields import document_fields
from femgear.levels.lubrication import LevelFilm
from femgear.physics.body.fields import BodySection
from femgear.physics.contact.path import ContactPath
from femgear.physics.ltca.maps import LoadMaps
from femgear.physics.ltca.te import TEAnalysis
from femgear.physics.lubrication.map import MapError
from femgear.physics.rating import MeshPowerLoss, PittingRating
from femgear.physics.rating.suite import PairRating
from femgear.physics.stiffness.iso6336 import IsoStiffness
from femgear.physics.stiffness.tvms import MeshStiffness
from femgear.system.coupling.state import CoupledResult
from femgear.system.dynamics.housing_result import HousingResult


@document_fields
@dataclass(frozen=True)
class Tribology:
    """Lubrication, thermal expansion and wear along the case's path grid (None: level off)."""

    load_per_length: np.ndarray
    """passage-mean load per unit contact-line length w̄' at the case's path positions case.path.u (measured from T1),
    per helix; static runs: the contact pass's shared line load [N/m]"""
    friction_coefficient: np.ndarray | None
    """friction coefficient μ of the lubrication level at each path position (None: lubrication off) [-]"""
    temperature_rise: np.ndarray | None
    """contact (flash) temperature rise ΔT of the lubrication level at each path position (None: lubrication off) [K]"""
    flank_temperature_rise: float
    """bulk (body) temperature rise of both flanks that drives the thermal expansion [K]"""
    thermal_deviation: np.ndarray | None
    """(2, n) thermal growth ζ_T of the pinion (row 0) and gear (row 1) flank along the path, normal to the flank, + =
    material added (None: thermal off) [m]"""
    wear: np.ndarray | None
    """(2, n) wear depth of the pinion (row 0) and gear (row 1) flank along the path, normal to the flank (None: wear
    off) [m]"""
    wear_cycles: float = 0.0
    """pinion revolutions of accumulated wear [rev]"""
    wear_steps: int = 0
    """update steps the wear integration took [-]"""
    wear_load: str | None = None
    """the load that wore, ``wear.load``: "asperity" (the asperity-borne part) or "total" (the whole load; None: wear
    off) [-]"""
    wear_film_parameter: float | None = None
    """smallest film parameter λ = h/σ along the path at ``load_per_length``, of the JGP split the asperity-borne
    wear takes (None: wear off) [-]"""
    wear_asperity_share: float | None = None
    """largest share of the load the asperities carry along the path at ``load_per_length`` (None: wear off) [-]"""
    wear_warnings: tuple[str, ...] = ()
    """what the wear result does not support, one ``key: message`` each (the constant-coefficient form on a pair
    whose film carries the load) [-]"""
    face_grid: np.ndarray | None = None
    """(m,) face coordinate ζ of the face-resolved fields, 0 … b of each helix (``wear.field = "face"`` or ``thermal =
    "fe3d"``; else None) [m]"""
    wear_face: np.ndarray | None = None
    """(member, helix, n, m) wear depth over path position and face grid, ``wear.field = "face"`` (else None) [m]"""
    thermal_face: np.ndarray | None = None
    """(member, helix, n, m) thermal growth ζ_T over path position and face grid, ``thermal = "fe3d"`` (else None) [m]"""
    film: LevelFilm | None = None
    """the film of the lubrication level that ran, at ``load_per_length`` (:mod:`femgear.levels.lubrication`;
    None: lubrication off) [-]"""
    friction_map_error: MapError | None = None
    """the measured error of the friction map that stood in for the lubrication level's solves, beside its tolerance
    (:class:`femgear.physics.lubrication.map.MapError`; ``tehl`` with dynamics; None: direct solves) [-]"""


@document_fields
@dataclass(frozen=True)
class ContactFigures:
    """Figures of the quasi-static contact at the operating point, computed by the driver
    (:func:`femgear.rate.contact_figures`) and only formatted by :mod:`femgear.summary`."""

    pitting: PittingRating
    """ISO 6336-2 method B pitting rating of the ``[rating]`` table (also when the full rating of
    :class:`PairRating` could not be computed) [-]"""
    iso_stiffness: IsoStiffness
    """ISO 6336-1:2019 method B single and mesh stiffness per unit face width, at ``iso_line_load`` [N/(mm µm)]"""
    iso_line_load: float
    """the line load F_t K_A / b of one helix the ISO stiffness is evaluated at [N/m]"""
    friction_level: str
    """the lubrication level whose μ(u) the flash temperature and the power loss use: the run's own
    (``femgear info``: the scene's level at the static load) [-]"""
    flash_position: np.ndarray
    """path coordinate s of the flash temperature values (0 at the pitch point) [m]"""
    flash_temperature: np.ndarray
    """Blok's maximum flash temperature at ``flash_position``, with μ of ``friction_level`` and the
    contact pass's line load [K]"""
    power_loss: MeshPowerLoss
    """mesh power loss of μ(u) of ``friction_level`` at the contact pass's line load (its fields carry
    their units) [-]"""
    power_loss_iso: MeshPowerLoss | None = None
    """the same mesh power loss with ISO/TS 6336-20's constant μ_mC instead of femgear's μ(u), beside it (None: no
    rating) [-]"""


@document_fields
@dataclass(frozen=True)
class RunResult:
    """Everything one run computed."""

    case: Case
    """the case the run computed: pair, operating point, path positions, levels (its inputs are documented by the scene
    schema) [-]"""
    contact: ContactPath
    """the quasi-static contact pass along the path of contact: Hertz pressure, films, kinematics, load sharing [-]"""
    stiffness: MeshStiffness
    """the mesh stiffness of the ``stiffness`` level over one mesh period, along the normal line of action [-]"""
    tribology: Tribology
    """friction, temperatures, thermal growth and wear along the path (static, or the coupled loop's last state) [-]"""
    coupled: CoupledResult | None = None
    """with a dynamics level: the coupling loop's last state, its history and convergence (else None) [-]"""
    seconds: float = 0.0
    """wall time of the whole run [s]"""
    transmission_error: TEAnalysis | None = None
    """``stiffness = "ltca"``: loaded TE, its harmonics, stiffness, load share and peak pressure of the LTCA cycle of
    the stiffness level (new flanks with the scene's modifications, operating torque); else None [-]"""
    rating: PairRating | None = None
    """ISO 6336-2/-3, ISO/TS 6336-20/21/22 ratings beside femgear's own figures (:func:`femgear.rate.rate_case`); None
    when the rating could not be computed (logged) [-]"""
    figures: ContactFigures | None = None
    """ISO 6336-2 pitting, ISO 6336-1 stiffness, flash temperature and mesh power loss of the run's own μ
    (:func:`femgear.rate.contact_figures`; its fields carry their units) [-]"""
    body: tuple[BodySection, BodySection] | None = None
    """``thermal = "fe"``: the FE gear sections of pinion and gear at the run's flank and shaft rises
    (:func:`femgear.stages.body_sections`; its fields carry their units) [-]"""
    ltca_maps: LoadMaps | None = None
    """``stiffness = "ltca"``: the LTCA's pressure and load maps on the loaded flanks of both members in
    mesh (:func:`femgear.physics.ltca.maps.load_maps`, the stiffness level's cycle; ``w_worst`` at the phase
    of the largest pressure) [-]"""
    static_bearing_loads: np.ndarray | None = None
    """without a dynamics level: (4, 3) loads of the bearing stations (pinion_L, pinion_R, gear_L, gear_R; x, y
    radial, z axial) at the static load, on the scene's mounting with rigid shafts and no friction
    (:func:`femgear.stages.static_bearings`); with dynamics the dynamic run's own loads are in ``coupled`` [N]"""
    housing: HousingResult | None = None
    """with ``[housing]``: sensor accelerations, bearing and mesh forces and (FE) radiated power per mesh order over
    speed and at the operating point, and the FE housing's deflection shape
    (:func:`femgear.stages.housing_fields`; docs/models/housing.md) [-]"""


#: types reachable from :class:`RunResult` whose fields are inputs documented elsewhere (the Case and its gear pair:
#: the scene schema; the gear-rotor model the dynamics builds from them): the field docs and the ``units`` table of
#: ``results.json`` (:func:`femgear.docfields.units_table`) stop there
INPUT_TYPES = ("Case", "GearPair", "GearRotorModel")
