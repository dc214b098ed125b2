"""The quasi-static contact pass along the path of contact of a scene's gear pair.

At each position the load per unit contact-line length is the time-mean value
w' = F_bn / (2 L̄), F_bn = T1/(r_b1 cos β_b) shared by the two helices, each with the
mean contact-line length L̄ = ε_α b / cos β_b (uniform load along the lines, as ISO
6336 assumes).  Each position is then a Hertz line contact of radius R (normal
section) with the film formulas of :mod:`femgear.contact.film`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from femgear.contact.film import line_film
from femgear.contact.hertz import hertz_line, reduced_modulus
from femgear.geometry import GearPair, PathKinematics, kinematics, path_positions


@dataclass(frozen=True)
class ContactPath:
    """Contact quantities along the path of contact (arrays over positions)."""

    kin: PathKinematics
    normal_force: float        #: F_bn, both helices [N]
    load_per_length: float     #: w' [N/m]
    hertz_half_width: np.ndarray  #: b_H [m]
    hertz_pressure: np.ndarray    #: p_H [Pa]
    film_central: np.ndarray      #: h_c, Moes line formula [m]
    film_central_dt: np.ndarray   #: h_c, Dowson–Toyoda [m]
    film_minimum: np.ndarray      #: h_min, Dowson–Higginson [m]
    moes_M: np.ndarray
    moes_L: np.ndarray
    pitch_index: int              #: index of the position nearest the pitch point


def pinion_speed(scene) -> float:
    """Pinion speed [rev/min] from the driving member's speed."""
    op = scene.operating
    return op.speed_rpm if op.driver == "pinion" else op.speed_rpm * scene.gear.teeth / scene.pinion.teeth


def pinion_torque(scene) -> float:
    """Torque on the pinion [N m] (losses neglected)."""
    op = scene.operating
    return op.torque if op.driver == "pinion" else op.torque * scene.pinion.teeth / scene.gear.teeth


def normal_force(scene, pair: GearPair) -> float:
    """Normal mesh force of the pair, both helices: F_bn = T1 / (r_b1 cos β_b) [N]."""
    return pinion_torque(scene) / (pair.rb1 * math.cos(pair.beta_b))


def contact_along_path(scene, n: int | None = None, pair: GearPair | None = None) -> ContactPath:
    """Hertz pressure, films and velocities at ``n`` positions from A to E."""
    pair = pair or GearPair.from_scene(scene)
    n = n or scene.numerics.path_points
    u = path_positions(pair, n)
    # include the pitch point exactly so that pitch-point figures are not interpolated
    u = np.unique(np.append(u, pair.u_pitch))
    omega1 = pinion_speed(scene) * 2 * math.pi / 60
    kin = kinematics(pair, u, omega1)
    F_bn = normal_force(scene, pair)
    w = F_bn / (2 * pair.mean_contact_length)
    E_red = reduced_modulus(scene.material.youngs_modulus, scene.material.poisson_ratio)
    hertz = [hertz_line(w, R, E_red) for R in kin.R]
    films = line_film(w, kin.R, kin.ue, E_red, scene.oil.viscosity, scene.oil.pressure_viscosity)
    return ContactPath(
        kin=kin, normal_force=F_bn, load_per_length=w,
        hertz_half_width=np.array([h.half_width for h in hertz]),
        hertz_pressure=np.array([h.max_pressure for h in hertz]),
        film_central=films["central_moes"], film_central_dt=films["central_dt"],
        film_minimum=films["minimum_dh"], moes_M=films["M"], moes_L=films["L"],
        pitch_index=int(np.argmin(np.abs(u - pair.u_pitch))),
    )
