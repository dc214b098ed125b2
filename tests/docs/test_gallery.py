"""The gallery (``docs/gen/gallery.py``, the page ``gallery.md``) shows every figure femgear draws, and its committed
pictures are those of the current scenes, commands and plotting code (issue 42 item 7).

A figure whose recorded input digest is not the current one is stale: ``python docs/gen/gallery.py`` remakes the
stale ones (``make docs`` runs it; ``--check`` lists them).  A new ``plot_*`` function in ``femgear/edge/plot``
needs its entry in the table (one line: name, group, command, output, code, two lines to read).
"""

from __future__ import annotations

import ast
import importlib.util
import shlex
import sys
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[2]
PLOT = ROOT / "femgear" / "edge" / "plot"
#: the largest picture and the whole gallery [bytes]
MAX_BYTES, MAX_TOTAL = 400_000, 3_000_000


def _load(name: str):
    spec = importlib.util.spec_from_file_location(f"femgear_doc_{name}", ROOT / "docs" / "gen" / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module
    spec.loader.exec_module(module)
    return module


gallery = _load("gallery")


def test_every_picture_is_current():
    stale = gallery.stale()
    assert not stale, ("stale gallery figures (a scene, command or the code drawing them changed): run "
                       f"python docs/gen/gallery.py --only {','.join(f.name for f in stale)}")


def test_pictures_are_small_and_none_is_left_over():
    pngs = {p.stem: p.stat().st_size for p in gallery.GALLERY.glob("*.png")}
    assert set(pngs) == {f.name for f in gallery.FIGURES}, "a picture without its entry, or an entry without picture"
    big = {k: v for k, v in pngs.items() if v > MAX_BYTES}
    assert not big, f"pictures over {MAX_BYTES / 1e3:.0f} kB: {big}"
    assert sum(pngs.values()) < MAX_TOTAL
    recorded = gallery.read_manifest()
    assert set(recorded) == set(pngs)


def _plot_functions() -> set[str]:
    out = set()
    for path in sorted(PLOT.glob("*.py")):
        for node in ast.parse(path.read_text(encoding="utf-8")).body:
            if isinstance(node, ast.FunctionDef) and node.name.startswith("plot_"):
                out.add(f"{path.relative_to(ROOT).as_posix()}::{node.name}")
    return out


def test_every_figure_femgear_draws_is_in_the_gallery():
    drawn = {ref for f in gallery.FIGURES for ref in f.code}
    missing = sorted(_plot_functions() - drawn)
    assert not missing, f"plot functions without a gallery entry (docs/gen/gallery.py FIGURES): {missing}"


def test_entries_are_complete_and_their_code_exists():
    names = [f.name for f in gallery.FIGURES]
    assert len(names) == len(set(names))
    for f in gallery.FIGURES:
        assert f.group in gallery.GROUPS, f.name
        assert len(f.read) == 2 and all(len(line) > 40 for line in f.read), f.name
        assert f.code and all("::" in ref for ref in f.code), f.name
        for ref in f.code + gallery.COMMON + gallery.RENDER_CODE:
            assert gallery.code_text(ref), ref          # KeyError for a function that is gone
    assert {f.group for f in gallery.FIGURES} == set(gallery.GROUPS)


def test_commands_parse_and_their_scenes_load():
    """Every command is one the CLI accepts, and every scene it names loads with its overrides."""
    from femgear.edge.cli import build_parser
    from femgear.scene import load_scene

    parser = build_parser()
    for command in dict.fromkeys(f.command for f in gallery.FIGURES):
        args = shlex.split(command)
        assert args[0] == "femgear"
        ns = parser.parse_args(args[1:] + ["--out", "unused"])
        scene = getattr(ns, "scene", None)
        if scene is not None:
            load_scene(ROOT / scene, ns.overrides)
    sweep_files = [p for f in gallery.FIGURES for p in gallery.input_files(f.command) if "sweep" in f.command]
    assert sweep_files and all(p.exists() for p in sweep_files)


def test_a_changed_input_changes_the_digest(tmp_path, monkeypatch):
    """The digest sees the scene's data and the drawing code, not a scene's comments or a docstring."""
    fig = next(f for f in gallery.FIGURES if f.name == "baseline_dynamics_spectra")
    root = tmp_path / "repo"
    for ref in set(fig.code + gallery.COMMON):
        src = ROOT / ref.split("::")[0]
        (root / src.relative_to(ROOT)).parent.mkdir(parents=True, exist_ok=True)
        (root / src.relative_to(ROOT)).write_text(src.read_text(encoding="utf-8"), encoding="utf-8")
    scene = root / gallery.BASE
    scene.parent.mkdir(parents=True, exist_ok=True)
    scene.write_text((ROOT / gallery.BASE).read_text(encoding="utf-8"), encoding="utf-8")
    monkeypatch.setattr(gallery, "ROOT", root)
    before = gallery.inputs_digest(fig)
    scene.write_text(scene.read_text(encoding="utf-8") + "\n# a comment\n", encoding="utf-8")
    plot = root / "femgear/edge/plot/dynamics.py"
    plot.write_text(plot.read_text(encoding="utf-8").replace('"""Hanning-windowed', '"""Hann-windowed', 1),
                    encoding="utf-8")
    assert gallery.inputs_digest(fig) == before
    scene.write_text(scene.read_text(encoding="utf-8").replace("speed_rpm = 500.0", "speed_rpm = 600.0"),
                     encoding="utf-8")
    assert gallery.inputs_digest(fig) != before
    scene.write_text(scene.read_text(encoding="utf-8").replace("speed_rpm = 600.0", "speed_rpm = 500.0"),
                     encoding="utf-8")
    assert gallery.inputs_digest(fig) == before
    plot.write_text(plot.read_text(encoding="utf-8").replace("max_order: float = 32.0", "max_order: float = 40.0"),
                    encoding="utf-8")
    assert gallery.inputs_digest(fig) != before


def test_the_page_and_the_markers_show_every_entry():
    page = gallery.page()
    for f in gallery.FIGURES:
        assert f"(gallery/{f.name}.png)" in page and f.command in page and f.read[0] in page, f.name
    vibration = (ROOT / "docs" / "guide" / "vibration.md").read_text(encoding="utf-8")
    markers = gallery.MARKER.findall(vibration)
    assert {"baseline_dynamics_mesh_force", "marine_dynamics_spectra", "baseline_dynamics_sweep"} <= set(markers)
    expanded = gallery.expand(vibration, prefix="../")
    assert not gallery.MARKER.search(expanded) and "(../gallery/baseline_dynamics_sweep.png)" in expanded
    with pytest.raises(KeyError, match="no_such_figure"):
        gallery.expand("<!-- figure: no_such_figure -->")


def test_render_draws_a_field_on_a_flank(tmp_path):
    """The off-screen view of the gallery (docs/gen/render.py) colours a surface by its field: not a blank."""
    pytest.importorskip("pyvista")
    import meshio

    from femgear.edge.io.paraview import Frame, flank_surface, write_collection

    rb, z = 0.05, np.linspace(-0.01, 0.01, 9)
    pts, quads = flank_surface(rb, np.linspace(rb * 1.01, rb * 1.1, 12), (0.0, 0.0), 0.0, 1.0, z, 0.0, 8.0)
    field = np.linspace(0.0, 1.0, len(pts))
    mesh = meshio.Mesh(pts, [("quad", quads)], point_data={"p": field})
    pvd = write_collection(tmp_path, "flank", [Frame(time=0.0, part=0, name="flank", mesh=mesh)])
    render = _load("render")
    out = render.render_flank(pvd, "p", tmp_path / "flank.png", scale=1e3, label="p [kPa]", title="test")
    from PIL import Image

    image = np.asarray(Image.open(out).convert("RGB")).astype(int)
    covered = np.any(np.abs(image - image[0, 0]) > 30, axis=-1).mean()
    assert 0.02 < covered < 0.9
    assert len(np.unique(image.reshape(-1, 3), axis=0)) > 50       # shaded and coloured, not one flat colour
