"""Relative curvature of crowned involute flanks: R_x, R_y and the point contact per tooth pair.

An involute helicoid is a ruled surface: along the contact line (a straight generator in
the plane of action, inclined at the base helix angle beta_b to the axis) its normal
curvature is zero, across it (normal section) the relative curvature is 1/R with R the
path's reduced radius (:mod:`femgear.physics.geometry.kinematics`). An uncrowned pair is therefore
a line contact; a lead crowning turns every contact into a slender ellipse.

Lead crowning (``modifications.crowning`` C_beta, ISO 21771 §9: amount normal to the flank
at each end of a helix of face width b, parabola C_beta (2 zeta/b - 1)^2 over the face
coordinate zeta, as in :func:`femgear.physics.ltca.separation.member_deviation`) has the normal
curvature kappa = 8 C_beta / b^2 along the axial direction e_zeta, which lies in the plane
of action (the flank's tangent plane along the contact line). With s along the contact
line and n across it (both in that plane), e_zeta = cos(beta_b) e_s + sin(beta_b) e_n, so
the crowning adds the curvature tensor kappa e_zeta e_zeta^T. Summed over both members
(each carries its own C_beta; the top-level keys apply to both, ``[modifications.pinion]``/
``[modifications.gear]`` override per member) the relative curvature tensor in (n, s) is

    [[1/R + kappa_r sin^2 beta_b,  kappa_r sin beta_b cos beta_b],
     [kappa_r sin beta_b cos beta_b,  kappa_r cos^2 beta_b]],   kappa_r = 8 (C_1 + C_2)/b^2,

whose eigenvalues are the principal relative curvatures: 1/R_x (across the contact line,
~ 1/R + kappa_r sin^2 beta_b) and 1/R_y (along it, ~ kappa_r cos^2 beta_b; the exact
eigenvalues are used; the axes turn by ~ kappa_r R sin beta_b cos beta_b, < 1e-2 rad for
any real crowning, and are taken as the (n, s) frame). Derived here.

Load per contact: the path's load per unit contact length w(u) (:mod:`femgear.physics.contact.
sharing`) times the mean contact-line length of one tooth pair, L_mean = b / cos(beta_b)
* eps_alpha / eps_gamma (the total L = eps_alpha b / cos beta_b of ISO 6336 spread over the
eps_gamma pairs in contact on average; b / cos beta_b for a spur pair).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from femgear.errors import SceneError


@dataclass(frozen=True)
class CrownedContact:
    """Geometry that turns the line load of a crowned pair into elliptic point contacts."""

    kappa: float          #: summed crowning curvature of both members along the axis [1/m]
    beta_b: float         #: base helix angle [rad]
    contact_length: float  #: mean contact-line length of one tooth pair [m]

    def radii(self, R) -> tuple[np.ndarray, np.ndarray]:
        """(R_x, R_y) [m] for the profile reduced radius R [m] (arrays broadcast)."""
        R = np.asarray(R, dtype=float)
        c, s = math.cos(self.beta_b), math.sin(self.beta_b)
        a = 1.0 / R + self.kappa * s * s
        d = self.kappa * c * c
        off = self.kappa * s * c
        mean, half = 0.5 * (a + d), np.sqrt(0.25 * (a - d) ** 2 + off * off)
        return 1.0 / (mean + half), 1.0 / (mean - half)

    def load(self, w) -> np.ndarray:
        """Load of one contact [N] from the load per unit contact length w [N/m]."""
        return np.asarray(w, dtype=float) * self.contact_length


def crowned_contact(pair, crowning: tuple[float, float]) -> CrownedContact:
    """:class:`CrownedContact` of ``pair`` with the lead crownings C_β of pinion and gear [m]
    (``modifications.crowning``, per member); an uncrowned pair raises SceneError naming that key."""
    c1, c2 = crowning
    if c1 + c2 <= 0.0:
        raise SceneError("modifications.crowning", "physics.lubrication = \"tehl-point\" needs a lead crowning > 0 "
                         "(an uncrowned involute flank has no curvature along the contact line: a line contact, "
                         "use \"tehl\")")
    b = pair.b
    kappa = 8.0 * (c1 + c2) / b**2
    length = b / math.cos(pair.beta_b) * pair.eps_alpha / pair.eps_gamma
    return CrownedContact(kappa=kappa, beta_b=pair.beta_b, contact_length=length)


#: Smallest R_x/R_y at which the ``tehl-point`` level is measured: the paper's pair with a 10 µm lead crowning
#: (0.0044–0.0050 along the path; studies/benchmarks/tehl_point.py: grid level 1 against 2 within 2.8 % in h_c,
#: 0.2 % in μ).  Below it the ellipse is a line contact for the point solver's grid (its stretched cells reach
#: aspect ratios beyond those tested) and the load continuation fails (a 2 x 120 mm marine helix: 4e-4); the
#: level hands such contacts over to line TEHL in face slices (:mod:`femgear.physics.tehl.slices`).
MIN_POINT_RATIO = 4.0e-3
