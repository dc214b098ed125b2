"""The housing result of a run: the order sweep, the operating point's orders, the operating deflection shape.

:func:`housing_result` joins the frequency-domain sweep (:func:`femgear.system.dynamics.nvh.housing_sweep`), the
operating point read from the time integration where there is one (:func:`operating_orders`: order lines of the
recorded history, least squares over whole mesh periods; the FE housing's sensors and surface from its recorded
coordinates, the receiver's sensors from the recorded bearing forces), and the FE housing's deflection shape at
one speed and order (:func:`deflection_shape`, from the linear response).  A housing coupled by LM-FBS has no
time-domain form (its FRFs live in the frequency domain): its operating point is the linear response there.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from femgear.docfields import document_fields
from femgear.physics.housing import acoustics
from femgear.system.dynamics.bearings import bearing_forces
from femgear.system.dynamics.forced import mesh_excitation, order_response
from femgear.system.dynamics.housing import housing_acceleration
from femgear.system.dynamics.model import GearRotorModel
from femgear.system.dynamics.nvh import DeflectionShape, HousingSweep, housing_sweep
from femgear.system.dynamics.orders import line_fit, whole_periods


@document_fields
@dataclass(frozen=True)
class OperatingOrders:
    """Housing outputs per mesh order at the operating speed (complex amplitudes, phase at t = 0)."""

    speed: float
    """pinion speed [rev/min]"""
    source: str
    """"time integration" (order lines of the dynamics' record) or "linear" (the linear response per order) [-]"""
    frequency: np.ndarray
    """(n_order,) frequency of each mesh order [Hz]"""
    sensor_acceleration: np.ndarray
    """(n_order, n_sensor) acceleration of each sensor along its direction [m/s²]"""
    bearing_force: np.ndarray
    """(n_order, 4, 3) load through each bearing station [N]"""
    sound_power: np.ndarray | None
    """(n_order,) equivalent radiated power of the FE housing (σ = 1; None for FRFs) [W]"""


@document_fields
@dataclass(frozen=True)
class HousingResult:
    """What the housing layer computed (docs/models/housing.md)."""

    model: str
    """the housing model, ``housing.model`` [-]"""
    coupling: str
    """how the housing joins the rotor: craig-bampton (FE, in the dynamics), lm-fbs or receiver (FRFs) [-]"""
    sensors: tuple[str, ...]
    """sensor names, the order of every sensor axis [-]"""
    sensor_points: np.ndarray | None
    """(n_sensor, 3) the FE housing's sensor vertices (None for FRFs) [m]"""
    sensor_directions: np.ndarray | None
    """(n_sensor, 3) their unit directions (None for FRFs) [-]"""
    natural_frequencies: np.ndarray | None
    """flexible natural frequencies of the rotor on the FE housing (None for FRFs) [Hz]"""
    rigid_natural_frequencies: np.ndarray
    """flexible natural frequencies of the rotor on a rigid housing [Hz]"""
    housing_frequencies: np.ndarray | None
    """natural frequencies of the reduced FE housing alone, seats free (None for FRFs) [Hz]"""
    fixed_interface_hz: np.ndarray | None
    """the retained fixed-interface modes' frequencies (None for FRFs) [Hz]"""
    full_dofs: int
    """DOFs of the unreduced FE housing (0 for FRFs) [-]"""
    housing_mass: float | None
    """mass of the FE housing (None for FRFs) [kg]"""
    surface_area: float | None
    """area of the FE housing's radiating outer surface (None for FRFs) [m^2]"""
    reduction_check: object | None
    """``housing.check_reduction``: the Craig–Bampton frequencies against the unreduced housing's
    (:class:`femgear.levels.housing.ReductionCheck`) [-]"""
    sweep: HousingSweep
    """outputs per speed and mesh order [-]"""
    operating: OperatingOrders
    """outputs per mesh order at the operating speed [-]"""
    ods: DeflectionShape | None
    """the FE housing's operating deflection shape at ``housing.ods_speed_rpm`` and ``ods_order`` [-]"""
    ignored_inputs: tuple[str, ...]
    """receiver: seat DOFs the FRF set has no input for (their bearing forces reach no sensor) [-]"""
    linear_valid: bool
    """the quasi-static mesh forces stay positive, so the linearisation about the loaded mesh holds [-]"""
    points: np.ndarray | None = None
    """(3, n_vertices) the FE housing's mesh vertices (for the deflection shape) [m]"""
    cells: np.ndarray | None = None
    """(4, n_tets) its tetrahedra [-]"""


def operating_orders(model: GearRotorModel, layer, run, orders: int, impedance: float) -> OperatingOrders:
    """The orders at the operating speed: from the record of ``run`` (a :class:`DynamicsRun`) for the FE housing
    and the receiver, else (LM-FBS, or no run) from the linear response."""
    speed = 60.0 * model.mesh_frequency / model.pair.z1
    if run is None or layer.coupling == "lm-fbs":
        s = housing_sweep(model, layer, np.array([speed]), orders, impedance)
        return OperatingOrders(speed, "linear", s.frequency[0], s.sensor_acceleration[0], s.bearing_force[0],
                               None if s.sound_power is None else s.sound_power[0])
    sim = run.simulation
    keep = sim.t >= run.settings.transient_cycles * model.mesh_period - 1e-12
    t, q, v = sim.t[keep], sim.q[keep], sim.v[keep]
    sel = whole_periods(t, model.mesh_frequency)
    f = model.mesh_frequency * np.arange(1, orders + 1)
    F = line_fit(bearing_forces(model, q[sel], v[sel]), t[sel], f)[1]
    power = None
    if layer.coupling == "craig-bampton":
        red = model.housing.reduced
        acc = line_fit(housing_acceleration(model, t[sel], q[sel], v[sel]), t[sel], f)[1]
        vn = line_fit(model.housing.housing_part(v[sel]) @ red.surface_normal_map.T, t[sel], f)[1]
        power = acoustics.equivalent_radiated_power(red.surface_area, vn, impedance)
    else:
        H = layer.frf.receptance(np.clip(f, *layer.frf.frequency[[0, -1]]), layer.sensors)
        acc = -(2 * math.pi * f[:, None]) ** 2 * np.einsum("hsi,hi->hs", H, F.reshape(orders, 12))
        acc[~layer.frf.covers(f)] = 0.0
    return OperatingOrders(speed, "time integration", f, acc, F, power)


def deflection_shape(model: GearRotorModel, speed: float, order: int) -> DeflectionShape:
    """The coupled FE housing's deflection shape at pinion ``speed`` [rev/min] and mesh ``order`` (linear response;
    the excitation of the rigid-housing model, as the sweep's)."""
    red = model.housing.reduced
    r = order_response(model, np.array([speed]), order, mesh_excitation(model.housing.rigid))
    qh = model.housing.housing_part(r.state[0, order - 1])
    w = 2 * math.pi * r.frequency[0, order - 1]
    u = (red.vertex_map @ qh).reshape(-1, 3)
    vn = np.zeros(u.shape[0], dtype=complex)
    vn[red.outer_vertices] = 1j * w * (red.surface_normal_map @ qh)
    return DeflectionShape(speed=float(speed), order=int(order), frequency=float(r.frequency[0, order - 1]),
                           displacement=u, normal_velocity=vn)


def housing_result(model: GearRotorModel, layer, speeds: np.ndarray, orders: int, run=None,
                   ods: tuple[float, int] | None = None, impedance: float = acoustics.ZC_AIR) -> HousingResult:
    """The :class:`HousingResult` of ``layer`` (a :class:`~femgear.levels.housing.HousingLayer`) on ``model`` (coupled
    to an FE housing, or rigid); ``speeds``: pinion speeds of the sweep [rev/min]; ``run``: the dynamics run at the
    operating point (None: a static case); ``ods``: (pinion speed, order) of the deflection shape."""
    sweep = housing_sweep(model, layer, speeds, orders, impedance)
    operating = operating_orders(model, layer, run, orders, impedance)
    rigid = model.housing.rigid if model.housing is not None else model
    red = layer.reduced
    fe = red is not None
    shape = deflection_shape(model, *ods) if fe and ods is not None else None
    ignored = () if layer.frf is None or layer.coupling != "receiver" else layer.frf.missing_inputs
    return HousingResult(
        model=layer.name, coupling=layer.coupling, sensors=layer.sensors,
        sensor_points=red.sensor_points if fe else None, sensor_directions=red.sensor_directions if fe else None,
        natural_frequencies=np.array(model.flexible_modes_hz) if fe else None,
        rigid_natural_frequencies=np.array(rigid.flexible_modes_hz),
        housing_frequencies=red.frequencies() if fe else None, fixed_interface_hz=red.fixed_interface_hz if fe else None,
        full_dofs=layer.full_dofs, housing_mass=red.mass if fe else None,
        surface_area=float(red.surface_area.sum()) if fe else None, reduction_check=layer.check, sweep=sweep,
        operating=operating, ods=shape, ignored_inputs=ignored, linear_valid=mesh_excitation(rigid).contact,
        points=red.points if fe else None, cells=red.cells if fe else None)
