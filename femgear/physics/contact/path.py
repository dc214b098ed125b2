"""The quasi-static contact pass along the path of contact of a gear pair.

The normal force F_bn = T1/(r_b1 cos β_b) is shared by the helices (two for a
double-helical pair).  Along the path, the load per unit contact-line length
``line_load`` w(u) comes from the load sharing between the tooth pairs in contact
(:mod:`femgear.physics.contact.sharing`, with the pair stiffness k'(u) of the run's
mesh-stiffness level, :func:`femgear.levels.contact.contact_pass`): the single-pair load
F_n/b in the single-contact zone of a spur pair, contact-line sharing for helical pairs.  Each position is then a Hertz line
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
from femgear.physics.contact.hertz import hertz_line
from femgear.physics.contact.sharing import LoadSharing, StiffnessPerWidth, load_sharing, single_contact_bounds
from femgear.physics.geometry import GearPair, PathKinematics, path_positions


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

    def line_loads(self) -> np.ndarray:
        """w(u) at every position: the load sharing's ``line_load``, else the path mean ``load_per_length`` [N/m]."""
        if self.line_load is not None:
            return self.line_load
        return np.full(self.kin.u.shape, self.load_per_length)


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


def contact_along_path(pair: GearPair, kin: PathKinematics, normal_force: float, E_red: float, eta0: float,
                       alpha: float, stiffness: StiffnessPerWidth | None = None) -> ContactPath:
    """Hertz pressure, films and velocities at the positions of ``kin`` (:func:`femgear.physics.geometry.kinematics`).

    ``normal_force`` F_bn of the pair, all helices [N]; ``E_red`` the reduced modulus [Pa]; ``eta0``,
    ``alpha`` the oil's viscosity [Pa s] and Barus coefficient [1/Pa] for the film formulas;
    ``stiffness`` the pair stiffness per unit width k'(u) for the load sharing (None: uniform).
    """
    share = load_sharing(pair, np.asarray(kin.u, float), normal_force / pair.n_helices, stiffness)
    return _contact(pair, kin, normal_force, share, E_red, eta0, alpha)


def _contact(pair: GearPair, kin: PathKinematics, F_bn: float, share: LoadSharing, E_red: float,
             eta0: float, alpha: float) -> ContactPath:
    w = share.line_load
    hertz = [hertz_line(wi, R, E_red) for wi, R in zip(w, kin.R, strict=True)]
    films = line_film(w, kin.R, kin.ue, E_red, eta0, alpha)
    return ContactPath(
        kin=kin, normal_force=F_bn, load_per_length=share.mean_line_load,
        hertz_half_width=np.array([h.half_width for h in hertz]),
        hertz_pressure=np.array([h.max_pressure for h in hertz]),
        film_central=films.central_moes, film_central_dt=films.central_dt,
        film_minimum=films.minimum_dh, moes_M=films.M, moes_L=films.L,
        pitch_index=int(np.argmin(np.abs(kin.u - pair.u_pitch))),
        line_load=w, line_load_max=share.line_load_max, load_fraction=share.fraction,
        single_contact=single_contact_bounds(pair), n_helices=pair.n_helices,
    )
