"""The pressure map of an LTCA cycle on the 3-D pinion flank, as a VTK file for ParaView (meshio, lazily).

The flank of the pinion's tooth 0 (left helix, :func:`femgear.ltca.flank.flank_points`) is
tessellated on a (ρ, ζ) grid; each node carries the largest Hertz pressure over the cycle
(``p_max``) and the cycle-mean load per length (``w_mean``) of the contact points that
passed within half a grid cell, so the map shows where the flank is loaded and how hard.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np


def flank_pressure_map(result, pair, youngs_modulus: float, poisson_ratio: float, n_rho: int = 40,
                       n_z: int = 60) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(ρ grid, ζ grid, p_max[n_rho, n_z]) of the left helix from ``result.line_load`` [m, m, Pa]."""
    from femgear.ltca.flank import roll_range
    from femgear.ltca.halfspace import hertz_pressure, reduced_modulus

    if not result.line_load:
        raise ValueError("result has no line loads: run mesh_cycle(..., keep_lines=True)")
    r0, r1 = roll_range(pair, 1)
    rho = np.linspace(r0, r1, n_rho)
    zeta = np.linspace(0.0, pair.b, n_z)
    pmax = np.zeros((n_rho, n_z))
    cb = math.cos(pair.beta_b)
    Ep = reduced_modulus(youngs_modulus, poisson_ratio)
    for arr in result.line_load:
        s = arr[:, 0] == 0
        u, z, w = arr[s, 2], arr[s, 3], arr[s, 4]
        R = u * (pair.line_of_action - u) / pair.line_of_action / cb
        p = hertz_pressure(w, R, Ep)
        i = np.clip(np.rint((u - r0) / (r1 - r0) * (n_rho - 1)).astype(int), 0, n_rho - 1)
        j = np.clip(np.rint(z / pair.b * (n_z - 1)).astype(int), 0, n_z - 1)
        np.maximum.at(pmax, (i, j), p)
    return rho, zeta, pmax


def write_flank_pressure(path: str | Path, result, pair, youngs_modulus: float, poisson_ratio: float) -> Path:
    """Write the pressure map on the 3-D pinion flank as VTK unstructured quads (``.vtu``)."""
    import meshio

    from femgear.ltca.flank import flank_points

    rho, zeta, pmax = flank_pressure_map(result, pair, youngs_modulus, poisson_ratio)
    R, Z = np.meshgrid(rho, zeta, indexing="ij")
    pts = flank_points(pair, 1, R.ravel(), Z.ravel()).T
    nr, nz = R.shape
    idx = np.arange(nr * nz).reshape(nr, nz)
    quads = np.column_stack([idx[:-1, :-1].ravel(), idx[1:, :-1].ravel(), idx[1:, 1:].ravel(), idx[:-1, 1:].ravel()])
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    meshio.write(path, meshio.Mesh(pts, [("quad", quads)], point_data={"p_max": pmax.ravel(), "rho": R.ravel()}))
    return path
