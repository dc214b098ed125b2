"""ISO 6336-1:2019 single stiffness c' and mesh stiffness c_γα, c_γβ (Method B).

Sources: ISO 6336-1:2019 §9 (eqs. for q', c'_th, C_M, C_R, C_B, c_γα = c'(0.75 ε_α + 0.25),
c_γβ = 0.85 c_γα); worked example: ISO/TR 6336-30:2017 example 1 (reproduced in
``tests/stiffness/test_iso6336.py``).

Units: the standard's c' and c_γ are in N/(mm·µm) per unit face width; the functions
here return them in those units and :func:`iso_mesh_stiffness` converts to N/m for the
face width of one helix, k = c_γ · b[mm] · 1e6.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from femgear.docfields import document_fields
from femgear.physics.geometry.gear import GearPair

#: ISO 6336-1 Table 9 (Method B) coefficients of q' [mm·µm/N]
_C = (0.04723, 0.15551, 0.25791, -0.00635, -0.11654, -0.00193, -0.24188, 0.00529, 0.00182)


@document_fields
@dataclass(frozen=True)
class IsoStiffness:
    """ISO 6336-1 stiffness values of one helix (per unit face width, N/(mm·µm))."""

    q_prime: float
    """minimum flexibility of a tooth pair [mm·µm/N]"""
    c_th: float
    """theoretical single stiffness c'_th = 1/q' per unit face width [N/(mm·µm)]"""
    c_prime: float
    """single stiffness c' of one tooth pair per unit face width (ISO 6336-1 Method B) [N/(mm·µm)]"""
    c_gamma_alpha: float
    """mesh stiffness c_γα = c' (0.75 ε_α + 0.25) per unit face width (transverse) [N/(mm·µm)]"""
    c_gamma_beta: float
    """mesh stiffness c_γβ = 0.85 c_γα per unit face width (for K_Hβ) [N/(mm·µm)]"""
    eps_alpha: float
    """transverse contact ratio ε_α used in c_γα [-]"""
    face_width: float
    """face width of the helix the values are per unit of (``k()`` multiplies by it) [m]"""

    def k(self, which: str = "c_gamma_alpha") -> float:
        """The named value times the face width, in N/m."""
        return getattr(self, which) * self.face_width * 1e3 * 1e6


def virtual_teeth(z: int, beta: float, beta_b: float) -> float:
    """Virtual number of teeth z_n = z/(cos²β_b cos β)."""
    return z / (math.cos(beta_b) ** 2 * math.cos(beta))


def gear_blank_factor(rim: float, web_ratio: float, m_n: float) -> float:
    """ISO 6336-1:2019's gear blank factor C_R = 1 + ln(b_s/b) / (5 exp(s_R/(5 m_n))) of a webbed gear: ``rim`` the
    rim thickness s_R below the root circle [m], ``web_ratio`` the web's thickness over the face width b_s/b [-],
    clamped to the standard's ranges 0.2 ≤ b_s/b ≤ 1.2 and s_R ≥ m_n (1 for a solid disc, b_s = b)."""
    if not (rim > 0 and web_ratio > 0 and m_n > 0):
        raise ValueError(f"gear blank factor: s_R, b_s/b and m_n must be positive, got {rim!r}, {web_ratio!r}, {m_n!r}")
    bs = min(max(web_ratio, 0.2), 1.2)
    return 1.0 + math.log(bs) / (5.0 * math.exp(max(rim, m_n) / (5.0 * m_n)))


def iso6336_stiffness(pair: GearPair, line_load: float | None = None, C_M: float = 0.8,
                      C_R: float = 1.0, eps_alpha: float | None = None,
                      youngs_modulus: float = 206e9) -> IsoStiffness:
    """c', c_γα, c_γβ of ``pair`` by ISO 6336-1:2019 Method B.

    ``line_load`` = F_t K_A / b [N/m]; below 100 N/mm the standard scales c' by
    (F_t K_A/b / 100 N/mm)^0.25.  ``C_R`` = 1 for solid discs (:func:`gear_blank_factor` for a webbed gear).  ``eps_alpha`` defaults
    to the pair's transverse contact ratio.  Materials other than steel scale with
    E/E_steel (E_steel = 206 GPa in the standard).
    """
    zn1 = virtual_teeth(pair.z1, pair.beta, pair.beta_b)
    zn2 = virtual_teeth(pair.z2, pair.beta, pair.beta_b)
    x1, x2 = pair.x1, pair.x2
    C = _C
    q = (C[0] + C[1] / zn1 + C[2] / zn2 + C[3] * x1 + C[4] * x1 / zn1 + C[5] * x2
         + C[6] * x2 / zn2 + C[7] * x1 ** 2 + C[8] * x2 ** 2)
    c_th = 1.0 / q
    C_B = (1 + 0.5 * (1.2 - pair.h_fP)) * (1 - 0.02 * (20.0 - math.degrees(pair.alpha_n)))
    c_p = c_th * C_M * C_R * C_B * math.cos(pair.beta) * youngs_modulus / 206e9
    if line_load is not None:
        w = line_load * 1e-3  # N/m -> N/mm
        if w < 100:
            c_p *= (w / 100) ** 0.25
    ea = pair.eps_alpha if eps_alpha is None else eps_alpha
    c_ga = c_p * (0.75 * ea + 0.25)
    return IsoStiffness(q_prime=q, c_th=c_th, c_prime=c_p, c_gamma_alpha=c_ga,
                        c_gamma_beta=0.85 * c_ga, eps_alpha=ea, face_width=pair.b)
