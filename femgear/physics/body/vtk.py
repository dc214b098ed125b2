"""VTK output of a thermo-elastic result: temperature, displacement, von Mises stress.

pyvista is imported inside :func:`write_vtu` only.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np


def write_vtu(result, path: str | Path, youngs_modulus: float, poisson_ratio: float, expansion: float) -> Path:
    """Write ``result`` (:class:`femgear.physics.body.thermal.ThermoElasticResult`) as an unstructured grid.

    Point data at the mesh vertices: ``temperature_rise`` [K], ``displacement`` [m]
    (3-vector, z = 0); cell data: ``von_mises`` [Pa] (element mean).
    """
    import pyvista as pv

    mesh = result.mesh
    nv = mesh.p.shape[1]
    T = result.T[result.basis_T.nodal_dofs[0]] if result.basis_T.nodal_dofs.shape[0] == 1 else result.T[:nv]
    ux = result.u[result.basis_u.nodal_dofs[0]]
    uy = result.u[result.basis_u.nodal_dofs[1]]
    pts = np.column_stack([mesh.p.T, np.zeros(nv)])
    cells = np.column_stack([np.full(mesh.t.shape[1], 3), mesh.t.T]).ravel()
    grid = pv.UnstructuredGrid(cells, np.full(mesh.t.shape[1], 5, dtype=np.uint8), pts)
    grid.point_data["temperature_rise"] = T
    grid.point_data["displacement"] = np.column_stack([ux, uy, np.zeros(nv)])
    grid.cell_data["von_mises"] = result.von_mises(youngs_modulus, poisson_ratio, expansion)
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    grid.save(path)
    return path
