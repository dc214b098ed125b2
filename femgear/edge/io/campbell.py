"""Files of a Campbell diagram: ``campbell.json`` (the summary) and ``campbell.png``."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from femgear.edge.io.results import write_json
from femgear.system.dynamics.campbell import MESH_ENERGY_MIN, CampbellDiagram


def campbell_summary(d: CampbellDiagram) -> dict[str, Any]:
    """The JSON summary: ``speed_rpm``; per mode its ``frequency_hz`` over the speeds, ``mac_min`` (the worst MAC
    of its tracking), ``energy`` (strain-energy shares at each speed: ``mesh_L``, ``mesh_R``, ``bearing_<station>``,
    ``loop``, ``shafts``); the ``orders`` (label, member 0 = pinion / 1 = gear, multiple of that member's speed);
    ``critical_speeds`` (order, speed_rpm, frequency_hz, mode, energy there) with the criterion
    ``mesh_energy_min``.  Frequencies in Hz, speeds in rpm (driver), shares in [-]."""
    modes = [{"index": m, "frequency_hz": d.frequency[:, m].tolist(), "mac_min": float(d.mac[:, m].min()),
              "energy": {k: v[:, m].tolist() for k, v in d.energy.items()}} for m in range(d.frequency.shape[1])]
    return {"speed_rpm": d.speed_rpm.tolist(), "speed_ratio": list(d.speed_ratio), "teeth": list(d.teeth),
            "orders": [{"label": o[0], "member": ("pinion", "gear")[o[1]], "multiple": o[2]} for o in d.orders],
            "mesh_energy_min": MESH_ENERGY_MIN, "critical_speeds": list(d.critical), "modes": modes,
            "units": {"speed_rpm": "rpm", "frequency_hz": "Hz", "energy": "-"}}


def write_campbell(d: CampbellDiagram, folder: str | Path, plots: bool = True, name: str = "") -> dict[str, Path]:
    """Write ``campbell.json`` (and ``campbell.png``, titled with ``name``) into ``folder``."""
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    files = {"campbell_json": write_json(folder / "campbell.json", campbell_summary(d))}
    if plots:
        from femgear.edge.io.figures import save_figure
        from femgear.edge.plot.campbell import plot_campbell

        files["campbell_png"] = save_figure(plot_campbell(d, name=name), folder / "campbell.png")
    return files
