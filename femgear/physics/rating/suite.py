"""All four ISO ratings of one pair, with their validity flags, and femgear's own figures beside them.

:func:`rate_pair` is pure (a :class:`femgear.physics.geometry.GearPair`, numbers and typed inputs);
the driver binds a scene to it (:mod:`femgear.rate`) and carries the frozen
:class:`PairRating` on the run's result.  ``flags`` lists, per safety factor, the inputs
outside the range a method was made for (each ``"S_x: key = value outside …"``); the
factor is still computed.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from femgear.docfields import document_fields
from femgear.physics.body.fillet import FilletStress
from femgear.physics.geometry.gear import GearPair
from femgear.physics.rating.bending import BendingInputs, BendingRating, bending_rating
from femgear.physics.rating.load_factors import RatingFactors
from femgear.physics.rating.micropitting import MicropittingRating, micropitting_rating
from femgear.physics.rating.permissible import PittingRating
from femgear.physics.rating.scuffing import ScuffingInputs, ScuffingRating, scuffing_rating


@document_fields
@dataclass(frozen=True)
class OwnFigures:
    """femgear's own physics beside the ISO figures (None where not computed)."""

    u: np.ndarray
    """path positions of the contact pass, measured from T1 along the transverse line of action [m]"""
    film: np.ndarray
    """minimum film thickness of the contact pass [m]"""
    film_level: str
    """which film the figures use, in words ("formula: h_min of …", or the contact pass's Dowson–Higginson h_min) [-]"""
    specific_film: np.ndarray
    """specific film thickness λ = h / R_a along the path (R_a the mean of both flanks) [-]"""
    temperature: np.ndarray | None
    """contact temperature along the path: ambient (oil supply) + flank bulk rise + contact rise ΔT of the lubrication
    level (None: not computed) [K]"""
    temperature_level: str | None
    """the lubrication level that gave ΔT (None: not computed) [-]"""
    fillet: tuple[FilletStress, FilletStress] | None = None
    """FE largest principal fillet stress of the pinion and the gear (None: not computed) [-]"""

    @property
    def lambda_min(self) -> float:
        return float(np.min(self.specific_film))

    @property
    def max_temperature(self) -> float | None:
        return None if self.temperature is None else float(np.max(self.temperature))


@document_fields
@dataclass(frozen=True)
class PairRating:
    """Pitting, bending, scuffing and micropitting of one pair (all frozen results)."""

    pitting: PittingRating
    """ISO 6336-2 pitting: contact stress, permissible stress and safety S_H [-]"""
    bending: BendingRating
    """ISO 6336-3 tooth-root bending: root stress, permissible stress and safety S_F [-]"""
    scuffing: ScuffingRating
    """ISO/TS 6336-20/21 scuffing: flash and integral temperatures and safeties S_B, S_intS [-]"""
    micropitting: MicropittingRating
    """ISO/TS 6336-22 micropitting: specific film thickness and safety S_λ [-]"""
    flags: tuple[str, ...] = ()
    """inputs outside a standard's range, each prefixed with the safety factor it concerns ("S_F: …") [-]"""
    defaults: tuple[str, ...] = ()
    """the ``[rating]`` keys that took their documented default [-]"""
    own: OwnFigures | None = None
    """femgear's own film, specific film, contact temperature and FE fillet stress beside the ISO figures [-]"""
    factors: RatingFactors | None = None
    """K_v, K_Hβ, K_Hα the ratings used, each with its source and ISO 6336-1's value beside (None: not bound) [-]"""

    @property
    def safety_factors(self) -> dict[str, float]:
        """The smallest of each: S_H, S_F (per member minimum), S_B, S_intS, S_λ."""
        return {"S_H": min(self.pitting.S_H), "S_F": min(self.bending.S_F), "S_B": self.scuffing.S_B,
                "S_intS": self.scuffing.S_intS, "S_lambda": self.micropitting.S_lambda}

    def flagged(self, factor: str) -> bool:
        return any(f.startswith(factor + ":") for f in self.flags)


def validity_flags(pair: GearPair, bending: BendingRating, pitch_line_velocity: float) -> tuple[str, ...]:
    """Inputs outside the ranges of ISO 6336-3, ISO/TS 6336-20/21 and ISO/TS 6336-22."""
    flags = []
    for name, g in zip(("pinion", "gear"), bending.root, strict=True):
        if not 1 <= g.q_s < 8:
            flags.append(f"S_F: {name} notch parameter q_s = {g.q_s:.3g} outside ISO 6336-3's 1 ≤ q_s < 8 (Y_S)")
    for name, rz in zip(("pinion", "gear"), bending.inputs.root_Rz, strict=True):
        if rz > 40e-6:
            flags.append(f"S_F: rating.root_roughness_rz ({name}) = {rz * 1e6:.3g} µm above ISO 6336-3's 40 µm (Y_RrelT)")
    eps_an = pair.eps_alpha / math.cos(pair.beta_b) ** 2
    if eps_an > 2.05:
        flags.append(f"S_F: virtual contact ratio ε_αn = {eps_an:.3g} > 2.05: Y_DT < 1 needs accuracy grade ≤ 4 "
                     "(Y_DT = 1 applied)")
    beta = math.degrees(pair.beta)
    if beta > 30:
        flags.append(f"S_F: pair.helix_angle_deg = {beta:.3g} above ISO 6336-3's 30° (Y_β)")
    if beta > 25:
        flags.append(f"S_lambda: pair.helix_angle_deg = {beta:.3g} above ISO/TS 6336-22's 25°")
    if pitch_line_velocity < 2:
        flags.append(f"S_lambda: pitch line velocity {pitch_line_velocity:.3g} m/s below ISO/TS 6336-22's 2 m/s "
                     "(operating.speed_rpm)")
    if math.degrees(pair.alpha_wt) > 25:
        flags.append(f"S_lambda: working pressure angle {math.degrees(pair.alpha_wt):.3g}° above ISO/TS 6336-22's 25°")
    if pair.eps_alpha >= 2:
        flags.append(f"S_B: ε_α = {pair.eps_alpha:.3g} ≥ 2: the load sharing X_Γ of ISO/TS 6336-20 is for ε_α < 2 "
                     "(1/ε_α used)")
    return tuple(flags)


def rate_pair(pair: GearPair, pitting: PittingRating, pinion_torque: float, pinion_rpm: float,
              bending: BendingInputs, scuffing: ScuffingInputs, scuffing_stage: float, micropitting_stage: float,
              viscosity: Callable[[float], float], pressure_viscosity: float | Callable[[float], float],
              own: OwnFigures | None = None, defaults: tuple[str, ...] = ()) -> PairRating:
    """The four ratings of ``pair`` (``pitting`` computed by :func:`femgear.physics.rating.pitting_rating`)."""
    b = bending_rating(pair, pinion_torque, pinion_rpm, bending)
    s = scuffing_rating(pair, pinion_torque, pinion_rpm, scuffing, scuffing_stage, viscosity(363.15))
    m = micropitting_rating(pair, pinion_torque, pinion_rpm, scuffing, viscosity, pressure_viscosity,
                            micropitting_stage)
    flags = validity_flags(pair, b, pitting.pitch_line_velocity)
    return PairRating(pitting=pitting, bending=b, scuffing=s, micropitting=m, flags=flags, defaults=defaults, own=own)
