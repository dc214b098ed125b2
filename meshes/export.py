"""Export the meshes the baseline's solvers use, for inspection in ParaView.

    python meshes/export.py [SCENE] [--level N] [--h MESH_SIZE] [--out DIR]

femgear meshes on the fly (gmsh through :mod:`femgear.physics.mesh`), so no reference mesh is stored in
git.  This writes into ``DIR`` (default ``out/meshes/``), as ``.vtu`` via meshio:

- ``pinion_body.vtu``, ``gear_body.vtu``: the 3-D member bodies the LTCA solves
  (:func:`femgear.physics.mesh.segment.member_body`: both helices of opposite hand, the groove, the
  stagger, the rack-generated flank and trochoid fillet, the rim down to the bore), built from the
  scene as :func:`femgear.levels.stiffness.body_options` does, at body resolution ``--level`` (default 1,
  the ``ltca`` stiffness level's);
- ``pinion_section.vtu``, ``gear_section.vtu``: the 2-D transverse sections (three teeth down to
  the bore) of the ``fe`` levels, mesh size ``--h`` (default m_n/4).

Each file holds the volume (or area) cells with ``region`` = 0 and its named boundary facets as
triangles (lines in 2-D) with ``region`` = the tag of their name; the tag → name table is written
next to it as ``<name>_regions.json`` (with the facet count of each region), so in ParaView a
Threshold on ``region`` picks one: the flanks per helix, tooth and side
(``flank_<left|right>_t<k>_<drive|coast>``, :func:`femgear.physics.mesh.segment.flank_regions`), ``fillet``,
``tip``, ``bore``, ``rim``, ``end0``/``end1``, ``groove_wall``/``groove_floor``.  The regions partition
the boundary: every boundary facet is written once.
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path

import numpy as np

from femgear.case import build_case
from femgear.case.pair import pair_from_scene
from femgear.levels.stiffness import body_options

ROOT = Path(__file__).resolve().parents[1]
AGGREGATES = ("flank", "loaded_flank", "loaded_flank_right")   #: unions of other regions (not written twice)


def write_regions(path: Path, mesh, regions: dict[str, np.ndarray], aliases: dict[str, str] | None = None) -> dict:
    """Write a skfem mesh and its named boundary ``regions`` (facet indices, disjoint) as ``.vtu`` + the name table.

    Returns the table {name: {"tag": int, "facets": int}} (also in ``<stem>_regions.json``).
    """
    import meshio

    from femgear.edge.io.atomic import write_text_atomic
    from femgear.edge.io.paraview import write_vtu

    dim = mesh.p.shape[0]
    cell_type, facet_type = ("tetra", "triangle") if dim == 3 else ("triangle", "line")
    names = sorted(regions)
    facets = np.concatenate([regions[n] for n in names]) if names else np.zeros(0, np.int64)
    if np.unique(facets).size != facets.size:
        raise ValueError(f"{path.name}: the regions overlap (a facet would be written twice)")
    tags = np.concatenate([np.full(regions[n].size, i + 1) for i, n in enumerate(names)])
    points = mesh.p.T if dim == 3 else np.column_stack([mesh.p.T, np.zeros(mesh.p.shape[1])])
    out = meshio.Mesh(points, [(cell_type, mesh.t.T), (facet_type, mesh.facets[:, facets].T)],
                      cell_data={"region": [np.zeros(mesh.t.shape[1], np.int32), tags.astype(np.int32)]})
    write_vtu(path, out)
    table = {n: {"tag": i + 1, "facets": int(regions[n].size)} for i, n in enumerate(names)}
    info = {"file": path.name, "region_tag": table, "volume_tag": 0, "aliases": aliases or {}}
    write_text_atomic(path.with_name(path.stem + "_regions.json"), json.dumps(info, indent=1))
    return table


def body_regions(body, pair, member: int, spec) -> tuple[dict, dict]:
    """The body's boundary partitioned by name (the flanks per helix, tooth and side) and the aliases of the
    LTCA's loaded flanks."""
    from femgear.physics.mesh.segment import flank_regions

    regions = {n: f for n, f in body.boundaries.items() if n not in AGGREGATES}
    regions.update(flank_regions(body, pair, member, spec))
    aliases = {"loaded_flank": "flank_left_t+0_drive", "loaded_flank_right": "flank_right_t+0_drive"}
    return regions, aliases


def export(scene_path: str, level: int = 1, h: float | None = None, out: Path | None = None) -> list[Path]:
    """Write the member bodies and the transverse sections of the scene; return the ``.vtu`` paths."""
    from femgear.physics.mesh.section import gear_section
    from femgear.physics.mesh.segment import default_spec, member_body
    from femgear.scene import load_scene

    scene = load_scene(scene_path)
    pair = pair_from_scene(scene)
    body = body_options(build_case(scene))
    out = Path(out) if out is not None else ROOT / "out" / "meshes"
    written = []
    for member, name in ((1, "pinion"), (2, "gear")):
        spec = default_spec(pair, member, level, r_bore=body["bore_radius"][member - 1],
                            groove=body["groove_width"], stagger=body["stagger"])
        mesh = member_body(pair, member, spec)
        regions, aliases = body_regions(mesh, pair, member, spec)
        write_regions(out / f"{name}_body.vtu", mesh, regions, aliases)
        written.append(out / f"{name}_body.vtu")
        sec = gear_section(pair, member, h or pair.m_n / 4)
        write_regions(out / f"{name}_section.vtu", sec, dict(sec.boundaries))
        written.append(out / f"{name}_section.vtu")
    return written


def main(argv: list[str] | None = None) -> list[Path]:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("scene", nargs="?", default=str(ROOT / "studies" / "paper_baseline.toml"))
    p.add_argument("--level", type=int, default=1, help="member-body resolution level (default 1, the ltca level's)")
    p.add_argument("--h", type=float, default=None, help="2-D section mesh size [m] (default m_n/4)")
    p.add_argument("--out", type=Path, default=None, help="output folder (default out/meshes)")
    args = p.parse_args(argv)
    written = export(args.scene, args.level, args.h, args.out)
    for path in written:
        print(path)
    return written


if __name__ == "__main__":
    main()
