"""Initial separation of the flanks at contact points, from modifications and deviations.

Convention (normal to the flanks, metres, positive = gap): every amount of
:class:`femgear.scene.schema.FlankModification` is measured along the flank normal
(ISO 21771 states modifications normal to the flank; a value measured along the base
tangent in the transverse plane must be multiplied by cos β_b before it is entered).
A point of a helix is addressed by its roll distances (ρ₁ on the pinion, ρ₂ = T₁T₂ − ρ₁
on the gear) and its face coordinate ζ ∈ [0, b] with the groove at ζ = b (both helices
in their own mirrored coordinate, see :mod:`femgear.physics.ltca.contact`).

    ε = Σ_members [C_α(ρ_i) + C_β(ζ) + C_I(ζ) + topography_i(ρ_i, ζ)] + f_Hβ,h (b − ζ)/b + extra

- tip relief C_a ((ρ − ρ_Ca)/L_Ca)^e for ρ > ρ_Ca = ρ_tip − L_Ca; root relief
  C_f ((ρ_Cf − ρ)/L_Cf)^e for ρ < ρ_Cf = ρ_start + L_Cf; e = 1 linear, 2 parabolic;
- crowning C_β (2(ζ − b/2)/b)² (the circular arc of ISO 21771 to second order);
- end relief C_I max(0, 1 − ζ/L_I) + C_I max(0, 1 − (b − ζ)/L_I);
- helix slope deviation f_Hβ of the helix: 0 at the groove end, f_Hβ at the outer end;
- ``extra``: wear depth, thermal growth (negative) and pitch/profile deviation fields
  supplied by the caller (:data:`Deviation`).
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from femgear.errors import SceneError
from femgear.physics.geometry.gear import GearPair
from femgear.physics.ltca.flank import roll_range

#: extra(helix, member, rho, zeta) -> normal deviation of that member's flank [m] (+: material removed)
Deviation = Callable[[str, int, np.ndarray, np.ndarray], np.ndarray]


def tabulated_deviation(tables: dict) -> Deviation:
    """A :data:`Deviation` from arrays: ``tables[(helix, member)] = (rho, zeta, values)`` on a grid [m].

    ``rho`` (n,) roll distances and ``zeta`` (m,) face coordinates, ascending; ``values`` (n, m)
    the normal deviation (wear depth +, thermal growth −, pitch/profile deviation).  Bilinear,
    clamped to the grid; (helix, member) pairs not given contribute nothing.
    """
    from scipy.interpolate import RegularGridInterpolator

    interp = {}
    for key, (rho, zeta, values) in tables.items():
        values = np.asarray(values, float)
        if values.shape != (len(rho), len(zeta)) or not np.all(np.isfinite(values)):
            raise ValueError(f"deviation table {key}: values must be finite with shape (len(rho), len(zeta))")
        interp[key] = (np.asarray(rho, float), np.asarray(zeta, float), RegularGridInterpolator((rho, zeta), values))

    def extra(helix: str, member: int, rho: np.ndarray, zeta: np.ndarray) -> np.ndarray:
        if (helix, member) not in interp:
            return np.zeros(np.shape(rho))
        r, z, f = interp[(helix, member)]
        pts = np.column_stack([np.clip(np.ravel(rho), r[0], r[-1]), np.clip(np.ravel(zeta), z[0], z[-1])])
        return f(pts).reshape(np.shape(rho))

    return extra


def path_deviation(pair: GearPair, u: np.ndarray, removed: np.ndarray) -> Deviation:
    """A face-uniform :data:`Deviation` of both members from depths along the path of contact.

    ``removed`` (2, n): normal depth removed from the pinion's and the gear's drive flank
    (wear +, thermal growth −) at the path positions ``u`` (distance from T₁, ascending) [m],
    the same on both helices.  The pinion's flank point at u has roll distance ρ₁ = u, the
    gear's ρ₂ = T₁T₂ − u.
    """
    u = np.asarray(u, float)
    removed = np.asarray(removed, float)
    if removed.shape != (2, u.size) or u.size < 2 or np.any(np.diff(u) <= 0):
        raise ValueError("path_deviation: removed must be (2, n) at n >= 2 ascending path positions u")
    zeta = np.array([0.0, pair.b])
    tables = {}
    for helix in ("left", "right"):
        tables[(helix, 1)] = (u, zeta, np.repeat(removed[0][:, None], 2, axis=1))
        tables[(helix, 2)] = ((pair.line_of_action - u)[::-1], zeta, np.repeat(removed[1][::-1, None], 2, axis=1))
    return tabulated_deviation(tables)


def face_deviation(pair: GearPair, u: np.ndarray, zeta: np.ndarray, removed: np.ndarray) -> Deviation:
    """A face-resolved :data:`Deviation` of both members on both helices (:mod:`femgear.physics.wear.face`).

    ``removed`` (2, 2, n, m): normal depth removed from [member: pinion, gear][helix: left, right] at the
    path positions ``u`` (n, ascending) and face coordinates ``zeta`` (m, ascending) [m]; the gear's
    point at u has roll distance ρ₂ = T₁T₂ − u (as :func:`path_deviation`).
    """
    u, zeta, removed = np.asarray(u, float), np.asarray(zeta, float), np.asarray(removed, float)
    if removed.shape != (2, 2, u.size, zeta.size) or u.size < 2 or zeta.size < 2 or np.any(np.diff(u) <= 0):
        raise ValueError("face_deviation: removed must be (2 members, 2 helices, n, m) at n >= 2 ascending u "
                         "and m >= 2 face positions zeta")
    tables = {}
    for s, helix in enumerate(("left", "right")):
        tables[(helix, 1)] = (u, zeta, removed[0, s])
        tables[(helix, 2)] = ((pair.line_of_action - u)[::-1], zeta, removed[1, s][::-1])
    return tabulated_deviation(tables)


def _relief(x: np.ndarray, amount: float, length: float, shape: str) -> np.ndarray:
    e = 1.0 if shape == "linear" else 2.0
    return amount * np.clip(x / length, 0.0, None) ** e if amount > 0 else np.zeros_like(x)


def check_modification(pair: GearPair, member: int, mod) -> None:
    """Raise :class:`SceneError` if a relief is longer than the active profile or the face."""
    name = "pinion" if member == 1 else "gear"
    r0, r1 = roll_range(pair, member)
    for key in ("tip_relief_length", "root_relief_length"):
        if getattr(mod, key) > (r1 - r0) * (1 + 1e-9):
            raise SceneError(f"modifications.{key}", f"{getattr(mod, key) * 1e3:.3f} mm exceeds the {name}'s active "
                             f"profile roll length {(r1 - r0) * 1e3:.3f} mm")
    if mod.end_relief_length > pair.b / 2:
        raise SceneError("modifications.end_relief_length", f"{mod.end_relief_length * 1e3:.3f} mm exceeds half the "
                         f"face width of a helix ({pair.b * 1e3 / 2:.3f} mm)")


def member_deviation(pair: GearPair, member: int, mod, rho: np.ndarray, zeta: np.ndarray) -> np.ndarray:
    """Modification of ``member``'s flank at roll distances ``rho`` and face coordinates ``zeta`` [m]."""
    rho = np.asarray(rho, float)
    zeta = np.asarray(zeta, float)
    r0, r1 = roll_range(pair, member)
    b = pair.b
    out = _relief(rho - (r1 - mod.tip_relief_length), mod.tip_relief, mod.tip_relief_length or 1.0,
                  mod.tip_relief_shape)
    out = out + _relief((r0 + mod.root_relief_length) - rho, mod.root_relief, mod.root_relief_length or 1.0,
                        mod.root_relief_shape)
    out = out + mod.crowning * (2 * (zeta - b / 2) / b) ** 2
    if mod.end_relief > 0:
        L = mod.end_relief_length
        out = out + mod.end_relief * (np.clip(1 - zeta / L, 0, None) + np.clip(1 - (b - zeta) / L, 0, None))
    if mod.topography is not None:
        from scipy.interpolate import RegularGridInterpolator

        grid = np.asarray(mod.topography, float)
        interp = RegularGridInterpolator((np.linspace(0, 1, grid.shape[0]), np.linspace(0, 1, grid.shape[1])), grid)
        s = np.clip((rho - r0) / (r1 - r0), 0, 1)
        eta = np.clip((b - zeta) / b, 0, 1)
        out = out + interp(np.column_stack([s.ravel(), eta.ravel()])).reshape(rho.shape)
    return out


def separation(pair: GearPair, modifications, helix: str, u: np.ndarray, zeta: np.ndarray,
               extra: Deviation | None = None) -> np.ndarray:
    """Initial normal separation ε at contact points (path position ``u``, face coordinate ``zeta``) [m]."""
    if helix not in ("left", "right"):
        raise ValueError(f"helix must be 'left' or 'right', got {helix!r}")
    u = np.asarray(u, float)
    zeta = np.asarray(zeta, float)
    rho = {1: u, 2: pair.line_of_action - u}
    eps = np.zeros(u.shape)
    if modifications is not None:
        for member in (1, 2):
            eps = eps + member_deviation(pair, member, modifications.member(member), rho[member], zeta)
        f_hb = getattr(modifications, f"helix_slope_deviation_{helix}")
        eps = eps + f_hb * (pair.b - zeta) / pair.b
    if extra is not None:
        for member in (1, 2):
            eps = eps + np.asarray(extra(helix, member, rho[member], zeta), float)
    return eps
