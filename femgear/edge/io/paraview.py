"""ParaView output: ``.pvd`` collections of ``.vtu`` files written with meshio.

:func:`write_collection` writes any list of frames (time, part, :class:`meshio.Mesh`)
as one ``.pvd`` file plus its ``.vtu`` files, each written atomically (a temporary
file renamed into place), the ``.pvd`` last, so that a collection that exists is complete.

:func:`write_run_paraview` writes the main job (:class:`femgear.results.RunResult`):

- ``flanks.pvd``: the active flank of one tooth of each member, both helices (the one helix of a
  single-helical or spur pair, in the mid-plane), as a surface over (profile, face width), with the fields along the path of contact
  mapped onto it by radius: ``hertz_pressure`` [Pa], ``film_central``,
  ``film_minimum`` [m], ``load_per_length`` [N/m], ``sliding_speed`` [m/s] and, where
  the scene computes them, ``friction_coefficient`` [-], ``temperature_rise`` [K],
  ``wear_depth`` [m], ``thermal_deviation`` [m].  The along-path model is per unit
  length of the contact line, so the fields are uniform across the face width.
- ``body.pvd`` (with ``thermal = "fe"``): the FE gear sections of both members with
  ``temperature_rise`` [K], ``displacement`` [m] and ``von_mises`` [Pa]
  (:func:`femgear.edge.io.paraview_run.body_frames`).
- ``flank_face.vtu`` (with ``wear.field = "face"`` or ``thermal = "fe3d"``): the face-resolved
  fields on the 3-D loaded flank of tooth 0 of both members, both helices, over (ρ, ζ):
  ``wear_depth`` [m] (the run's final face wear field, whose face mean is ``flanks.pvd``'s
  wear) and ``thermal_deviation`` [m] (ζ_T of the 3-D unit solutions at the run's bulk rise),
  with ``member``, ``helix``, ``u``, ``rho``, ``zeta``; each member's LTCA body frame turned into its
  meshing position, the gear's axis at (a_w, 0) (:func:`femgear.edge.io.paraview_run.face_mesh`).
- ``ltca_pressure.vtu`` (with ``stiffness = "ltca"``): the LTCA's pressure and load maps on the
  loaded flanks of both members in mesh (:mod:`femgear.physics.ltca.maps`): ``p_max``, ``w_mean``,
  ``w_worst``, ``edge``, ``edge_contact``, ``member``, ``helix``, ``rho``, ``u``, ``zeta``.
- ``dynamics.pvd`` (with a dynamics level): the last simulated mesh cycle as a time
  series: the working pitch circles of the four helix halves, with the vector
  ``displacement`` = d + θ × r of each body's six DOFs [m] (it includes the static
  torsional wind-up), ``vibration`` = the same about its mean over the cycle [m] (use
  *Warp By Vector* with a large scale factor to see it) and the helix's ``mesh_force`` [N]; part 1 the four
  bearing stations as points on the shaft axes with ``bearing_force`` (the load of the shaft on the bearing:
  x, y radial, z axial) and ``bearing_force_dynamic`` (about its mean over the record) [N].

Geometry (SI, the frame of :mod:`femgear.system.dynamics.layout`): shafts along z, pinion at
the origin, gear at (a_w, 0); the flanks touch at the pitch point (r_w1, 0) on the
line of centres.  A transverse involute point at radius r has roll angle
φ = √(r²/r_b² − 1) and polar angle inv α = φ − arctan φ; a helicoid turns it by
z tan β_b / r_b (ISO 21771), with opposite hands on the two members and the two helices.
"""

from __future__ import annotations

import os
import xml.etree.ElementTree as ET
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from femgear.edge.io.atomic import write_text_atomic


@dataclass(frozen=True)
class Frame:
    """One dataset of a collection: ``time`` [s] and ``part`` index as ParaView reads them."""

    time: float
    part: int
    name: str
    mesh: object  # meshio.Mesh (meshio imported lazily)


def write_vtu(path: str | Path, mesh, field_data: dict[str, np.ndarray] | None = None) -> Path:
    """Write a meshio ``mesh`` to ``path`` atomically (a temporary file, then a rename: complete or absent); the
    one VTK writer of femgear.  ``field_data``: arrays of the whole dataset (VTK ``FieldData``, which meshio reads
    back as ``mesh.field_data`` but does not write)."""
    import meshio

    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = path.with_name(f".{path.name}.{os.getpid()}.tmp")
    try:
        meshio.write(tmp, mesh, file_format="vtu", binary=True, compression=None)
        if field_data:
            _add_field_data(tmp, field_data)
        os.chmod(tmp, 0o644)
        os.replace(tmp, path)
    except BaseException:
        tmp.unlink(missing_ok=True)
        raise
    return path


def _add_field_data(path: Path, field_data: dict[str, np.ndarray]) -> None:
    """Insert a ``FieldData`` block (ASCII ``Float64`` arrays) as the first child of the file's ``UnstructuredGrid``."""
    tree = ET.parse(path)
    grid = tree.getroot().find("UnstructuredGrid")
    block = ET.Element("FieldData")
    for name, values in field_data.items():
        v = np.asarray(values, dtype=np.float64).ravel()
        array = ET.SubElement(block, "DataArray", type="Float64", Name=name, NumberOfTuples=str(v.size),
                              format="ascii")
        array.text = " ".join(repr(float(x)) for x in v)
    grid.insert(0, block)
    tree.write(path, xml_declaration=True, encoding="utf-8")


def write_collection(folder: str | Path, name: str, frames: Sequence[Frame]) -> Path:
    """Write ``<folder>/<name>.pvd`` and its ``.vtu`` files under ``<folder>/<name>/``."""
    folder = Path(folder)
    data_dir = folder / name
    data_dir.mkdir(parents=True, exist_ok=True)
    root = ET.Element("VTKFile", type="Collection", version="0.1", byte_order="LittleEndian")
    coll = ET.SubElement(root, "Collection")
    for i, frame in enumerate(frames):
        _check_finite(frame)
        file = data_dir / f"{frame.name}_{i:04d}.vtu"
        write_vtu(file, frame.mesh)
        ET.SubElement(coll, "DataSet", timestep=repr(float(frame.time)), group="", part=str(frame.part),
                      file=f"{name}/{file.name}", name=frame.name)
    ET.indent(root)
    pvd = folder / f"{name}.pvd"
    write_text_atomic(pvd, '<?xml version="1.0"?>\n' + ET.tostring(root, encoding="unicode") + "\n")
    return pvd


def collection_files(pvd: str | Path) -> list[Path]:
    """The ``.vtu`` files a ``.pvd`` collection names, in its order."""
    pvd = Path(pvd)
    return [pvd.parent / d.attrib["file"] for d in ET.parse(pvd).getroot().iter("DataSet")]


def _check_finite(frame: Frame) -> None:
    fields = list(frame.mesh.point_data.items())
    fields += [(k, np.concatenate(v)) for k, v in frame.mesh.cell_data.items()]
    for key, value in fields:
        if not np.all(np.isfinite(value)):
            raise ValueError(f"paraview: field {key!r} of {frame.name!r} is not finite")


def involute_points(rb: float, r: np.ndarray, angle0: float, sense: float) -> np.ndarray:
    """(n, 2) transverse involute points at radii ``r``, polar angle angle0 + sense·inv α(r)."""
    phi = np.sqrt(np.maximum(np.asarray(r, dtype=float) ** 2 / rb**2 - 1.0, 0.0))
    theta = angle0 + sense * (phi - np.arctan(phi))
    return np.column_stack([r * np.cos(theta), r * np.sin(theta)])


def flank_surface(rb: float, r: np.ndarray, centre: tuple[float, float], angle0: float, sense: float,
                  z: np.ndarray, z_ref: float, twist: float) -> tuple[np.ndarray, np.ndarray]:
    """Points (len(r)·len(z), 3) and quads of a helicoid flank turned by twist·(z − z_ref) [rad]."""
    base = involute_points(rb, r, angle0, sense)
    pts = []
    for zk in z:
        c, s = np.cos(twist * (zk - z_ref)), np.sin(twist * (zk - z_ref))
        xy = base @ np.array([[c, s], [-s, c]])
        pts.append(np.column_stack([xy[:, 0] + centre[0], xy[:, 1] + centre[1], np.full(len(r), zk)]))
    points = np.concatenate(pts)
    n, m = len(r), len(z)
    i, k = np.meshgrid(np.arange(n - 1), np.arange(m - 1), indexing="ij")
    a = (k * n + i).ravel()
    quads = np.column_stack([a, a + 1, a + n + 1, a + n])
    return points, quads


__all__ = ["Frame", "collection_files", "flank_surface", "involute_points", "write_collection", "write_vtu"]
