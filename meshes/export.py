"""Export the baseline's gmsh meshes for inspection in ParaView or gmsh.

    python meshes/export.py [SCENE] [--h MESH_SIZE]

femgear meshes on the fly through the gmsh API (:mod:`femgear.mesh`, one mesh size
knob, local refinement at the contact point), so no reference mesh is stored in git.
This writes, into ``out/meshes/``: the pinion's and the gear's transverse sections
(three teeth down to the bore) and both helices of the pinion as 3-D tetrahedral
meshes, as ``.vtu`` via meshio, with the named boundaries as cell sets.
"""

from __future__ import annotations

import argparse
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def main(argv: list[str] | None = None) -> list[Path]:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("scene", nargs="?", default=str(ROOT / "studies" / "paper_baseline.toml"))
    p.add_argument("--h", type=float, default=None, help="mesh size [m] (default m_n/4)")
    args = p.parse_args(argv)

    from femgear.geometry import GearPair
    from femgear.mesh.section import double_helical_member, gear_section
    from femgear.scene import load_scene

    pair = GearPair.from_scene(load_scene(args.scene))
    h = args.h or pair.m_n / 4
    out = ROOT / "out" / "meshes"
    out.mkdir(parents=True, exist_ok=True)
    written = []
    for member, name in ((1, "pinion"), (2, "gear")):
        path = out / f"{name}_section.vtu"
        gear_section(pair, member, h).save(str(path))
        written.append(path)
    left, right = double_helical_member(pair, 1, min(2 * h, pair.m_n / 2.5))
    for mesh, side in ((left, "left"), (right, "right")):
        path = out / f"pinion_helix_{side}.vtu"
        mesh.save(str(path))
        written.append(path)
    for path in written:
        print(path)
    return written


if __name__ == "__main__":
    main()
