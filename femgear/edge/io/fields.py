"""Fields of the physics results as meshio meshes, written by the one VTK writer (:func:`femgear.edge.io.paraview.write_vtu`).

- :func:`body_mesh`: a thermo-elastic gear section (:class:`femgear.physics.body.fields.BodySection`) as triangles
  with ``temperature_rise`` [K], ``displacement`` [m] (3-vector, z = 0) at the vertices and ``von_mises`` [Pa]
  per triangle;
- :func:`tehl_film_mesh`: the film temperature of one TEHL contact (:class:`femgear.physics.tehl.line.TEHLResult`)
  on the (x/b, ζ = z/h) grid as quads (the pixels of the 2-D rectilinear grid written before, in counter-clockwise
  node order: meshio has no pixel cell), ``temperature`` [K] per cell,
  ``z`` [m] and ``pressure`` [Pa] at the points, ``surface_temperature_1/2`` [K] as field data;
- :func:`ehl_mesh`: an EHL solution (:class:`femgear.physics.ehl.results.EHLResult`) on its node grid (quads of a
  point contact, lines of a line contact) with ``P``, ``H`` (Hertzian units) and ``H_moes`` at the points.

The grids are those the earlier pyvista writers wrote as ``.vtr``/``.vts`` (same points in the same order, x
fastest, same cells and arrays; the TEHL pixels as quads), now as ``.vtu``.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from femgear.edge.io.paraview import write_vtu


def body_mesh(section, offset: tuple[float, float] = (0.0, 0.0)):
    """A :class:`femgear.physics.body.fields.BodySection` as a meshio triangle mesh, shifted by ``offset`` [m]."""
    import meshio

    p = np.asarray(section.points, float)
    n = len(p)
    points = np.column_stack([p[:, 0] + offset[0], p[:, 1] + offset[1], np.zeros(n)])
    return meshio.Mesh(points, [("triangle", np.asarray(section.triangles))],
                       point_data={"temperature_rise": np.asarray(section.temperature_rise, float),
                                   "displacement": np.column_stack([section.displacement, np.zeros(n)])},
                       cell_data={"von_mises": [np.asarray(section.von_mises, float)]})


def write_body_vtu(path: str | Path, section) -> Path:
    """Write one gear section (:func:`body_mesh`) as ``.vtu``."""
    return write_vtu(path, body_mesh(section))


def _grid_quads(nx: int, ny: int) -> np.ndarray:
    """Quads (counter-clockwise) of an (nx, ny) point grid, points and cells numbered x fastest."""
    i, j = np.meshgrid(np.arange(nx - 1), np.arange(ny - 1), indexing="ij")
    a = (i + nx * j).ravel(order="F")
    return np.column_stack([a, a + 1, a + nx + 1, a + nx])


def tehl_film_mesh(result):
    """The film temperature field of one TEHL contact on the (x/b, ζ) grid (module docstring); returns
    (mesh, field_data)."""
    import meshio

    T = result.T_film                                    # (nt, nz) cell values
    nt, nz = T.shape
    dx = result.x_cells[1] - result.x_cells[0]
    xf = np.r_[result.x_cells - dx / 2, result.x_cells[-1] + dx / 2]
    zeta = np.linspace(0.0, 1.0, nz + 1)
    X, Z = np.meshgrid(xf / result.b, zeta, indexing="ij")
    points = np.column_stack([X.ravel(order="F"), Z.ravel(order="F"), np.zeros(X.size)])
    h_f = np.interp(xf, result.x, result.h)
    p_f = np.interp(xf, result.x, result.p)
    mesh = meshio.Mesh(points, [("quad", _grid_quads(nt + 1, nz + 1))],
                       point_data={"z": (h_f[:, None] * zeta[None, :]).ravel(order="F"),
                                   "pressure": np.repeat(p_f[:, None], nz + 1, 1).ravel(order="F")},
                       cell_data={"temperature": [np.asarray(T, float).ravel(order="F")]})
    field_data = {"surface_temperature_1": np.atleast_1d(result.T_surface1),
                  "surface_temperature_2": np.atleast_1d(result.T_surface2)}
    return mesh, field_data


def write_tehl_vtu(path: str | Path, result) -> Path:
    """Write one TEHL contact's film temperature (:func:`tehl_film_mesh`) as ``.vtu``."""
    mesh, field_data = tehl_film_mesh(result)
    return write_vtu(Path(path).with_suffix(".vtu"), mesh, field_data=field_data)


def ehl_mesh(result):
    """An EHL solution on its node grid (module docstring)."""
    import meshio

    y = result.y if result.P.ndim == 2 else np.zeros(1)
    X, Y = np.meshgrid(result.x, y, indexing="ij")
    points = np.column_stack([X.ravel(order="F"), Y.ravel(order="F"), np.zeros(X.size)])
    P, H = np.atleast_2d(result.P), np.atleast_2d(result.H)     # (ny, nx)
    fac = result.Hc / result.Hc_hertz if result.Hc_hertz else 1.0
    nx = result.x.size
    if y.size > 1:
        cells = [("quad", _grid_quads(nx, y.size))]
    else:
        cells = [("line", np.column_stack([np.arange(nx - 1), np.arange(1, nx)]))]
    return meshio.Mesh(points, cells, point_data={"P": P.T.ravel(order="F"), "H": H.T.ravel(order="F"),
                                                  "H_moes": H.T.ravel(order="F") * fac})


def write_ehl_vtu(path: str | Path, result) -> Path:
    """Write an EHL solution (:func:`ehl_mesh`) as ``.vtu``."""
    return write_vtu(Path(path).with_suffix(".vtu"), ehl_mesh(result))


__all__ = ["body_mesh", "ehl_mesh", "tehl_film_mesh", "write_body_vtu", "write_ehl_vtu", "write_tehl_vtu"]
