"""File output of EHL results: VTK fields (pyvista) and centre-line plots (matplotlib).

Both libraries are imported inside the functions, so importing femgear.physics.ehl stays light.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from femgear.physics.ehl.core.results import EHLResult


def write_vtk(result: EHLResult, path: str | Path) -> Path:
    """Write P and H (Hertzian units) and H in Moes units as a structured grid (.vts)."""
    import pyvista as pv

    path = Path(path).with_suffix(".vts")
    path.parent.mkdir(parents=True, exist_ok=True)
    y = result.y if result.P.ndim == 2 else np.zeros(1)
    X, Y, Z = np.meshgrid(result.x, y, [0.0], indexing="ij")
    grid = pv.StructuredGrid(X, Y, Z)
    P = np.atleast_2d(result.P)  # (ny, nx)
    H = np.atleast_2d(result.H)
    fac = result.Hc / result.Hc_hertz if result.Hc_hertz else 1.0
    grid.point_data["P"] = P.T.ravel(order="F")
    grid.point_data["H"] = H.T.ravel(order="F")
    grid.point_data["H_moes"] = H.T.ravel(order="F") * fac
    grid.save(str(path))
    return path


def plot_centreline(result: EHLResult, path: str | Path) -> Path:
    """PNG of P and H along Y = 0 (point) or along X (line)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    path = Path(path).with_suffix(".png")
    path.parent.mkdir(parents=True, exist_ok=True)
    if result.P.ndim == 2:
        j0 = int(np.argmin(np.abs(result.y)))
        P, H = result.P[j0], result.H[j0]
    else:
        P, H = result.P, result.H
    fig, ax = plt.subplots(figsize=(7, 4))
    ax.plot(result.x, P, "b-", label="P = p/p_h")
    ax.set_xlabel("X = x/a")
    ax.set_ylabel("P", color="b")
    ax2 = ax.twinx()
    ax2.plot(result.x, H, "r-", label="H")
    ax2.set_ylabel("H = h R/a^2", color="r")
    ax2.set_ylim(0, 3 * max(result.Hc_hertz, 1e-12))
    ax.set_title(f"{result.kind} contact M={result.M:g} L={result.L:g}: "
                 f"Hc={result.Hc:.4g}, Hmin={result.Hmin:.4g} (Moes)")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return path


def _jsonable(o):
    if isinstance(o, np.ndarray):
        return o.tolist()
    if isinstance(o, np.generic):
        return o.item()
    raise TypeError(type(o).__name__)


def write_all(result: EHLResult, folder: str | Path, stem: str = "ehl") -> dict[str, str]:
    """VTK + PNG + summary JSON into ``folder``; returns the paths written."""
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    out = {"vtk": str(write_vtk(result, folder / stem)),
           "png": str(plot_centreline(result, folder / f"{stem}_centreline"))}
    js = folder / f"{stem}.json"
    js.write_text(json.dumps(result.summary(), indent=1, default=_jsonable))
    out["json"] = str(js)
    return out
