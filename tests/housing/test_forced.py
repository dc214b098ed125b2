"""The linear response per mesh order against the time integration it linearises (the same model, the same speed)."""

import numpy as np

from femgear.system.dynamics import run_dynamics
from femgear.system.dynamics.forced import mesh_excitation, order_response
from femgear.system.dynamics.housing import couple_housing, housing_acceleration
from femgear.system.dynamics.orders import mesh_orders


def _close(fd, td, tol):
    """Each order line of the frequency domain within ``tol`` of the largest time-domain line."""
    return np.max(np.abs(np.abs(fd) - td)) <= tol * np.max(td)


def test_orders_match_the_time_integration_on_a_rigid_housing(rigid_model):
    """Baseline, 500 rpm, no friction, contact-line stiffness (5.6 % ripple): the bearing-force orders 1–6 of the
    linear response equal the line fit of the time integration's record within 1 % of the largest line (measured
    0.4 %), the mesh-force orders within 2 % (measured 1.1 %: the mesh force k(t) δ(t) carries the product of the
    stiffness ripple and the deflection's, the parametric coupling the linear response leaves out)."""
    exc = mesh_excitation(rigid_model)
    assert exc.contact
    r = order_response(rigid_model, [500.0], 6, exc)
    run = run_dynamics(rigid_model, cycles=160, transient_cycles=80)
    assert _close(r.bearing_force[0], run.response.bearings.orders, 0.01)
    N_td = mesh_orders(run.response.mesh_force, run.response.t, rigid_model.mesh_frequency, 6)
    assert _close(r.mesh_force[0], N_td, 0.02)


def test_orders_match_the_time_integration_on_the_fe_housing(rigid_model, reduced):
    """The same on the coupled FE housing (bearings on the seats): bearing forces and the sensors' accelerations."""
    model = couple_housing(rigid_model, reduced)
    r = order_response(model, [500.0], 6, mesh_excitation(rigid_model))
    run = run_dynamics(model, cycles=100, transient_cycles=60)      # the housing's modes (ζ 0.02, > 700 Hz) decay
    assert run.settings.method == "rk4"                              # the default for more than 12 coordinates
    assert _close(r.bearing_force[0], run.response.bearings.orders, 0.02)
    s = run.simulation
    keep = s.t >= 60 * model.mesh_period - 1e-12
    a_td = mesh_orders(housing_acceleration(model, s.t[keep], s.q[keep], s.v[keep]), s.t[keep], model.mesh_frequency, 6)
    w = 2 * np.pi * r.frequency[0]
    a_fd = -(w**2)[:, None] * (model.housing.housing_part(r.state[0]) @ reduced.sensor_map.T)
    assert _close(a_fd, a_td, 0.02)
