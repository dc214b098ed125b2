"""The quasi-static contact pass along the path of contact of a scene's gear pair.

The normal force F_bn = T1/(r_b1 cos β_b) is shared by the helices (two for a
double-helical pair).  Along the path, the load per unit contact-line length
``line_load`` w(u) comes from the load sharing between the tooth pairs in contact
(:mod:`femgear.physics.contact.sharing`, with the pair stiffness k'(u) of the scene's
mesh-stiffness level): the single-pair load F_n/b in the single-contact zone of a spur
pair, contact-line sharing for helical pairs.  Each position is then a Hertz line
contact of radius R (normal section) under w(u) with the film formulas of
:mod:`femgear.physics.contact.film`.  ``load_per_length`` keeps the time mean over the path,
w̄' = F_n / L̄ with L̄ = ε_α b / cos β_b (ISO 6336's uniform load), for the callers that
take one load.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from femgear.docfields import document_fields
from femgear.physics.contact.film import line_film
from femgear.physics.contact.hertz import hertz_line, reduced_modulus
from femgear.physics.contact.sharing import LoadSharing, StiffnessPerWidth, load_sharing, single_contact_bounds
from femgear.physics.geometry import GearPair, PathKinematics, kinematics, path_positions


@document_fields
@dataclass(frozen=True)
class ContactPath:
    """Contact quantities along the path of contact (arrays over positions)."""

    kin: PathKinematics
    """the path positions u (measured from T1 along the transverse line of action) with radii, curvatures and speeds [-]"""
    normal_force: float
    """total normal force F_bn of all helices (driver torque / r_b / cos β_b) [N]"""
    load_per_length: float
    """time mean over the path of the load per unit contact-line length, w̄' = F_n / L̄ per helix [N/m]"""
    hertz_half_width: np.ndarray
    """Hertz half-width b_H of the line contact at each path position [m]"""
    hertz_pressure: np.ndarray
    """Hertz peak pressure p_H at each path position, under the shared line load ``line_load`` [Pa]"""
    film_central: np.ndarray
    """central film thickness h_c at each path position, Moes line-contact formula [m]"""
    film_central_dt: np.ndarray
    """central film thickness h_c at each path position, Dowson–Toyoda [m]"""
    film_minimum: np.ndarray
    """minimum film thickness h_min at each path position, Dowson–Higginson [m]"""
    moes_M: np.ndarray
    """Moes dimensionless load parameter M at each path position [-]"""
    moes_L: np.ndarray
    """Moes dimensionless lubricant parameter L at each path position [-]"""
    pitch_index: int
    """index into the path positions of the one nearest the pitch point C [-]"""
    line_load: np.ndarray | None = None
    """load per unit contact-line length w(u) from the load sharing between the pairs in contact (Hertz and films use
    it) [N/m]"""
    line_load_max: np.ndarray | None = None
    """helical: the largest w over the mesh phases at each u [N/m]"""
    load_fraction: np.ndarray | None = None
    """share of one helix's force carried by the contact line through u [-]"""
    single_contact: tuple[float, float] = (math.nan, math.nan)
    """(u_B, u_D): the inner points of single tooth-pair contact, measured from T1 (NaN for helical pairs without one)
    [m]"""
    n_helices: int = 2
    """helices of the pair: 2 double-helical, 1 single-helical or spur [-]"""

    def at(self, u: float) -> int:
        """Index of the position nearest ``u`` [m]."""
        return int(np.argmin(np.abs(self.kin.u - u)))


def pinion_speed(scene) -> float:
    """Pinion speed [rev/min] from the driving member's speed."""
    return scene.pinion_rpm


def pinion_torque(scene) -> float:
    """Torque on the pinion [N m] (losses neglected)."""
    op = scene.operating
    return op.torque if op.driver == "pinion" else op.torque * scene.pinion.teeth / scene.gear.teeth


def normal_force(scene, pair: GearPair) -> float:
    """Normal mesh force of the pair, all helices: F_bn = T1 / (r_b1 cos β_b) [N]."""
    return pinion_torque(scene) / (pair.rb1 * math.cos(pair.beta_b))


def zone_grid(pair: GearPair, n: int) -> np.ndarray:
    """``n`` positions from A to E plus the pitch point and, for a spur pair, both sides of the
    load jumps at B and D (the outer side 1e-7 p_bt away), so that path integrals of the
    piecewise load are exact up to the smooth parts' trapezoid error [m]."""
    u = np.append(path_positions(pair, n), pair.u_pitch)
    if pair.beta_b == 0:
        u_B, u_D = single_contact_bounds(pair)
        eps = 1e-7 * pair.p_bt
        u = np.append(u, [u_B - eps, u_B, u_D, u_D + eps])
    return np.unique(u)


def pair_stiffness_curve(scene, pair: GearPair, stiffness=None) -> StiffnessPerWidth | None:
    """k'(u) of the scene's mesh-stiffness level for load sharing (None: uniform).

    ``constant`` and ``iso6336`` are uniform along the path.  ``pem`` is evaluated here;
    ``fe`` uses the FE curve of a given :class:`femgear.physics.stiffness.MeshStiffness` and falls
    back to PEM without one (the FE tooth solves are not repeated for the static pass).
    """
    level = scene.physics.stiffness
    if level in ("constant", "iso6336"):
        return None
    from femgear.physics.stiffness.tvms import tabulated

    if getattr(stiffness, "k_pair_per_width", None) is not None:
        return tabulated(pair, stiffness.u, stiffness.k_pair_per_width)
    from femgear.physics.stiffness.pem import pair_stiffness_per_width

    u = np.linspace(pair.u_start, pair.u_end, 81)
    m = scene.material
    k = pair_stiffness_per_width(pair, u, m.youngs_modulus, m.poisson_ratio,
                                 (scene.pinion.bore_radius, scene.gear.bore_radius))
    return tabulated(pair, u, k)


def contact_along_path(scene, n: int | None = None, pair: GearPair | None = None, u: np.ndarray | None = None,
                       stiffness=None) -> ContactPath:
    """Hertz pressure, films and velocities at ``n`` positions from A to E (plus the pitch point).

    ``u`` replaces the positions [m]; ``stiffness`` (a :class:`MeshStiffness` of the
    scene's level) supplies k'(u) for the load sharing instead of recomputing it.
    """
    pair = pair or GearPair.from_scene(scene)
    if u is None:
        n = n or scene.numerics.path_points
        # include the pitch point exactly so that pitch-point figures are not interpolated
        u = np.unique(np.append(path_positions(pair, n), pair.u_pitch))
    u = np.asarray(u, float)
    omega1 = pinion_speed(scene) * 2 * math.pi / 60
    kin = kinematics(pair, u, omega1)
    F_bn = normal_force(scene, pair)
    share = load_sharing(pair, u, F_bn / pair.n_helices, pair_stiffness_curve(scene, pair, stiffness))
    E_red = reduced_modulus(scene.material.youngs_modulus, scene.material.poisson_ratio)
    return _contact(pair, kin, F_bn, share, E_red, scene.oil.viscosity, scene.oil.pressure_viscosity)


def _contact(pair: GearPair, kin: PathKinematics, F_bn: float, share: LoadSharing, E_red: float,
             eta0: float, alpha: float) -> ContactPath:
    w = share.line_load
    hertz = [hertz_line(wi, R, E_red) for wi, R in zip(w, kin.R, strict=True)]
    films = line_film(w, kin.R, kin.ue, E_red, eta0, alpha)
    return ContactPath(
        kin=kin, normal_force=F_bn, load_per_length=share.mean_line_load,
        hertz_half_width=np.array([h.half_width for h in hertz]),
        hertz_pressure=np.array([h.max_pressure for h in hertz]),
        film_central=films["central_moes"], film_central_dt=films["central_dt"],
        film_minimum=films["minimum_dh"], moes_M=films["M"], moes_L=films["L"],
        pitch_index=int(np.argmin(np.abs(kin.u - pair.u_pitch))),
        line_load=w, line_load_max=share.line_load_max, load_fraction=share.fraction,
        single_contact=single_contact_bounds(pair), n_helices=pair.n_helices,
    )
