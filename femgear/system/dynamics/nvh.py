"""From the bearings to the sensor and the air: housing outputs per mesh order, over speed and at the operating point.

Three paths, by the housing's ``coupling`` (:class:`femgear.levels.housing.HousingLayer`):

- ``craig-bampton`` (FE housing): the model carries the reduced housing (:mod:`femgear.system.dynamics.housing`);
  the linear response per order (:func:`femgear.system.dynamics.forced.order_response`) of the coupled model gives
  the housing's coordinates, hence the sensors (a = −ω² s·u), the outer surface's normal velocity (v_n = iω n·u)
  and its equivalent radiated power (:mod:`femgear.physics.housing.acoustics`, σ = 1);
- ``receiver`` (FRFs seat → sensor): the bearing forces F of the model on a rigid housing drive the FRFs,
  a = −ω² H(ω) F (the housing is taken not to load the bearings: exact for a housing far stiffer than them);
- ``lm-fbs`` (FRFs with the seat-to-seat block): the rotor with its bearings' outer rings free (subsystem A) and
  the housing's receptances (B) are joined per frequency by LM-FBS (:mod:`femgear.physics.housing.fbs`); the
  interface forces are the bearing forces through the compliant seats.

Every path also runs the rigid housing (the reference of the housing's effect on the bearing and mesh forces).
The excitation is the rigid-housing model's effective transmission error in every path (the housing's static
compliance would shift the helices' load sharing by a little; an FRF set does not give the static compliance).
The outputs take the state amplitudes of any frequency-domain solver (:class:`OrderResponse`): a harmonic-balance
solution per order plugs in where :func:`order_response` is called.  At the operating speed the time integration
gives the same quantities from its record (:func:`operating_orders`: least-squares order lines).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from femgear.docfields import document_fields
from femgear.physics.housing import acoustics
from femgear.physics.housing.fbs import lm_fbs
from femgear.physics.housing.frf import SEAT_DOFS, FRFSet
from femgear.system.dynamics.forced import (
    OrderResponse,
    derived,
    dynamic_stiffness,
    mesh_excitation,
    mesh_forcing,
    order_response,
)
from femgear.system.dynamics.model import GearRotorModel


@document_fields
@dataclass(frozen=True)
class HousingSweep:
    """Housing outputs per speed and mesh order (complex amplitudes: x = Re X e^{iωt})."""

    speeds: np.ndarray
    """(n_speed,) pinion speeds [rev/min]"""
    frequency: np.ndarray
    """(n_speed, n_order) frequency of each order line [Hz]"""
    valid: np.ndarray
    """(n_speed, n_order) whether the housing model covers the line (an FRF set: inside its frequency grid) [-]"""
    sensor_acceleration: np.ndarray
    """(n_speed, n_order, n_sensor) acceleration of each sensor along its direction, 0 where not ``valid`` [m/s²]"""
    bearing_force: np.ndarray
    """(n_speed, n_order, 4, 3) load through each bearing station on the housing model [N]"""
    mesh_force: np.ndarray
    """(n_speed, n_order, 2) dynamic mesh force of the left and right helix on the housing model [N]"""
    rigid_bearing_force: np.ndarray
    """(n_speed, n_order, 4, 3) the same bearing loads with a rigid housing [N]"""
    rigid_mesh_force: np.ndarray
    """(n_speed, n_order, 2) the same mesh forces with a rigid housing [N]"""
    sound_power: np.ndarray | None
    """(n_speed, n_order) equivalent radiated power of the FE housing's outer surface (σ = 1; None for FRFs) [W]"""

    @property
    def sound_power_level(self) -> np.ndarray | None:
        """(n_speed, n_order) L_W = 10 lg(P/1 pW) of each order [dB]."""
        return None if self.sound_power is None else acoustics.power_level(self.sound_power)

    @property
    def overall_sound_power_level(self) -> np.ndarray | None:
        """(n_speed,) the orders' power sum [dB re 1 pW]."""
        return None if self.sound_power is None else acoustics.power_level(self.sound_power.sum(axis=1))

    @property
    def overall_a_weighted(self) -> np.ndarray | None:
        """(n_speed,) the orders' power sum, each A-weighted at its frequency (IEC 61672-1) [dB(A) re 1 pW]."""
        if self.sound_power is None:
            return None
        return acoustics.total_level(self.sound_power_level + acoustics.a_weighting(self.frequency), axis=1)

    def force_change(self) -> dict[str, np.ndarray]:
        """Relative change of the housing against the rigid housing per valid line: ``bearing`` |ΔF|/|F_rigid| (the
        radial loads of the four stations as one vector) and ``mesh`` |ΔN|/|N_rigid| (both helices) [-]."""
        dF = np.linalg.norm((self.bearing_force - self.rigid_bearing_force)[..., :2].reshape(self.valid.shape + (-1,)),
                            axis=-1)
        F = np.linalg.norm(self.rigid_bearing_force[..., :2].reshape(self.valid.shape + (-1,)), axis=-1)
        dN = np.linalg.norm(self.mesh_force - self.rigid_mesh_force, axis=-1)
        N = np.linalg.norm(self.rigid_mesh_force, axis=-1)
        ok = self.valid & (F > 0) & (N > 0)
        return {"bearing": dF[ok] / F[ok], "mesh": dN[ok] / N[ok]}


@document_fields
@dataclass(frozen=True)
class DeflectionShape:
    """The FE housing's operating deflection shape at one speed and mesh order."""

    speed: float
    """pinion speed [rev/min]"""
    order: int
    """mesh order [-]"""
    frequency: float
    """the order's frequency [Hz]"""
    displacement: np.ndarray
    """(n_vertices, 3) complex displacement amplitude of every mesh vertex [m]"""
    normal_velocity: np.ndarray
    """(n_vertices,) complex outward normal velocity amplitude, 0 off the outer surface [m/s]"""


def _fe_outputs(model: GearRotorModel, r: OrderResponse, impedance: float) -> tuple[np.ndarray, np.ndarray]:
    """(sensor accelerations (S, H, n_s), ERP (S, H)) of a coupled FE housing's order response."""
    red = model.housing.reduced
    w = 2 * math.pi * r.frequency
    qh = model.housing.housing_part(r.state)
    sensors = -(w**2)[..., None] * (qh @ red.sensor_map.T)
    vn = 1j * w[..., None] * (qh @ red.surface_normal_map.T)
    return sensors, acoustics.equivalent_radiated_power(red.surface_area, vn, impedance)


def housing_sweep(model: GearRotorModel, layer, speeds: np.ndarray, orders: int,
                  impedance: float = acoustics.ZC_AIR) -> HousingSweep:
    """The outputs of ``layer`` (a :class:`~femgear.levels.housing.HousingLayer`) per mesh order 1 … ``orders``
    at the pinion ``speeds`` [rev/min] (module docstring); ``model``: coupled to an FE housing, or rigid;
    ``impedance``: ρc of the air [N s/m^3]."""
    rigid_model = model.housing.rigid if model.housing is not None else model
    exc = mesh_excitation(rigid_model)
    rigid = order_response(rigid_model, speeds, orders, exc)
    power = None
    if layer.coupling == "craig-bampton":
        r = order_response(model, speeds, orders, exc)
        sensors, power = _fe_outputs(model, r, impedance)
        valid = np.ones(r.frequency.shape, bool)
    elif layer.coupling == "receiver":
        r = rigid
        sensors, valid = receiver(rigid, layer.frf, layer.sensors)
    else:
        r, sensors, valid = lm_fbs_response(rigid_model, layer.frf, layer.sensors, speeds, orders)
    return HousingSweep(speeds=rigid.speeds, frequency=rigid.frequency, valid=valid, sensor_acceleration=sensors,
                        bearing_force=r.bearing_force, mesh_force=r.mesh_force,
                        rigid_bearing_force=rigid.bearing_force, rigid_mesh_force=rigid.mesh_force, sound_power=power)


def receiver(r: OrderResponse, frf: FRFSet, sensors: tuple[str, ...]) -> tuple[np.ndarray, np.ndarray]:
    """(sensor accelerations (S, H, n_s), valid (S, H)): a = −ω² H_sensor,seat(ω) F of the bearing forces ``F`` of
    ``r`` at every line inside the FRF grid (0 outside)."""
    f = r.frequency
    valid = frf.covers(f)
    out = np.zeros(f.shape + (len(sensors),), dtype=complex)
    if valid.any():
        H = frf.receptance(f[valid], sensors)                                 # (n, n_s, 12)
        F = r.bearing_force[valid].reshape(-1, 12)
        out[valid] = -(2 * math.pi * f[valid][:, None]) ** 2 * np.einsum("nsi,ni->ns", H, F)
    return out, valid


def rotor_receptance(model: GearRotorModel, omega: float) -> np.ndarray:
    """Y_A(ω): receptance of the rotor with the outer rings of its bearings as 12 free DOFs (after its own)."""
    n = model.n
    kb = model.bearings.stiffness.ravel()
    kc = kb + 1j * omega * (model.bearings.damping.ravel() + model.rayleigh[1] * kb)
    B = model.bearing_map
    Z = np.zeros((n + 12, n + 12), dtype=complex)
    Z[:n, :n] = dynamic_stiffness(model, omega)           # with the bearings to ground: Bᵀ K_c B is in it
    Z[:n, n:] = -(B.T * kc)
    Z[n:, :n] = -(kc[:, None] * B)
    Z[n:, n:] = np.diag(kc)
    return np.linalg.inv(Z)


def lm_fbs_response(model: GearRotorModel, frf: FRFSet, sensors: tuple[str, ...], speeds: np.ndarray,
                    orders: int) -> tuple[OrderResponse, np.ndarray, np.ndarray]:
    """(order response of the coupled rotor, sensor accelerations, valid) of the rigid-housing ``model`` joined
    to the FRF housing by LM-FBS at every line inside the FRF grid (module docstring); the bearing forces are the
    interface forces λ (the loads through the bearings on the compliant seats), 0 outside the grid."""
    exc = mesh_excitation(model)
    E, X = exc.harmonics(orders)
    k = np.arange(1, orders + 1)
    speeds = np.atleast_1d(np.asarray(speeds, dtype=float))
    f = np.outer(speeds * model.pair.z1 / 60.0, k)
    valid = frf.covers(f)
    n = model.n
    Q = np.zeros(f.shape + (n,), dtype=complex)
    lam = np.zeros(f.shape + (12,), dtype=complex)
    acc = np.zeros(f.shape + (len(sensors),), dtype=complex)
    outputs = SEAT_DOFS + tuple(sensors)
    for i, j in zip(*np.nonzero(valid)):
        w = 2 * math.pi * f[i, j]
        fA = np.concatenate([mesh_forcing(model, w, E[j], X[j]), np.zeros(12)])
        YB = frf.receptance(np.array([f[i, j]]), outputs)[0]                  # (12 + n_s, 12)
        uA, uB, lam[i, j] = lm_fbs(rotor_receptance(model, w), fA, np.arange(n, n + 12), YB, np.arange(12))
        Q[i, j], acc[i, j] = uA[:n], -w**2 * uB[12:]
    r = derived(model, speeds, k, f, Q, E, X, exc.contact)
    return OrderResponse(speeds=speeds, orders=k, frequency=f, state=Q, mesh_force=np.where(valid[..., None],
                         r.mesh_force, 0.0), bearing_force=lam.reshape(f.shape + (4, 3)), contact=exc.contact), acc, valid
