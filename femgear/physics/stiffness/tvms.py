"""Time-varying mesh stiffness (TVMS) of a double-helical pair, per helix.

Convention (what the dynamics model consumes):

- ``phase`` is the mesh position in transverse base pitches; one mesh period is
  phase ∈ [0, 1).  Phase 0 is the instant used by
  :func:`femgear.physics.geometry.contact_lines`: the front (ζ = b) of a contact line enters
  the path at A.  At constant speed, phase = f_mesh · t.
- ``k_left``/``k_right`` are the stiffnesses of the left/right helix *along the normal
  line of action* [N/m]: F_n = k δ_n with δ_n the approach of the flanks measured
  normal to the teeth (δ_n = δ_t cos β_b for a transverse approach δ_t).
- The right helix is the left one shifted by ``stagger`` base pitches:
  k_right(φ) = k_left(φ + stagger), as in :func:`femgear.physics.geometry.double_helical_contact`.
- A single-helical or spur pair (``pair.kind``) has one mesh: ``k_left``; ``k_right`` is 0.

The contact lines over the face (notes §5; Ajmi & Velex 2005 for the limits of the thin-slice model): the
face point ζ ∈ [0, b] of contact line k sits at u = u_A − b tan β_b + (φ mod 1) p_bt + k p_bt + ζ tan β_b on the
path, a thin transverse slice whose stiffness per unit width is the tooth pair's k'(u).  Slices are uncoupled, so
the ripple is an upper bound and the mean a lower bound of a 3-D model.  A line's transverse stiffness is the
integral of k' over its part on the path, k_t = ∫ k'(u(ζ)) dζ = [K(u_hi) − K(u_lo)] / tan β_b with K the
antiderivative of k' and [u_lo, u_hi] the line's extent clipped to [u_A, u_E]; it projects to the normal line of
action as k_n = k_t / cos²β_b (F_t = F_n cos β_b, δ_n = δ_t cos β_b).  The integral is exact for the cubic
spline through the k'(u) samples: the table is continuous in φ however wide the face.  (A midpoint sum over N
slices, used before, made a staircase: each slice entering at A or leaving at E switched k'(u_A) Δb or k'(u_E) Δb
on or off within one phase sample: 0.6 % steps and one-sample notches on the marine pair, ε_β = 3.2, N = 100,
which excited the dynamic mesh force far above the mesh frequency.)
"""

from __future__ import annotations

import math
import time
from dataclasses import KW_ONLY, dataclass
from typing import TYPE_CHECKING

import numpy as np

from femgear.docfields import document_fields
from femgear.physics.geometry.gear import GearPair
from femgear.physics.stiffness.iso6336 import IsoStiffness

if TYPE_CHECKING:
    from scipy.interpolate import CubicSpline

U_SAMPLES = 161   #: path positions A..E at which the ``pem`` and ``fe`` levels sample k'(u)


@document_fields
@dataclass(frozen=True)
class FESamples:
    """The ``fe`` level's tooth-pair stiffness samples from the 2-D FE teeth in series with Hertz."""

    u: np.ndarray
    """path positions of the FE samples, measured from T1 (the pinion's base tangent point) [m]"""
    k: np.ndarray
    """transverse tooth-pair stiffness per unit face width at ``u`` [N/m²]"""
    compliance: tuple[np.ndarray, np.ndarray]
    """bending/shear/foundation compliance per unit face width of the pinion and the gear tooth at ``u`` [m²/N]"""
    ndofs: tuple[int, ...]
    """degrees of freedom of the pinion's and the gear's FE model [-]"""
    h: float | None
    """element size of the FE models at the flank [m]"""
    seconds: float
    """wall time of both members' FE models and solves [s]"""


@document_fields
@dataclass(frozen=True)
class MeshStiffness:
    """Mesh stiffness of both helices over one mesh period, along the normal line of action.

    The typed by-products of a level (its tooth-pair stiffness along the path, the ISO figures,
    the FE samples, the LTCA cycle) are None where the level has none."""

    level: str
    """the stiffness level that computed it (``constant``, ``iso6336``, ``pem``, ``fe``, ``ltca``) [-]"""
    phase: np.ndarray
    """sample phases over one mesh period, [0, 1); phase 0: the front of a contact line enters the path at A [base
    pitches]"""
    k_left: np.ndarray
    """stiffness of the left helix at ``phase``, along the normal line of action (F_n = k δ_n) [N/m]"""
    k_right: np.ndarray
    """stiffness of the right helix at ``phase`` (0 for a single-helical or spur pair) [N/m]"""
    stagger: float
    """offset of the right helix against the left one: k_right(φ) = k_left(φ + stagger) [base pitches]"""
    seconds: float
    """wall time to compute [s]"""
    _: KW_ONLY
    u: np.ndarray | None = None
    """``pem``, ``fe``: path positions of ``k_pair_per_width``, measured from T1 (the pinion's base tangent point) [m]"""
    k_pair_per_width: np.ndarray | None = None
    """``pem``, ``fe``: transverse stiffness of one tooth pair per unit face width at ``u`` (the shape of the
    contact-line stiffness along the path) [N/m²]"""
    iso: IsoStiffness | None = None
    """``iso6336``: the ISO 6336-1 Method B single and mesh stiffnesses the level's constant comes from [-]"""
    fe: FESamples | None = None
    """``fe``: the FE samples of the tooth-pair stiffness that ``k_pair_per_width`` interpolates [-]"""
    ltca: LTCACycle | None = None  # noqa: F821 (a higher tier's class, named not imported: docfields resolves it)
    """``ltca``: the loaded tooth contact analysis cycle whose secant stiffnesses are ``k_left``/``k_right`` (a
    :class:`femgear.physics.ltca.cycle.LTCACycle`, a higher tier: named, not imported) [-]"""

    @property
    def resolved_orders(self) -> int | None:
        """``ltca``: the mesh orders its contact discretisation resolves (the dynamics keeps those); else None."""
        return None if self.ltca is None else self.ltca.resolved_orders

    @property
    def k_total(self) -> np.ndarray:
        return self.k_left + self.k_right

    @property
    def mean_left(self) -> float:
        return float(np.mean(self.k_left))

    @property
    def mean_right(self) -> float:
        return float(np.mean(self.k_right))

    @property
    def mean(self) -> float:
        """Mean of the summed (left + right) stiffness [N/m]."""
        return float(np.mean(self.k_total))

    def ripple(self, helix: str = "total") -> float:
        """Peak-to-peak over mean of the left, right or total stiffness [-]."""
        k = {"left": self.k_left, "right": self.k_right, "total": self.k_total}[helix]
        if not np.any(k):
            return 0.0   # the absent right helix of a single-helical or spur pair
        return float((k.max() - k.min()) / k.mean())

    def at(self, phase, helix: str = "total"):
        """Periodic linear interpolation at ``phase`` [base pitches] for 'left', 'right' or 'total'."""
        k = {"left": self.k_left, "right": self.k_right, "total": self.k_total}[helix]
        ph = np.asarray(phase, float) % 1.0
        xp = np.concatenate([self.phase, [self.phase[0] + 1.0]])
        fp = np.concatenate([k, [k[0]]])
        return np.interp(ph, xp, fp)

    def __call__(self, phase):
        """(k_left, k_right) at ``phase`` [base pitches]."""
        return self.at(phase, "left"), self.at(phase, "right")


def helix_stiffness(pair: GearPair, u_samples: np.ndarray, k_samples: np.ndarray, phases: np.ndarray,
                    offset: float = 0.0) -> np.ndarray:
    """Normal stiffness [N/m] of one helix at ``phases`` (shifted by ``offset`` base pitches): every contact line's
    tooth-pair stiffness per width k'(u), given at path positions ``u_samples`` [m] by ``k_samples``
    [N/m per m] and interpolated by a cubic spline, integrated exactly over the line's part on the path
    (module docstring); a spur pair's line has one position: k'(u) b."""
    spline = tabulated(pair, np.asarray(u_samples, float), np.asarray(k_samples, float))
    tb = math.tan(pair.beta_b)
    span = pair.b * tb
    k_max = int(math.ceil((pair.g_alpha + span) / pair.p_bt)) + 2
    kk = np.arange(-1, k_max + 1)
    shift = ((np.asarray(phases, float) + offset) % 1.0) * pair.p_bt
    u0 = pair.u_start - span + shift[:, None] + kk[None, :] * pair.p_bt     # each line's face end ζ = 0
    if span == 0.0:
        inside = (u0 >= pair.u_start) & (u0 <= pair.u_end)
        k_t = np.where(inside, spline(u0), 0.0) * pair.b
    else:
        K = spline.antiderivative()
        lo = np.clip(u0, pair.u_start, pair.u_end)
        hi = np.clip(u0 + span, pair.u_start, pair.u_end)
        k_t = (K(hi) - K(lo)) / tb
    return k_t.sum(axis=1) / math.cos(pair.beta_b) ** 2


def tabulated(pair: GearPair, u_samples: np.ndarray, k_samples: np.ndarray) -> CubicSpline:
    """k'(u): the cubic spline through samples along the path, from A to E (``antiderivative()`` integrates it)."""
    from scipy.interpolate import CubicSpline

    return CubicSpline(u_samples, k_samples)


def check_period(n_positions: int, stagger: float) -> np.ndarray:
    """The ``n_positions`` phases i/n of one mesh period, after checking ``n_positions`` and ``stagger``."""
    if n_positions < 2:
        raise ValueError(f"n_positions must be ≥ 2, got {n_positions}")
    if not 0.0 <= stagger < 1.0:
        raise ValueError(f"stagger must be in [0, 1) base pitches, got {stagger}")
    return np.arange(n_positions) / n_positions


def uniform_mesh_stiffness(pair: GearPair, k: float, label: str, n_positions: int = 200, stagger: float = 0.0,
                           t0: float | None = None, **fields) -> MeshStiffness:
    """A mesh stiffness constant over the period: ``k`` per helix [N/m] (the ``constant`` and ``iso6336``
    levels); the right helix of a single-helical or spur pair is 0.  ``fields``: the level's other
    :class:`MeshStiffness` fields; ``t0``: when the level started (for ``seconds``)."""
    t0 = time.perf_counter() if t0 is None else t0
    phases = check_period(n_positions, stagger)
    kl = np.full(n_positions, k)
    kr = kl.copy() if pair.n_helices == 2 else np.zeros(n_positions)
    return MeshStiffness(label, phases, kl, kr, stagger, time.perf_counter() - t0, **fields)


def iso6336_helix_stiffness(pair: GearPair, youngs_modulus: float = 210e9):
    """(k, iso): ISO 6336-1's c_γα b read as a transverse stiffness per unit face width and projected to the
    normal line of action like the ``pem`` and ``fe`` levels, k = c_γα b / cos²β_b [N/m] per helix, and the ISO record."""
    from femgear.physics.stiffness.iso6336 import iso6336_stiffness

    iso = iso6336_stiffness(pair, youngs_modulus=youngs_modulus)
    return iso.k("c_gamma_alpha") / math.cos(pair.beta_b) ** 2, iso


def path_samples(pair: GearPair) -> np.ndarray:
    """The :data:`U_SAMPLES` path positions from A to E at which the ``pem`` and ``fe`` levels sample k'(u) [m]."""
    return np.linspace(pair.u_start, pair.u_end, U_SAMPLES)


def integrated_mesh_stiffness(pair: GearPair, u_grid: np.ndarray, k_grid: np.ndarray, label: str,
                              n_positions: int = 200, stagger: float = 0.0, t0: float | None = None,
                              fe: FESamples | None = None) -> MeshStiffness:
    """Mesh stiffness of both helices from the pair stiffness per width ``k_grid`` at path positions ``u_grid``
    (the ``pem`` and ``fe`` levels): k'(u) integrated over every contact line (:func:`helix_stiffness`).
    ``fe``: the ``fe`` level's FE samples; ``t0``: when the level started (for ``seconds``)."""
    t0 = time.perf_counter() if t0 is None else t0
    phases = check_period(n_positions, stagger)
    kl = helix_stiffness(pair, u_grid, k_grid, phases)
    kr = helix_stiffness(pair, u_grid, k_grid, phases, offset=stagger) if pair.n_helices == 2 else np.zeros_like(kl)
    return MeshStiffness(label, phases, kl, kr, stagger, time.perf_counter() - t0, u=u_grid,
                         k_pair_per_width=k_grid, fe=fe)
