"""EHL film-thickness formulas and the dimensionless groups they use.

Dimensionless groups (Hamrock–Dowson), with mean entrainment speed u_m = (u1+u2)/2:
U = η0 u_m/(E' R_x), G = α E', W = F/(E' R_x²) (point), W' = w'/(E' R) (line).
Moes groups use the sum speed 2u_m (the factor-2 trap):
point M = W (2U)^(−3/4), line M = W' (2U)^(−1/2), L = G (2U)^(1/4), H = (h/R_x)(2U)^(−1/2).

Every function returns a film thickness made dimensionless as its source does; the
``*_m`` wrappers return metres.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np


# ----------------------------------------------------------------- groups
def moes_point(W: float, U: float, G: float) -> tuple[float, float]:
    """Moes (M, L) of a point contact: M = W(2U)^(−3/4), L = G(2U)^(1/4)."""
    return W * (2 * U) ** -0.75, G * (2 * U) ** 0.25


def moes_line(W_line: float, U: float, G: float) -> tuple[float, float]:
    """Moes (M, L) of a line contact: M = W'(2U)^(−1/2), L = G(2U)^(1/4)."""
    return W_line * (2 * U) ** -0.5, G * (2 * U) ** 0.25


def moes_to_h(H_moes, U: float, Rx: float):
    """Film thickness [m] from Moes H: h = H R_x (2U)^(1/2)."""
    return np.asarray(H_moes) * np.asarray(Rx) * np.sqrt(2 * np.asarray(U))


# ----------------------------------------------------------------- point contact
def hamrock_dowson_central(U, G, W, k=1.0339):
    """Hamrock & Dowson (1977), J. Lubr. Technol. 99:264: H_c = h_c/R_x.

    H_c = 2.69 U^0.67 G^0.53 W^−0.067 (1 − 0.61 e^(−0.73 k)); k = b/a the ellipticity.
    """
    return 2.69 * U**0.67 * G**0.53 * W**-0.067 * (1 - 0.61 * np.exp(-0.73 * k))


def hamrock_dowson_minimum(U, G, W, k=1.0339):
    """Hamrock & Dowson (1977): H_min = 3.63 U^0.68 G^0.49 W^−0.073 (1 − e^(−0.68 k))."""
    return 3.63 * U**0.68 * G**0.49 * W**-0.073 * (1 - np.exp(-0.68 * k))


def nvm_central(M, L, ratio: float = 1.0):
    """Nijenbanning, Venner & Moes (1994), Wear 176:217: central film H_c in Moes units.

    ``ratio`` λ = R_x/R_y (1 for a circular contact).  Blends the four asymptotes
    rigid-isoviscous (RI), rigid-piezoviscous (RP), elastic-isoviscous (EI) and
    elastic-piezoviscous (EP):

        H_c = {[H_RI^(3/2) + (H_EI^−4 + H_00^−4)^(−3/8)]^(2s/3) + (H_RP^−8 + H_EP^−8)^(−s/8)}^(1/s)

    with s = 1.5 (1 + exp(−1.2 H_EI/H_RI)) and H_00 = 1.8/λ.  L = 0 switches the
    piezoviscous part off.
    """
    M = np.asarray(M, dtype=float)
    L = np.asarray(L, dtype=float)
    lam = float(ratio)
    c = 1 + 0.006 * math.log(lam) + 0.63 * lam ** (4 / 7)
    H_RI = 145 * (1 + 0.796 * lam ** (14 / 15)) ** (-15 / 7) / lam * M**-2
    H_EI = 3.18 * c ** (-14 / 25) * lam ** (-1 / 15) * M ** (-2 / 15)
    H_00 = 1.8 / lam
    s = 1.5 * (1 + np.exp(-1.2 * H_EI / H_RI))
    iso = (H_RI**1.5 + (H_EI**-4 + H_00**-4) ** (-3 / 8)) ** (2 * s / 3)
    with np.errstate(divide="ignore"):
        H_RP = 1.29 * (1 + 0.691 * lam) ** (-2 / 3) * L ** (2 / 3)
        H_EP = 1.48 * c ** (-7 / 20) * lam ** (-1 / 24) * M ** (-1 / 12) * L**0.75
        piezo = np.where(L > 0, (H_RP**-8 + H_EP**-8) ** (-s / 8), 0.0)
    return (iso + piezo) ** (1 / s)


def rigid_isoviscous_point(ratio: float = 1.0) -> float:
    """Brewe, Hamrock & Taylor (1979), J. Lubr. Technol. 101:231: the rigid-isoviscous
    film of a fully flooded point contact (Reynolds cavitation), as the coefficient C of
    H_Moes = C M^−2.

    Their fit H_min = 128 α φ² [0.131 atan(α/2) + 1.683]² (U/W)², α = R_y/R_x = 1/λ,
    φ = (1 + 2/(3α))^−1, uses Hamrock's groups on the mean speed; with the Moes groups of
    this module (sum speed) (U/W)² = M^−2 (2U)^(1/2) / 4, so C = 32 α φ² [...]².  Rigid
    surfaces: the minimum film is the central one.  For λ = 1, C = 35.0 (NVM's rigid-
    isoviscous asymptote, :func:`nvm_central`, uses 41.3).
    """
    alpha = 1.0 / ratio
    phi = 1.0 / (1.0 + 2.0 / (3.0 * alpha))
    return 32.0 * alpha * phi**2 * (0.131 * math.atan(alpha / 2.0) + 1.683) ** 2


# ----------------------------------------------------------------- line contact
def dowson_higginson_minimum(U, G, W_line):
    """Dowson & Higginson (1977 form), line contact: H_min = 2.65 U^0.70 G^0.54 W'^−0.13."""
    return 2.65 * U**0.70 * G**0.54 * W_line**-0.13


def dowson_toyoda_central(U, G, W_line):
    """Dowson & Toyoda (1979), line contact: H_c = 3.06 U^0.69 G^0.56 W'^−0.10."""
    return 3.06 * U**0.69 * G**0.56 * W_line**-0.10


def moes_line_central(M, L):
    """Moes (1992), Wear 159:57: central film of a line contact in Moes units.

    H_RI = 3 M^−1, H_EI = 2.621 M^−1/5, H_RP = 1.287 L^2/3, H_EP = 1.311 M^−1/8 L^3/4,
    s = (7 + 8 exp(−2 H_EI/H_RI))/5,
    H_c = {(H_RI^7/3 + H_EI^7/3)^(3s/7) + (H_RP^−7/2 + H_EP^−7/2)^(−2s/7)}^(1/s).
    (Also in Venner & Lubrecht, *Multilevel Methods in Lubrication*, 2000, ch. 7.)
    """
    M = np.asarray(M, dtype=float)
    L = np.asarray(L, dtype=float)
    H_RI = 3.0 / M
    H_EI = 2.621 * M ** (-1 / 5)
    s = (7 + 8 * np.exp(-2 * H_EI / H_RI)) / 5
    iso = (H_RI ** (7 / 3) + H_EI ** (7 / 3)) ** (3 * s / 7)
    with np.errstate(divide="ignore"):
        H_RP = 1.287 * L ** (2 / 3)
        H_EP = 1.311 * M ** (-1 / 8) * L**0.75
        piezo = np.where(L > 0, (H_RP**-3.5 + H_EP**-3.5) ** (-2 * s / 7), 0.0)
    return (iso + piezo) ** (1 / s)


# ----------------------------------------------------------------- dimensional wrappers
@dataclass(frozen=True)
class LineFilm:
    """Isothermal films of line contacts by the published formulas (arrays over the contacts)."""

    central_dt: np.ndarray
    """central film h_c, Dowson–Toyoda (1979) [m]"""
    minimum_dh: np.ndarray
    """minimum film h_min, Dowson–Higginson [m]"""
    central_moes: np.ndarray
    """central film h_c, Moes (1992) line fit [m]"""
    M: np.ndarray
    """Moes load parameter M = W'(2U)^(−1/2) [-]"""
    L: np.ndarray
    """Moes lubricant parameter L = G(2U)^(1/4) [-]"""


def line_film(w, R, ue, E_red: float, eta0: float, alpha: float) -> LineFilm:
    """Line-contact films [m] at load w' [N/m], radius R [m], entrainment speed u_e [m/s],
    with the Moes groups M, L (:class:`LineFilm`)."""
    w, R, ue = (np.asarray(v, dtype=float) for v in (w, R, ue))
    U = eta0 * ue / (E_red * R)
    G = alpha * E_red
    Wl = w / (E_red * R)
    M, L = moes_line(Wl, U, G)
    return LineFilm(central_dt=dowson_toyoda_central(U, G, Wl) * R, minimum_dh=dowson_higginson_minimum(U, G, Wl) * R,
                    central_moes=moes_to_h(moes_line_central(M, L), U, R), M=M, L=L)
