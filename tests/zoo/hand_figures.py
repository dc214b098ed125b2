"""Hand-checked figures of a zoo scene, computed from the standards WITHOUT femgear.

This file imports nothing from femgear: it reads the scene TOML itself and writes out the
formulas of the standards and the classic papers, so that ``tests/zoo/test_hand_figures.py``
checks femgear's ``info`` against an independent calculation.  Printed as the comment block
each zoo scene carries (``--write`` replaces the block in the file)::

    python tests/zoo/hand_figures.py studies/zoo/marine.toml
    python tests/zoo/hand_figures.py --write studies/zoo/*.toml

Conditions of the figures: ISO's uniform load along the contact lines (femgear's
``physics.stiffness = "iso6336"`` level) and a constant friction coefficient
(``physics.lubrication = "constant"``, μ = ``friction.coefficient``); the test runs ``info``
with these two overrides.  The oil's ``viscosity`` is taken as the viscosity at the contact
inlet (the zoo scenes give it at the operating temperature).

Sources (each figure names its own):
- ISO 21771:2007 §§4–5: d = z m_n/cos β, tan α_t = tan α_n/cos β, d_b = d cos α_t,
  inv α_wt = inv α_t + 2 tan α_n (x1 + x2)/(z1 + z2), a_w = a cos α_t/cos α_wt,
  tip alteration k = (a_w − a)/m_n − (x1 + x2), d_a = d + 2 m_n (h_aP + x + k) (or the scene's
  ``tip_diameter``, the tip as made),
  ε_α = (√(r_a1² − r_b1²) + √(r_a2² − r_b2²) − a_w sin α_wt)/p_bt, ε_β = b sin β/(π m_n).
- ISO 6336-1:2019 §9 method B: q' = C1 + C2/z_n1 + ... (Table 9), c'_th = 1/q',
  c' = c'_th C_M C_R C_B cos β (C_M 0.8, C_R 1, C_B = [1 + 0.5(1.2 − h_fP/m_n)][1 − 0.02(20° − α_n)]),
  × (F_t K_A/b / 100 N/mm)^0.25 below 100 N/mm, × E/206 GPa; c_γα = c'(0.75 ε_α + 0.25), c_γβ = 0.85 c_γα.
- ISO 6336-2:2019 method B: σ_H0 = Z_H Z_E Z_ε Z_β √(F_t (u+1)/(d1 b u)), Z_H = √(2 cos β_b cos α_wt/
  (cos² α_t sin α_wt)), Z_E = √(E/(2π(1 − ν²))), Z_ε (ε_β < 1: √((4 − ε_α)(1 − ε_β)/3 + ε_β/ε_α);
  else √(1/ε_α)), Z_β = √(1/cos β), Z_B/Z_D from M1/M2 (spur), interpolated for ε_β < 1, 1 for ε_β ≥ 1.
- Hertz (1882), line contact: p_H = √(w E'/(2π R)), b_H = √(8 w R/(π E')), E' = E/(1 − ν²),
  R = ρ1 ρ2/((ρ1 + ρ2) cos β_b) in the normal section.
- Load per unit line length: ISO's uniform load w = F_bn,helix / L(φ), the contact-line length
  L(φ) in the plane of action (lines inclined by β_b), averaged over the face at the flank
  point (spur: F_bn / (b × pairs in contact)).
- Dowson & Toyoda (1979), line contact central film H_c = 3.06 U^0.69 G^0.56 W^−0.10
  (U = η0 u_m/(E' R), G = α E', W = w/(E' R), u_m = (v1 + v2)/2, v_i = ω_i ρ_i).
- Moes (1992), Wear 159:57, line-contact central film from M = W (2U)^−1/2, L = G (2U)^1/4.
- Blok (1937) / Jaeger (1942): maximum flash temperature of a semi-elliptic band source,
  θ = c μ w |v1 − v2| / (√(2 b_H) (B √v1 + B √v2)), B = √(k ρ c); the constant c = 2√2 I_max/π^1.5
  = 1.1115 is integrated here (I_max = max_X ∫ √(1 − t²)/√(X − t) dt), not taken from a book.
- Mesh frequency f_z = z1 n1/60.
"""

from __future__ import annotations

import math
import sys
import tomllib
from pathlib import Path

import numpy as np

RACKS = {"A": (1.0, 1.25, 0.38), "B": (1.0, 1.25, 0.30), "C": (1.0, 1.25, 0.25), "D": (1.0, 1.40, 0.39)}  # ISO 53
Q_COEFFS = (0.04723, 0.15551, 0.25791, -0.00635, -0.11654, -0.00193, -0.24188, 0.00529, 0.00182)  # ISO 6336-1 T. 9

#: where a tip radius comes from: the scene's tip_diameter (as made), else ISO 21771 from the shift
TIP_SOURCE = {True: "the drawing's d_a/2 (pinion/gear.tip_diameter)", False: "ISO 21771 d_a = d + 2 m_n (h_aP + x + k)"}
#: tolerances (relative) stated beside each figure
TOL = {"geometry": 1e-6, "ratio": 1e-5, "iso": 5e-3, "hertz": 5e-3, "film": 1e-2, "flash": 1e-2}


def inv(a: float) -> float:
    return math.tan(a) - a


def inv_inverse(y: float) -> float:
    a = (3 * y) ** (1 / 3)
    for _ in range(60):
        a -= (inv(a) - y) / math.tan(a) ** 2
    return a


def blok_constant() -> float:
    """2√2 I_max/π^1.5 with I(X) = ∫_{−1}^{X} √(1 − t²)/√(X − t) dt (t = X − s², midpoint rule, 1e-6)."""
    best = 0.0
    for X in np.linspace(0.60, 0.70, 201):
        s = np.linspace(0, math.sqrt(X + 1), 20001)
        s = 0.5 * (s[1:] + s[:-1])
        integral = float(np.sum(2 * np.sqrt(np.clip(1 - (X - s * s) ** 2, 0, None))) * math.sqrt(X + 1) / s.size)
        best = max(best, integral)
    return 2 * math.sqrt(2) * best / math.pi**1.5


class Pair:
    """The scene's pair, ISO 21771 (from the TOML dict, SI)."""

    def __init__(self, s: dict):
        p, g1, g2 = s["pair"], s["pinion"], s["gear"]
        self.kind = p.get("kind", "double-helical")
        self.mn = p["normal_module"]
        self.an = math.radians(p.get("normal_pressure_angle_deg", 20.0))
        self.beta = math.radians(p["helix_angle_deg"])
        self.b = p["face_width"]
        self.helices = 2 if self.kind == "double-helical" else 1
        rack = RACKS[p["basic_rack"]] if "basic_rack" in p else (
            p.get("addendum_coeff", 1.0), p.get("dedendum_coeff", 1.25), p.get("root_radius_coeff", 0.38))
        self.haP, self.hfP = rack[0], rack[1]
        self.z1, self.z2 = g1["teeth"], g2["teeth"]
        self.x1, self.x2 = g1.get("profile_shift", 0.0), g2.get("profile_shift", 0.0)
        self.at = math.atan(math.tan(self.an) / math.cos(self.beta))
        self.d1, self.d2 = (z * self.mn / math.cos(self.beta) for z in (self.z1, self.z2))
        self.db1, self.db2 = self.d1 * math.cos(self.at), self.d2 * math.cos(self.at)
        self.bb = math.atan(math.tan(self.beta) * math.cos(self.at))
        self.awt = inv_inverse(inv(self.at) + 2 * math.tan(self.an) * (self.x1 + self.x2) / (self.z1 + self.z2))
        a = (self.d1 + self.d2) / 2
        self.aw = a * math.cos(self.at) / math.cos(self.awt)
        k = (self.aw - a) / self.mn - (self.x1 + self.x2)
        # a tip diameter given in the scene is the tip as made (a drawing's d_a), else the rack's with k
        self.tip_given = ("tip_diameter" in g1, "tip_diameter" in g2)
        self.da1 = g1.get("tip_diameter", self.d1 + 2 * self.mn * (self.haP + self.x1 + k))
        self.da2 = g2.get("tip_diameter", self.d2 + 2 * self.mn * (self.haP + self.x2 + k))
        self.pbt = math.pi * self.mn / math.cos(self.beta) * math.cos(self.at)
        self.g1 = math.sqrt((self.da1 / 2) ** 2 - (self.db1 / 2) ** 2)    # T1E
        self.g2 = math.sqrt((self.da2 / 2) ** 2 - (self.db2 / 2) ** 2)
        self.T1T2 = self.aw * math.sin(self.awt)
        self.uA, self.uE = self.T1T2 - self.g2, self.g1                     # ρ1 at A and E
        self.uC = self.d1 / 2 * math.cos(self.at) * math.tan(self.awt)     # ρ1 at the pitch point
        self.ea = (self.g1 + self.g2 - self.T1T2) / self.pbt
        self.eb = self.b * math.sin(self.beta) / (math.pi * self.mn)

    def line_load(self, u: float, F_helix: float) -> float:
        """ISO's uniform load at path position u (ρ1 = u): face mean of F/L(φ)."""
        if self.beta == 0:
            n = sum(1 for j in range(-4, 5) if self.uA - 1e-12 <= u + j * self.pbt <= self.uE + 1e-12)
            return F_helix / (self.b * n)
        t = math.tan(self.bb)
        zeta = (np.arange(20000) + 0.5) / 20000 * self.b            # flank points across the face
        reach = int((self.uE - self.uA + self.b * t) / self.pbt) + 2   # lines that can cross the zone
        c = (u - zeta * t)[:, None] + self.pbt * np.arange(-reach, reach + 1)[None, :]
        lo = np.maximum(0.0, (self.uA - c) / t)
        hi = np.minimum(self.b, (self.uE - c) / t)
        L = np.sum(np.clip(hi - lo, 0.0, None), axis=1) / math.cos(self.bb)
        return float(np.mean(F_helix / L))


def c_prime(P: Pair, s: dict, line_load: float) -> tuple[float, float, float, float]:
    """ISO 6336-1 method B: c'_th, c', c_γα, c_γβ [N/(mm µm)]."""
    zn1 = P.z1 / (math.cos(P.bb) ** 2 * math.cos(P.beta))
    zn2 = P.z2 / (math.cos(P.bb) ** 2 * math.cos(P.beta))
    C = Q_COEFFS
    q = (C[0] + C[1] / zn1 + C[2] / zn2 + C[3] * P.x1 + C[4] * P.x1 / zn1 + C[5] * P.x2 + C[6] * P.x2 / zn2
         + C[7] * P.x1**2 + C[8] * P.x2**2)
    C_B = (1 + 0.5 * (1.2 - P.hfP)) * (1 - 0.02 * (20 - math.degrees(P.an)))
    cp = (1 / q) * 0.8 * 1.0 * C_B * math.cos(P.beta) * s["material"]["youngs_modulus"] / 206e9
    if line_load < 100e3:
        cp *= (line_load / 100e3) ** 0.25
    cga = cp * (0.75 * P.ea + 0.25)
    return 1 / q, cp, cga, 0.85 * cga


def sigma_h(P: Pair, s: dict, T1: float) -> tuple[float, float, float]:
    """ISO 6336-2 method B (K factors of [rating], default 1): σ_H0, σ_H1, σ_H2 [Pa]."""
    m = s["material"]
    Ft = T1 / (P.d1 / 2)
    b = P.b * P.helices
    u = P.z2 / P.z1
    ZH = math.sqrt(2 * math.cos(P.bb) * math.cos(P.awt) / (math.cos(P.at) ** 2 * math.sin(P.awt)))
    ZE = math.sqrt(m["youngs_modulus"] / (2 * math.pi * (1 - m["poisson_ratio"] ** 2)))
    ea, eb = P.ea, P.eb
    Zeps = math.sqrt((4 - ea) * (1 - eb) / 3 + eb / ea) if eb < 1 else math.sqrt(1 / ea)
    Zbeta = math.sqrt(1 / math.cos(P.beta))
    s0 = ZH * ZE * Zeps * Zbeta * math.sqrt(Ft / (P.d1 * b) * (u + 1) / u)
    r1 = math.sqrt(P.da1**2 / P.db1**2 - 1)
    r2 = math.sqrt(P.da2**2 / P.db2**2 - 1)
    M1 = math.tan(P.awt) / math.sqrt((r1 - 2 * math.pi / P.z1) * (r2 - (ea - 1) * 2 * math.pi / P.z2))
    M2 = math.tan(P.awt) / math.sqrt((r2 - 2 * math.pi / P.z2) * (r1 - (ea - 1) * 2 * math.pi / P.z1))
    ZB, ZD = (max(1.0, M - eb * (M - 1)) if eb < 1 else 1.0 for M in (M1, M2))
    r = s.get("rating", {})
    K = math.sqrt(r.get("application_factor", 1.0) * r.get("dynamic_factor", 1.0)
                  * r.get("face_load_factor", 1.0) * r.get("transverse_load_factor", 1.0))
    return s0, ZB * s0 * K, ZD * s0 * K


def moes_line_central(M: float, L: float) -> float:
    """Moes (1992) line contact, central film in Moes units (asymptotes RI, EI, RP, EP)."""
    H_RI, H_EI = 3.0 / M, 2.621 * M ** (-1 / 5)
    H_RP, H_EP = 1.287 * L ** (2 / 3), 1.311 * M ** (-1 / 8) * L**0.75
    s = (7 + 8 * math.exp(-2 * H_EI / H_RI)) / 5
    return ((H_RI ** (7 / 3) + H_EI ** (7 / 3)) ** (3 * s / 7) + (H_RP ** -3.5 + H_EP ** -3.5) ** (-2 * s / 7)) ** (1 / s)


def figures(path: str | Path) -> list[tuple[str, float, float, str]]:
    """[(info key path, value, relative tolerance, source)] of a scene file."""
    s = tomllib.loads(Path(path).read_text())
    P = Pair(s)
    op, m, oil = s["operating"], s["material"], s["oil"]
    ratio = P.z2 / P.z1
    n1 = op["speed_rpm"] if op.get("driver", "pinion") == "pinion" else op["speed_rpm"] * ratio
    T1 = op["torque"] if op.get("driver", "pinion") == "pinion" else op["torque"] / ratio
    w1 = 2 * math.pi * n1 / 60
    w2 = w1 / ratio
    F_bn = T1 / (P.db1 / 2 * math.cos(P.bb))
    F_helix = F_bn / P.helices
    Ep = m["youngs_modulus"] / (1 - m["poisson_ratio"] ** 2)
    mu = s.get("friction", {}).get("coefficient", 0.05)
    B = math.sqrt(m["conductivity"] * m["density"] * m["specific_heat"])
    blok = blok_constant()
    G, T = TOL, P.T1T2
    out = [
        ("geometry.reference_radius.0", P.d1 / 2, G["geometry"], "ISO 21771 d = z m_n/cos β"),
        ("geometry.reference_radius.1", P.d2 / 2, G["geometry"], "ISO 21771 d = z m_n/cos β"),
        ("geometry.base_radius.0", P.db1 / 2, G["geometry"], "ISO 21771 d_b = d cos α_t"),
        ("geometry.base_radius.1", P.db2 / 2, G["geometry"], "ISO 21771 d_b = d cos α_t"),
        ("geometry.tip_radius.0", P.da1 / 2, G["geometry"], TIP_SOURCE[P.tip_given[0]]),
        ("geometry.tip_radius.1", P.da2 / 2, G["geometry"], TIP_SOURCE[P.tip_given[1]]),
        ("geometry.centre_distance", P.aw, G["geometry"], "ISO 21771 inv α_wt, a_w = a cos α_t/cos α_wt"),
        ("geometry.eps_alpha", P.ea, G["ratio"], "ISO 21771 ε_α from the tip circles"),
        ("geometry.eps_beta", P.eb, G["ratio"], "ISO 21771 ε_β = b sin β/(π m_n), one helix"),
        ("geometry.mesh_frequency", P.z1 * n1 / 60, G["ratio"], "f_z = z1 n1/60"),
    ]
    line_load = T1 / (P.d1 / 2) * s.get("rating", {}).get("application_factor", 1.0) / (P.b * P.helices)
    c_th, cp, cga, cgb = c_prime(P, s, line_load)
    out += [("stiffness_iso6336.c_prime_th", c_th * 1e9, G["iso"], "ISO 6336-1:2019 method B q', c'_th = 1/q'"),
            ("stiffness_iso6336.c_prime", cp * 1e9, G["iso"], "ISO 6336-1:2019 method B c'"),
            ("stiffness_iso6336.c_gamma_alpha", cga * 1e9, G["iso"], "ISO 6336-1:2019 c_γα = c'(0.75 ε_α + 0.25)"),
            ("stiffness_iso6336.c_gamma_beta", cgb * 1e9, G["iso"], "ISO 6336-1:2019 c_γβ = 0.85 c_γα")]
    s0, s1, s2 = sigma_h(P, s, T1)
    out += [("rating.sigma_H0", s0, G["iso"], "ISO 6336-2:2019 method B σ_H0"),
            ("rating.sigma_H.0", s1, G["iso"], "ISO 6336-2:2019 σ_H1 = Z_B σ_H0 √(K_A K_v K_Hβ K_Hα)"),
            ("rating.sigma_H.1", s2, G["iso"], "ISO 6336-2:2019 σ_H2 = Z_D σ_H0 √(K_A K_v K_Hβ K_Hα)")]
    # the pitch point C: Hertz and films
    wC = P.line_load(P.uC, F_helix)
    rho1, rho2 = P.uC, T - P.uC
    R = rho1 * rho2 / ((rho1 + rho2) * math.cos(P.bb))
    um = 0.5 * (w1 * rho1 + w2 * rho2)
    U, Gm, W = oil["viscosity"] * um / (Ep * R), oil["pressure_viscosity"] * Ep, wC / (Ep * R)
    M, L = W * (2 * U) ** -0.5, Gm * (2 * U) ** 0.25
    out += [("contact.pitch.line_load", wC, G["hertz"], "uniform load F_bn/L(φ), face mean at C"),
            ("contact.pitch.hertz_pressure", math.sqrt(wC * Ep / (2 * math.pi * R)), G["hertz"],
             "Hertz line contact p_H = √(w E'/(2π R)) at C"),
            ("contact.pitch.film_central_dowson_toyoda", R * 3.06 * U**0.69 * Gm**0.56 * W**-0.10, G["film"],
             "Dowson & Toyoda 1979 central film at C"),
            ("contact.pitch.film_central", moes_line_central(M, L) * R * math.sqrt(2 * U), G["film"],
             "Moes 1992 line-contact central film at C")]
    for name, u in (("A", P.uA), ("E", P.uE)):
        w = P.line_load(u, F_helix)
        rho1, rho2 = u, T - u
        R = rho1 * rho2 / ((rho1 + rho2) * math.cos(P.bb))
        bH = math.sqrt(8 * w * R / (math.pi * Ep))
        v1, v2 = w1 * rho1, w2 * rho2
        theta = blok * mu * w * abs(v1 - v2) / (math.sqrt(2 * bH) * (B * math.sqrt(v1) + B * math.sqrt(v2)))
        out.append((f"flash_temperature.theta_fl_{name}", theta, G["flash"],
                    f"Blok/Jaeger flash temperature at {name}, μ = {mu:g}"))
    return out


def block(path: str | Path) -> str:
    """The comment block of a scene (``# hand: key = value ± tol  source``)."""
    lines = ["# --- hand-checked figures: tests/zoo/hand_figures.py (independent of femgear), checked against",
             "# `femgear info --json --set physics.stiffness='\"iso6336\"' --set physics.lubrication='\"constant\"'`",
             "# with rating.dynamic_factor = face_load_factor = transverse_load_factor = 1 (K_v, K_Hβ, K_Hα of 1),",
             "# by tests/zoo/test_hand_figures.py; SI units; ± relative tolerance; source."]
    for key, value, tol, source in figures(path):
        lines.append(f"# hand: {key} = {value:.7g} ± {tol:g}  ({source})")
    return "\n".join(lines)


def write_block(path: str | Path) -> None:
    """Replace (or append) the scene's hand-figure block in place."""
    path = Path(path)
    text = path.read_text()
    head = text.split("\n# --- hand-checked figures", 1)[0].rstrip("\n")
    path.write_text(f"{head}\n\n{block(path)}\n")


if __name__ == "__main__":
    write = "--write" in sys.argv
    for arg in (a for a in sys.argv[1:] if a != "--write"):
        write_block(arg) if write else print(block(arg))
