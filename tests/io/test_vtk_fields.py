"""The one VTK writer (meshio, :mod:`femgear.edge.io.fields`): body sections, TEHL film temperatures and EHL fields
read back with meshio hold their arrays; the grids are those the earlier pyvista writers produced (same point
order, cell types and arrays), checked against pyvista where it is installed."""

from __future__ import annotations

from types import SimpleNamespace

import meshio
import numpy as np
import pytest

from femgear.edge.io.fields import ehl_mesh, tehl_film_mesh, write_body_vtu, write_ehl_vtu, write_tehl_vtu


def test_body_section_round_trip_uniform_rise(tmp_path):
    """Free ring, uniform ΔT = 10 K: u = α ΔT r, zero stress (exact for the FE solution)."""
    from femgear.physics.body.fields import section_fields
    from femgear.physics.body.thermal import solve_temperature, thermo_elastic
    from femgear.physics.mesh.section import annulus

    mesh = annulus(0.01, 0.03, 4e-3)
    temp = solve_temperature(mesh, 46.0, {"inner": 10.0, "outer": 10.0})
    res = thermo_elastic(mesh, temp, 210e9, 0.3, 1.2e-5, support="free", bore_radius=0.01)
    section = section_fields(res, 1, 210e9, 0.3, 1.2e-5)
    g = meshio.read(write_body_vtu(tmp_path / "ring.vtu", section))
    assert [c.type for c in g.cells] == ["triangle"] and len(g.cells[0].data) == mesh.t.shape[1]
    np.testing.assert_allclose(g.point_data["temperature_rise"], 10.0, atol=1e-9)
    np.testing.assert_allclose(g.point_data["displacement"][:, :2], 1.2e-4 * g.points[:, :2], rtol=1e-6, atol=1e-14)
    assert np.all(g.point_data["displacement"][:, 2] == 0)
    vm = g.cell_data["von_mises"][0]
    assert np.all(np.isfinite(vm)) and np.max(vm) < 1e-6 * 210e9 * 1.2e-4


def _tehl(nt=6, nz=4):
    """A TEHL-result-shaped object with distinct values everywhere (the writer's layout is what is tested)."""
    rng = np.random.default_rng(1)
    b = 2e-4
    x = np.linspace(-3 * b, 1.5 * b, 31)
    x_cells = np.linspace(-2 * b, b, nt)
    return SimpleNamespace(b=b, x=x, p=1e9 * np.exp(-(x / b) ** 2), h=4e-7 + 1e-7 * (x / b) ** 2, x_cells=x_cells,
                           T_film=313.0 + rng.random((nt, nz)), T_surface1=313.0 + rng.random(nt),
                           T_surface2=313.0 + rng.random(nt))


def test_tehl_film_round_trip(tmp_path):
    r = _tehl()
    nt, nz = r.T_film.shape
    g = meshio.read(write_tehl_vtu(tmp_path / "t.vtu", r))
    assert [c.type for c in g.cells] == ["quad"] and len(g.cells[0].data) == nt * nz
    assert len(g.points) == (nt + 1) * (nz + 1)
    np.testing.assert_array_equal(g.cell_data["temperature"][0], r.T_film.ravel(order="F"))
    np.testing.assert_array_equal(g.field_data["surface_temperature_1"], r.T_surface1)
    np.testing.assert_array_equal(g.field_data["surface_temperature_2"], r.T_surface2)
    # every pixel's first point is its (x, ζ) lower-left corner, x fastest; z = ζ h(x) there
    first = g.points[g.cells[0].data[:, 0]]
    assert np.all(np.diff(first[:nt, 0]) > 0) and np.all(first[:nt, 1] == 0)
    h = np.interp(g.points[:, 0] * r.b, r.x, r.h)
    np.testing.assert_allclose(g.point_data["z"], g.points[:, 1] * h, rtol=1e-12)


def test_tehl_film_matches_the_rectilinear_grid_of_vtk(tmp_path):
    """The same points and cells as the rectilinear grid pyvista wrote before (its VTK_PIXELs as quads: the same
    corners, counter-clockwise)."""
    pv = pytest.importorskip("pyvista")
    r = _tehl()
    nt, nz = r.T_film.shape
    mesh, _ = tehl_film_mesh(r)
    dx = r.x_cells[1] - r.x_cells[0]
    xf = np.r_[r.x_cells - dx / 2, r.x_cells[-1] + dx / 2]
    grid = pv.RectilinearGrid(xf / r.b, np.linspace(0.0, 1.0, nz + 1), np.array([0.0]))
    ref = grid.cast_to_unstructured_grid()
    np.testing.assert_allclose(mesh.points, ref.points, rtol=1e-14, atol=1e-14)
    assert set(ref.celltypes) == {pv.CellType.PIXEL}
    pixels = ref.cells.reshape(-1, 5)[:, 1:]
    np.testing.assert_array_equal(mesh.cells[0].data, pixels[:, [0, 1, 3, 2]])


def _ehl(point: bool):
    x = np.linspace(-2.5, 1.5, 9)
    y = np.linspace(-2.0, 2.0, 5) if point else np.array([])
    shape = (y.size, x.size) if point else (x.size,)
    P = np.arange(np.prod(shape), dtype=float).reshape(shape) / 10
    return SimpleNamespace(x=x, y=y, P=P, H=1.0 + P, Hc=0.3, Hc_hertz=0.6)


@pytest.mark.parametrize("point", [True, False])
def test_ehl_round_trip(tmp_path, point):
    r = _ehl(point)
    g = meshio.read(write_ehl_vtu(tmp_path / "e", r))
    assert (tmp_path / "e.vtu").exists()
    n = r.x.size * max(r.y.size, 1)
    assert len(g.points) == n
    assert [c.type for c in g.cells] == (["quad"] if point else ["line"])
    np.testing.assert_array_equal(g.point_data["P"], np.atleast_2d(r.P).T.ravel(order="F"))
    np.testing.assert_allclose(g.point_data["H_moes"], g.point_data["H"] * 0.5, rtol=1e-15)
    # the value at point (x_i, y_j) is P[j, i]
    k = 3 + r.x.size * (2 if point else 0)
    assert g.points[k, 0] == r.x[3] and g.point_data["P"][k] == np.atleast_2d(r.P)[2 if point else 0, 3]


@pytest.mark.parametrize("point", [True, False])
def test_ehl_matches_the_structured_grid_of_vtk(point):
    pv = pytest.importorskip("pyvista")
    r = _ehl(point)
    mesh = ehl_mesh(r)
    y = r.y if point else np.zeros(1)
    X, Y, Z = np.meshgrid(r.x, y, [0.0], indexing="ij")
    ref = pv.StructuredGrid(X, Y, Z).cast_to_unstructured_grid()
    np.testing.assert_allclose(mesh.points, ref.points, rtol=0, atol=0)
    want = pv.CellType.QUAD if point else pv.CellType.LINE
    assert set(ref.celltypes) == {want}
    width = 5 if point else 3
    np.testing.assert_array_equal(mesh.cells[0].data, ref.cells.reshape(-1, width)[:, 1:])
