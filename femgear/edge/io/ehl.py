"""Files of ``femgear ehl point|line --out``: the fields as VTK, the centre line as PNG, the summary as JSON."""

from __future__ import annotations

from pathlib import Path

from femgear.edge.io.fields import write_ehl_vtu
from femgear.edge.io.results import write_json


def write_all(result, folder: str | Path, stem: str = "ehl") -> dict[str, str]:
    """``<stem>.vtu`` (:func:`femgear.edge.io.fields.ehl_mesh`), ``<stem>_centreline.png``
    (:func:`femgear.edge.plot.ehl.plot_centreline`) and ``<stem>.json`` (``result.summary()``) into ``folder``;
    returns the paths written."""
    from femgear.edge.io.figures import save_figure
    from femgear.edge.plot.ehl import plot_centreline

    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    return {"vtk": str(write_ehl_vtu(folder / f"{stem}.vtu", result)),
            "png": str(save_figure(plot_centreline(result), folder / f"{stem}_centreline.png")),
            "json": str(write_json(folder / f"{stem}.json", result.summary()))}


__all__ = ["write_all"]
