"""Bearing forces of the gear-rotor model, from the model and a state history (every dynamics level).

Each member runs on two bearing stations (:data:`femgear.system.dynamics.structure.STATIONS`:
pinion_L, pinion_R, gear_L, gear_R), each a linear spring K_j and dashpot C_j per direction
x, y (radial) and z (axial, the thrust bearing) between the shaft and the housing (rigid ground, or the seats of
a compliant housing, :mod:`femgear.system.dynamics.housing`: u_j is then the bearing's deflection, shaft minus
seat).  The
force a station carries, i.e. the load the shaft puts on the bearing and the housing
(positive along +x, +y, +z of the model frame), is

    F_j(t) = K_j u_j + (C_j + a1 K_j) u̇_j,        u_j = B_j q   (``model.bearing_map``),

with u_j the displacement of the shaft at the station (a point of the rigid member for
``lumped``, the condensed bearing node of the shaft for ``timoshenko``) and a1 K_j the
stiffness-proportional Rayleigh damping of the bearing springs (``model.rayleigh``; the
shafts' own part of a1 K_struct is internal and cancels in any resultant).  F_j is linear in
the state: F = K_F q + C_F q̇ (:func:`force_matrices`), so a frequency-domain solution gives the
bearing-force harmonics from the state harmonics with the same two matrices.

Newton's law (:func:`newton_balance`): per member and direction, the translational inertia
of the member (``rᵀ M q̈``, r its rigid translation in the reduced coordinates) equals the
mesh force on it, the external force (unbalance) and minus its bearing forces, less the
Rayleigh mass-proportional term a0 rᵀ M_f q̇, which damps each body to ground directly (a
modelling device of the damping fit, not carried by a bearing).  The stiffness part of the
balance is exact at every level (the shaft's internal forces cancel); for ``timoshenko`` the
Guyan condensation weights the bearing dashpots by the condensed node's share w_j of the kept
nodes' rigid translation (``rᵀ C_red q̇ = Σ w_j C_j u̇_j``): the balance lists that term too.

Statics (:func:`static_bearing_loads`): the loads of the static state
(:meth:`GearRotorModel.static_state`); their sum per member balances the static mesh force
on it, and their moments its moment (the axial force's at the pitch radius included).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from femgear.docfields import document_fields
from femgear.system.dynamics.housing import bearing_deflection_map
from femgear.system.dynamics.model import GearRotorModel
from femgear.system.dynamics.orders import ORDERS, mesh_orders
from femgear.system.dynamics.structure import STATIONS

AXES = ("x", "y", "z")


def force_matrices(model: GearRotorModel) -> tuple[np.ndarray, np.ndarray]:
    """(K_F, C_F), each (4, 3, n): the station loads F = K_F q + C_F q̇ [N/m, N s/m] (module docstring)."""
    b = model.bearings
    B = bearing_deflection_map(model).reshape(4, 3, model.n)
    a1 = model.rayleigh[1]
    return b.stiffness[..., None] * B, (b.damping + a1 * b.stiffness)[..., None] * B


def bearing_forces(model: GearRotorModel, q: np.ndarray, v: np.ndarray) -> np.ndarray:
    """Loads of the four stations for states ``q``, ``v`` (..., n) in reduced coordinates: (..., 4, 3) [N]."""
    KF, CF = force_matrices(model)
    return np.einsum("jdn,...n->...jd", KF, q) + np.einsum("jdn,...n->...jd", CF, v)


def static_bearing_loads(model: GearRotorModel) -> np.ndarray:
    """(4, 3) loads of the stations in the static state of the mean system [N]."""
    return bearing_forces(model, model.static_state(), np.zeros(model.n))


@document_fields
@dataclass(frozen=True)
class BearingLoads:
    """The loads of the four bearing stations over the recorded mesh cycles, and their summary."""

    stations: tuple[str, ...]
    """station names, the order of the station axis (pinion_L, pinion_R, gear_L, gear_R) [-]"""
    force: np.ndarray
    """(n_t, 4, 3) load of each station along x, y (radial) and z (axial): the force of the shaft on the bearing [N]"""
    mean: np.ndarray
    """(4, 3) time mean of ``force`` over the record [N]"""
    peak_to_peak: np.ndarray
    """(4, 3) max − min of ``force`` over the record [N]"""
    orders: np.ndarray
    """(H, 4, 3) amplitude (half peak-to-peak) of mesh orders 1 … H of ``force``, over whole mesh periods [N]"""

    @property
    def radial_mean(self) -> np.ndarray:
        """(4,) magnitude of the mean radial load √(F̄x² + F̄y²) [N]."""
        return np.hypot(self.mean[:, 0], self.mean[:, 1])


def bearing_loads(model: GearRotorModel, t: np.ndarray, q: np.ndarray, v: np.ndarray,
                  orders: int = ORDERS) -> BearingLoads:
    """:class:`BearingLoads` of a recorded history (times ``t`` [s], reduced states ``q``, ``v`` (n_t, n))."""
    F = bearing_forces(model, q, v)
    return BearingLoads(stations=STATIONS, force=F, mean=F.mean(axis=0), peak_to_peak=np.ptp(F, axis=0),
                        orders=mesh_orders(F, t, model.mesh_frequency, orders))


def translation_vectors(model: GearRotorModel) -> np.ndarray:
    """(2, 3, n) reduced coordinates r of a unit rigid translation of each member along x, y, z."""
    r_full = np.zeros((2, 3, 24))
    for member in range(2):
        for d in range(3):
            r_full[member, d, [12 * member + d, 12 * member + 6 + d]] = 1.0
    r, *_ = np.linalg.lstsq(model.T, r_full.reshape(6, 24).T, rcond=None)
    if not np.allclose(model.T @ r, r_full.reshape(6, 24).T, atol=1e-12):
        raise ValueError("the model's coordinates do not contain the members' rigid translations")
    return r.T.reshape(2, 3, model.n)


def newton_balance(model: GearRotorModel, t: np.ndarray, q: np.ndarray, v: np.ndarray,
                   a: np.ndarray) -> dict[str, np.ndarray]:
    """The terms of Newton's law per member and direction, each (n_t, 2, 3) [N] (module docstring):

    ``inertia`` rᵀ M q̈; the forces on the member: ``mesh`` (mesh and friction), ``external`` (unbalance),
    ``bearings`` (−Σ F_j of its stations), ``body_damping`` (−a0 rᵀ M_f q̇, Rayleigh's mass term) and
    ``guyan_damping`` (Σ_j (1 − w_j) C_j u̇_j, the dashpot share the condensation moves off the stations: zero
    for rigid members); ``residual`` = inertia − the forces.
    """
    r = translation_vectors(model)
    _, _, Q = model.mesh_forces(t, q, v)
    B = model.bearing_map.reshape(4, 3, model.n)
    u_dot = np.einsum("jdn,...n->...jd", B, v)

    def per_member(x):                     # (..., 4, 3) by station → (..., 2, 3) by member
        return x.reshape(x.shape[:-2] + (2, 2, 3)).sum(axis=-2)

    w = np.einsum("jdn,mcn->jdmc", B, r)   # station j's motion along d under member m's translation along c
    applied = np.einsum("jdmc,jd,...jd->...mc", w, model.bearings.damping, u_dot)   # rᵀ C_b,red q̇
    C_rest = model.C - model.rayleigh[1] * model.K                                     # C_b,red + a0 M_f
    terms = {"inertia": np.einsum("mdn,nk,...k->...md", r, model.M, a),
             "mesh": np.einsum("mdn,...n->...md", r, Q),
             "external": np.einsum("mdn,...n->...md", r, model.external_force(t)),
             "bearings": -per_member(bearing_forces(model, q, v)),
             "body_damping": applied - np.einsum("mdn,nk,...k->...md", r, C_rest, v),
             "guyan_damping": per_member(model.bearings.damping * u_dot) - applied}
    terms["residual"] = terms["inertia"] - sum(terms[k] for k in ("mesh", "external", "bearings", "body_damping",
                                                                  "guyan_damping"))
    return terms
