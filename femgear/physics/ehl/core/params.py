"""Moes dimensionless groups <-> Hertzian dimensionless parameters.

Point contact (Venner & Lubrecht 2000, sec. 2.4; Moes 1992), with R = R_x:
    lam_bar = (128 pi^3 / (3 M^4))^(1/3),  alpha_bar = (L/pi) (3M/2)^(1/3),
    H_Moes = H (3M/2)^(2/3),  load int P = 2 pi / 3.
Line contact (Venner & Lubrecht 2000, sec. 2.2), X = x/b, H = h R / b^2:
    lam_bar = 3 pi^2 / (8 M^2),  alpha_bar = L sqrt(M / (2 pi)),
    H_Moes = H (8 M / pi),  load int P = pi / 2.
Here M = W (2U)^(-3/4) (point) or W' (2U)^(-1/2) (line), L = G (2U)^(1/4), and
H_Moes = (h/R) (2U)^(-1/2), with U built on the mean speed u_m = (u1 + u2)/2.
"""

from __future__ import annotations

import math


def point_lam_bar(M: float) -> float:
    return (128.0 * math.pi**3 / (3.0 * M**4)) ** (1.0 / 3.0)


def point_alpha_bar(M: float, L: float) -> float:
    return (L / math.pi) * (1.5 * M) ** (1.0 / 3.0)


def point_h_moes_factor(M: float) -> float:
    """H_Moes / H for point contacts."""
    return (1.5 * M) ** (2.0 / 3.0)


def line_lam_bar(M: float) -> float:
    return 3.0 * math.pi**2 / (8.0 * M**2)


def line_alpha_bar(M: float, L: float) -> float:
    return L * math.sqrt(M / (2.0 * math.pi))


def line_h_moes_factor(M: float) -> float:
    """H_Moes / H for line contacts."""
    return 8.0 * M / math.pi


POINT_LOAD = 2.0 * math.pi / 3.0
LINE_LOAD = math.pi / 2.0
