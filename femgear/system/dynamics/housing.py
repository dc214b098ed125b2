"""The gear-rotor model on a compliant housing: the bearings connect the shaft to the housing's seats.

:func:`couple_housing` joins a built :class:`GearRotorModel` (bearings to rigid ground) and a Craig–Bampton
reduced housing (:class:`femgear.physics.housing.fe.ReducedHousing`, coordinates w_H = (12 seat translations,
η)) into one model of n_R + n_H coordinates q' = (q, w_H).  Each bearing spring and dashpot then acts on the
bearing's deflection u_j − s_j (shaft at the station minus the housing seat) instead of on u_j:

    K' = diag(K − Bᵀ K_b B, K_H) + Lᵀ K_b L,    C' = diag(C − Bᵀ C̃_b B, C_H) + Lᵀ C̃_b L,    M' = diag(M, M_H),

with B the shaft's station displacements (``bearing_map``), L = [B, −S] (S: the seat translations of w_H),
K_b, C̃_b = C_b + a1 K_b the bearings' springs and dashpots (with the stiffness-proportional Rayleigh part a1 K_b
the rotor's damping gives them, so that the rotor's damping is exactly that of the rigid-housing model), and
C_H the housing's modal damping.  The mesh, the excitation and the rotor's Rayleigh coefficients are those of
the rigid-housing model; ``model.housing`` (:class:`HousingCoupling`) keeps the seat map and the housing's
output maps; the bearing forces (:mod:`femgear.system.dynamics.bearings`) are then the loads through the
bearings, K_b (u − s) + C̃_b (u̇ − ṡ).

The subtraction K − Bᵀ K_b B is exact where the bearing springs enter K additively: the ``lumped`` level
(rigid members on their bearings).  The ``timoshenko`` level condenses its bearing stations (Guyan) with the
springs to ground inside, so its stations cannot be re-connected without the uncondensed shaft; it is refused.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING

import numpy as np
from scipy.linalg import eigh

from femgear.system.dynamics.model import GearRotorModel

if TYPE_CHECKING:
    from femgear.physics.housing.fe import ReducedHousing


@dataclass(frozen=True)
class HousingCoupling:
    """What a model coupled to a housing carries about it (``GearRotorModel.housing``)."""

    n_rotor: int                 #: the rotor's coordinates come first, then the housing's [-]
    seat_map: np.ndarray         #: (12, n) displacement of the four seats (x, y, z) in the model's coordinates [-]
    reduced: ReducedHousing      #: the reduced housing and its output maps
    rigid: GearRotorModel        #: the same rotor on a rigid housing (the reference of the housing's effect)

    def housing_part(self, q: np.ndarray) -> np.ndarray:
        """The housing's coordinates of states ``q`` (..., n)."""
        return np.asarray(q)[..., self.n_rotor:]


def bearing_deflection_map(model: GearRotorModel) -> np.ndarray:
    """(12, n) deflection of the four bearings, shaft minus seat (the seat is ground without a housing)."""
    return model.bearing_map if model.housing is None else model.bearing_map - model.housing.seat_map


def couple_housing(model: GearRotorModel, housing: ReducedHousing) -> GearRotorModel:
    """``model`` with its bearings on the seats of ``housing`` (module docstring); ValueError for a model whose
    bearing stations are condensed (``timoshenko``) or that carries a housing already."""
    if model.housing is not None:
        raise ValueError("the model is coupled to a housing already")
    nR, nH = model.n, housing.n
    B = model.bearing_map
    if nR != 12:
        raise ValueError(f"the housing couples to the lumped dynamics level only: the {model.level!r} level condenses "
                         "its bearing stations with the springs to ground (module docstring)")
    kb = model.bearings.stiffness.ravel()
    cb = model.bearings.damping.ravel() + model.rayleigh[1] * kb
    S = np.zeros((12, nR + nH))
    S[:, nR:nR + 12] = np.eye(12)
    L = np.hstack([B, np.zeros((12, nH))]) - S

    def join(rotor, own, per_dof):
        out = np.zeros((nR + nH, nR + nH))
        out[:nR, :nR] = rotor - B.T @ (per_dof[:, None] * B)
        out[nR:, nR:] = own
        return out + L.T @ (per_dof[:, None] * L)

    K, C = join(model.K, housing.K, kb), join(model.C, housing.C, cb)
    M = np.zeros((nR + nH, nR + nH))
    M[:nR, :nR], M[nR:, nR:] = model.M, housing.M

    def pad(A):
        return np.hstack([A, np.zeros(A.shape[:-1] + (nH,))])

    coupled = replace(model, M=M, K=K, C=C, T=pad(model.T), G=pad(model.G), H0=pad(model.H0), H1=pad(model.H1),
                      bearing_map=pad(B))
    Km = coupled.mean_stiffness_matrix()
    w2 = eigh(Km, M, eigvals_only=True)
    flexible = w2[w2 > 1e-6 * w2.max()]
    return replace(coupled, flexible_modes_hz=tuple(np.sqrt(flexible) / (2 * math.pi)),
                   housing=HousingCoupling(n_rotor=nR, seat_map=S, reduced=housing, rigid=model))


def housing_acceleration(model: GearRotorModel, t: np.ndarray, q: np.ndarray, v: np.ndarray) -> np.ndarray:
    """(n_t, n_s) sensor accelerations along their directions of a recorded history of a coupled model [m/s²]."""
    a = model.acceleration(t, q, v)
    return model.housing.housing_part(a) @ model.housing.reduced.sensor_map.T
