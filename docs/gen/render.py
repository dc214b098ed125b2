"""Off-screen pictures of femgear's ParaView output (pyvista), for the gallery (``docs/gen/gallery.py``).

:func:`render_flank` draws one member's flank surface of a ``.pvd`` set (``flanks.pvd`` of ``femgear run``,
``ltca_maps_T<torque>Nm.pvd`` of ``femgear ltca``) coloured by one of its point fields, seen face-on from
outside the tooth with the pinion's tip at the top and the face width across.

Rendering is off-screen through EGL (``VTK_DEFAULT_OPENGL_WINDOW=vtkEGLRenderWindow``; Mesa's llvmpipe on a
machine without a GPU: the system packages ``libegl1 libegl-mesa0 libgl1-mesa-dri``, which ``make sysdeps``
installs), so no display or X server is needed.  pyvista is in the ``render`` and ``test`` extras.
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

import numpy as np

#: pixels of the picture (width, height)
WINDOW = (1000, 520)
#: what a failed off-screen start needs, said in the one line that reports it
NEEDS = ("pyvista (pip install -e '.[render]') and an off-screen OpenGL: EGL with Mesa "
         "(apt-get install libegl1 libegl-mesa0 libgl1-mesa-dri, or `make sysdeps` as root)")


def _pyvista():
    os.environ.setdefault("VTK_DEFAULT_OPENGL_WINDOW", "vtkEGLRenderWindow")
    import pyvista as pv

    pv.OFF_SCREEN = True
    return pv


def view_direction(surface) -> np.ndarray:
    """Unit vector from the surface's centre towards the camera: the mean cell normal (each cell's normal turned
    to agree with the first, since the helices' quads need not share an orientation), in the transverse plane,
    on the side away from the gear axis (z)."""
    normals = surface.compute_normals(cell_normals=True, point_normals=False, consistent_normals=False,
                                      auto_orient_normals=False).cell_data["Normals"]
    n = (normals * np.sign(normals @ normals[0])[:, None]).mean(axis=0)
    n[2] = 0.0
    if not np.linalg.norm(n) > 0:
        raise ValueError("the surface has no transverse normal to look along")
    n /= np.linalg.norm(n)
    centre = np.asarray(surface.center, dtype=float)
    return n if n @ centre >= 0 else -n


def render_flank(pvd: str | Path, field: str, out: str | Path, *, scale: float = 1.0, label: str = "",
                 part: int = 0, title: str = "") -> Path:
    """PNG of the ``part``-th dataset of ``pvd`` (0: the pinion) coloured by point field ``field`` × ``scale``
    (the colour bar titled ``label``), face-on, tip up; returns ``out``."""
    pv = _pyvista()
    blocks = pv.get_reader(str(pvd)).read()
    if part >= len(blocks):
        raise ValueError(f"{pvd}: no dataset {part} (it holds {len(blocks)})")
    surface = blocks[part].extract_surface(algorithm="dataset_surface")
    if field not in surface.point_data:
        raise ValueError(f"{pvd}: no point field {field!r} (it has {', '.join(surface.point_data)})")
    surface[field] = np.asarray(surface[field], dtype=float) * scale
    d = view_direction(surface)
    centre = np.asarray(surface.center, dtype=float)
    radial = np.array([centre[0], centre[1], 0.0])
    plotter = pv.Plotter(off_screen=True, window_size=WINDOW, lighting="light kit")
    try:
        plotter.set_background("white")
        plotter.add_mesh(surface.compute_normals(consistent_normals=True, split_vertices=False),
                         scalars=field, cmap="viridis", smooth_shading=True, ambient=0.5, diffuse=0.5,
                         specular=0.0,
                         scalar_bar_args={"title": label or field, "position_x": 0.2, "position_y": 0.04,
                                          "width": 0.6, "fmt": "%.0f", "title_font_size": 16,
                                          "label_font_size": 14, "color": "black"})
        plotter.camera.focal_point = centre
        plotter.camera.position = centre + d * 10 * float(np.ptp(surface.points, axis=0).max())
        plotter.camera.up = radial / np.linalg.norm(radial)
        plotter.camera.elevation = 10.0          # a little from the tip side: the involute's curvature shows
        plotter.reset_camera()
        plotter.camera.zoom(1.6)
        if title:
            plotter.add_text(title, position="upper_left", font_size=11, color="black")
        plotter.screenshot(str(out))
    finally:
        plotter.close()
    return Path(out)


def main(argv: list[str] | None = None) -> int:
    """``python docs/gen/render.py PVD FIELD OUT [--scale S] [--label L] [--part N] [--title T]``: the gallery runs
    each view in its own process, so that an OpenGL that cannot start off-screen ends that process only."""
    import argparse

    ap = argparse.ArgumentParser(prog="python docs/gen/render.py", description=render_flank.__doc__)
    ap.add_argument("pvd")
    ap.add_argument("field")
    ap.add_argument("out")
    ap.add_argument("--scale", type=float, default=1.0)
    ap.add_argument("--label", default="")
    ap.add_argument("--part", type=int, default=0)
    ap.add_argument("--title", default="")
    args = ap.parse_args(argv)
    try:
        render_flank(args.pvd, args.field, args.out, scale=args.scale, label=args.label, part=args.part,
                     title=args.title)
    except (ImportError, RuntimeError, ValueError, OSError) as exc:
        print(f"render: {type(exc).__name__}: {exc} (needs {NEEDS})", file=sys.stderr)
        return 1
    return 0


__all__ = ["NEEDS", "main", "render_flank", "view_direction"]


if __name__ == "__main__":
    sys.exit(main())
