"""Involute gear pair (spur, single- or double-helical): dimensions, contact ratios, feasibility (ISO 21771).

All lengths in metres, angles in radians.  Index 1 is the pinion, 2 the gear.  A
double-helical pair is two helical pairs of opposite hand; everything here refers to
one helix of width ``b`` (both helices share it).  A single-helical pair is one such
helix; a spur pair is the limit β = 0.  ``b`` is the width in contact (the smaller of
the two members' face widths).

Sources: ISO 21771:2007 (cylindrical involute gears, concepts and geometry), §4–5;
Niemann & Winter, *Maschinenelemente* II (2nd ed.), §21.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property

from femgear.errors import SceneError
from femgear.physics.geometry.involute import inv, inv_inverse

KINDS = ("double-helical", "single-helical", "spur")
__all__ = ["KINDS", "GearPair", "inv", "inv_inverse"]


@dataclass(frozen=True)
class GearPair:
    """Dimensions of one helix of an external involute helical gear pair.

    Built by :meth:`from_parameters` or :func:`femgear.case.pair.pair_from_scene`, which check that the gear
    can be made and meshes (no pointed tip, no interference, ε_α ≥ 1).
    """

    z1: int
    z2: int
    m_n: float          #: normal module [m]
    alpha_n: float      #: normal pressure angle [rad]
    beta: float         #: reference helix angle [rad]
    b: float            #: face width of one helix [m]
    x1: float           #: profile shift coefficients [-]
    x2: float
    h_aP: float = 1.0   #: basic-rack addendum / m_n
    h_fP: float = 1.25  #: basic-rack dedendum / m_n
    rho_fP: float = 0.38  #: basic-rack root radius / m_n
    kind: str = "double-helical"  #: "double-helical", "single-helical" or "spur"
    tip_radius1: float | None = None  #: the pinion's tip radius as made (a drawing's d_a/2) [m]; None: r + m_n (h_aP + x + k)
    tip_radius2: float | None = None  #: the gear's, likewise [m]

    def __post_init__(self):
        if self.kind not in KINDS:
            raise ValueError(f"kind must be one of {', '.join(KINDS)}, got {self.kind!r}")

    def identity(self) -> dict:
        """The pair's fields for a cache key: :func:`dataclasses.asdict` without the tip radii that are not
        given (so that a pair whose tips follow from its shifts keeps the key it had before tips were data)."""
        from dataclasses import asdict

        return {k: v for k, v in asdict(self).items() if v is not None}

    @property
    def n_helices(self) -> int:
        """Helices sharing the load: 2 for a double-helical pair, else 1."""
        return 2 if self.kind == "double-helical" else 1

    # ---------- transverse section ----------
    @property
    def m_t(self) -> float:
        """Transverse module m_t = m_n / cos β."""
        return self.m_n / math.cos(self.beta)

    @cached_property
    def alpha_t(self) -> float:
        """Transverse pressure angle, tan α_t = tan α_n / cos β."""
        return math.atan(math.tan(self.alpha_n) / math.cos(self.beta))

    @cached_property
    def beta_b(self) -> float:
        """Base helix angle, tan β_b = tan β cos α_t."""
        return math.atan(math.tan(self.beta) * math.cos(self.alpha_t))

    @property
    def u(self) -> float:
        """Gear ratio z2/z1."""
        return self.z2 / self.z1

    @property
    def r1(self) -> float:
        """Reference radius of the pinion, r = z m_t / 2."""
        return self.z1 * self.m_t / 2

    @property
    def r2(self) -> float:
        return self.z2 * self.m_t / 2

    @cached_property
    def rb1(self) -> float:
        """Base radius r_b = r cos α_t."""
        return self.r1 * math.cos(self.alpha_t)

    @cached_property
    def rb2(self) -> float:
        return self.r2 * math.cos(self.alpha_t)

    @cached_property
    def alpha_wt(self) -> float:
        """Working transverse pressure angle: inv α_wt = inv α_t + 2 tan α_n (x1+x2)/(z1+z2).

        Cached (a root of the involute function; the pair is frozen): the path-of-contact
        properties below are evaluated thousands of times per coupled run."""
        return inv_inverse(inv(self.alpha_t) + 2 * math.tan(self.alpha_n) * (self.x1 + self.x2) / (self.z1 + self.z2))

    @property
    def a(self) -> float:
        """Reference centre distance (r1 + r2)."""
        return self.r1 + self.r2

    @cached_property
    def a_w(self) -> float:
        """Working centre distance a_w = a cos α_t / cos α_wt."""
        return self.a * math.cos(self.alpha_t) / math.cos(self.alpha_wt)

    @cached_property
    def rw1(self) -> float:
        """Working pitch radius r_w = r_b / cos α_wt."""
        return self.rb1 / math.cos(self.alpha_wt)

    @cached_property
    def rw2(self) -> float:
        return self.rb2 / math.cos(self.alpha_wt)

    @cached_property
    def k_tip(self) -> float:
        """Tip alteration coefficient k = (a_w − a)/m_n − (x1 + x2) ≤ 0 (ISO 21771 §5.4)."""
        return (self.a_w - self.a) / self.m_n - (self.x1 + self.x2)

    def standard_tip_radius(self, member: int, shortened: bool = True) -> float:
        """Tip radius the rack and the shift give, r + m_n (h_aP + x + k) with ISO 21771's tip alteration k
        (``shortened``), else r + m_n (h_aP + x) [m]."""
        r, x = (self.r1, self.x1) if member == 1 else (self.r2, self.x2)
        return r + self.m_n * (self.h_aP + x + (self.k_tip if shortened else 0.0))

    @cached_property
    def ra1(self) -> float:
        """Tip radius: the given one (:attr:`tip_radius1`), else r_a = r + m_n (h_aP + x + k)."""
        return self.tip_radius1 if self.tip_radius1 is not None else self.standard_tip_radius(1)

    @cached_property
    def ra2(self) -> float:
        return self.tip_radius2 if self.tip_radius2 is not None else self.standard_tip_radius(2)

    @property
    def rf1(self) -> float:
        """Root radius r_f = r − m_n (h_fP − x)."""
        return self.r1 - self.m_n * (self.h_fP - self.x1)

    @property
    def rf2(self) -> float:
        return self.r2 - self.m_n * (self.h_fP - self.x2)

    @cached_property
    def p_bt(self) -> float:
        """Transverse base pitch p_bt = π m_t cos α_t."""
        return math.pi * self.m_t * math.cos(self.alpha_t)

    @property
    def p_bn(self) -> float:
        """Normal base pitch p_bn = π m_n cos α_n (= p_bt cos β_b)."""
        return math.pi * self.m_n * math.cos(self.alpha_n)

    # ---------- path of contact (transverse, measured from T1 on the pinion base circle) ----------
    @cached_property
    def line_of_action(self) -> float:
        """Length T1T2 = a_w sin α_wt of the transverse line of action between the base tangents."""
        return self.a_w * math.sin(self.alpha_wt)

    @cached_property
    def u_start(self) -> float:
        """T1A: start of contact (the gear's tip circle), distance from T1."""
        return self.line_of_action - math.sqrt(self.ra2**2 - self.rb2**2)

    @cached_property
    def u_end(self) -> float:
        """T1E: end of contact (the pinion's tip circle), distance from T1."""
        return math.sqrt(self.ra1**2 - self.rb1**2)

    @cached_property
    def u_pitch(self) -> float:
        """T1C: the pitch point, r_b1 tan α_wt."""
        return self.rb1 * math.tan(self.alpha_wt)

    def active_root_radius(self, member: int) -> float:
        """Radius of the lowest point of ``member``'s flank in contact (start of active profile, SAP): the
        pinion's at A, the gear's at E [m]."""
        if member == 1:
            return math.hypot(self.rb1, self.u_start)
        return math.hypot(self.rb2, self.line_of_action - self.u_end)

    @cached_property
    def g_alpha(self) -> float:
        """Length of the path of contact g_α = T1E − T1A."""
        return self.u_end - self.u_start

    @cached_property
    def eps_alpha(self) -> float:
        """Transverse contact ratio ε_α = g_α / p_bt."""
        return self.g_alpha / self.p_bt

    @property
    def eps_beta(self) -> float:
        """Overlap ratio of one helix ε_β = b sin β / (π m_n)."""
        return self.b * math.sin(self.beta) / (math.pi * self.m_n)

    @property
    def eps_gamma(self) -> float:
        """Total contact ratio of one helix ε_γ = ε_α + ε_β."""
        return self.eps_alpha + self.eps_beta

    @cached_property
    def mean_contact_length(self) -> float:
        """Time-mean total length of the contact lines of one helix, ε_α b / cos β_b [m]."""
        return self.eps_alpha * self.b / math.cos(self.beta_b)

    def tip_thickness(self, member: int) -> float:
        """Transverse tooth thickness on the tip circle of member 1 or 2 [m]."""
        z, x, ra = (self.z1, self.x1, self.ra1) if member == 1 else (self.z2, self.x2, self.ra2)
        r = z * self.m_t / 2
        s_t = self.m_t * (math.pi / 2 + 2 * x * math.tan(self.alpha_n))
        alpha_a = math.acos(r * math.cos(self.alpha_t) / ra)
        return 2 * ra * (s_t / (2 * r) + inv(self.alpha_t) - inv(alpha_a))

    def undercut_margin(self, member: int) -> float:
        """x − x_min, where x_min = h_a0 − z sin²α_t/(2 cos β) for the generating rack [-].

        The rack's straight flank ends at h_a0 = h_fP − ρ_fP (1 − sin α_n) above the
        datum line (ISO 21771 §6; Niemann & Winter §21.2).  Negative means undercut.
        """
        z, x = (self.z1, self.x1) if member == 1 else (self.z2, self.x2)
        h_a0 = self.h_fP - self.rho_fP * (1 - math.sin(self.alpha_n))
        x_min = h_a0 - z * math.sin(self.alpha_t) ** 2 / (2 * math.cos(self.beta))
        return x - x_min

    # ---------- construction ----------
    @classmethod
    def from_parameters(cls, **kw) -> GearPair:
        """Build and check a pair; raises :class:`SceneError` naming the scene key at fault."""
        pair = cls(**kw)
        pair.check()
        return pair

    def check(self) -> None:
        """Raise :class:`SceneError` if the pair cannot be made or does not mesh.  An undercut tooth can be
        made; whether its involute still carries the whole contact is
        :func:`femgear.case.pair.check_active_profile`'s question."""
        for member, name in ((1, "pinion"), (2, "gear")):
            if self.tip_thickness(member) <= 0:
                raise SceneError(f"{name}.profile_shift", f"the {name}'s teeth are pointed (tip thickness ≤ 0)")
        if self.rf1 <= 0 or self.rf2 <= 0:
            raise SceneError("pair.dedendum_coeff", "root radius ≤ 0")
        if self.u_start <= 0 and self.undercut_margin(1) < 0:
            raise SceneError(
                "pinion.profile_shift",
                f"involute interference: the pinion is undercut (x − x_min = {self.undercut_margin(1):.3f}) and the "
                f"gear's tip would meet it below its base circle (T1A = {self.u_start * 1e3:.3f} mm); raise "
                "pinion.profile_shift or pinion.teeth")
        if self.u_start <= 0:
            raise SceneError(
                "pair.addendum_coeff",
                "involute interference: contact would start below the pinion's base circle "
                f"(T1A = {self.u_start * 1e3:.3f} mm)",
            )
        if self.eps_alpha < 1:
            raise SceneError(
                "pair.addendum_coeff",
                f"transverse contact ratio ε_α = {self.eps_alpha:.3f} < 1: the teeth do not mesh continuously "
                "(raise pair.addendum_coeff or the tooth numbers pinion.teeth / gear.teeth)",
            )
