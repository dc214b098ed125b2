"""VTK writer: fields survive a round trip (uniform ΔT: u = λΔT r, zero stress)."""

import math

import numpy as np
import pytest


def test_vtu_round_trip(tmp_path):
    pv = pytest.importorskip("pyvista")
    from femgear.physics.body.thermal import solve_temperature, thermo_elastic
    from femgear.physics.body.vtk import write_vtu
    from femgear.physics.mesh.section import annulus

    mesh = annulus(0.01, 0.03, 4e-3)
    temp = solve_temperature(mesh, 46.0, {"inner": 10.0, "outer": 10.0})
    res = thermo_elastic(mesh, temp, 210e9, 0.3, 1.2e-5, support="free", bore_radius=0.01)
    path = write_vtu(res, tmp_path / "ring.vtu", 210e9, 0.3, 1.2e-5)
    g = pv.read(path)
    np.testing.assert_allclose(g.point_data["temperature_rise"], 10.0, atol=1e-9)
    np.testing.assert_allclose(g.point_data["displacement"][:, :2], 1.2e-4 * g.points[:, :2], rtol=1e-6, atol=1e-14)
    assert np.max(g.cell_data["von_mises"]) < 1e-6 * 210e9 * 1.2e-4
    assert math.isfinite(float(np.sum(g.cell_data["von_mises"])))
