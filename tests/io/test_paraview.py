"""ParaView output: the .pvd sets of the main job open with meshio (names, sizes, finite
values) and render off-screen with pyvista to a non-empty picture (not kept)."""

from __future__ import annotations

import os
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest

from femgear.edge.io.paraview import flank_surface, involute_points

ROOT = Path(__file__).resolve().parents[2]
BASE = ROOT / "studies" / "paper_baseline.toml"
FLANK_FIELDS = {"hertz_pressure", "film_central", "film_minimum", "load_per_length", "sliding_speed",
                "friction_coefficient", "temperature_rise", "wear_depth", "thermal_deviation"}


def test_involute_points_lie_at_their_radius_with_the_involute_polar_angle():
    rb = 0.05
    r = np.linspace(rb, 1.2 * rb, 7)
    p = involute_points(rb, r, 0.0, 1.0)
    assert np.allclose(np.hypot(*p.T), r, rtol=1e-14)
    alpha = np.arccos(rb / r)
    assert np.allclose(np.arctan2(p[:, 1], p[:, 0]), np.tan(alpha) - alpha, atol=1e-14)


def test_helicoid_turns_by_the_base_helix_lead():
    rb, twist = 0.05, np.tan(0.5) / 0.05
    pts, quads = flank_surface(rb, np.array([rb, 1.1 * rb]), (0.0, 0.0), 0.0, 1.0, np.array([0.0, 0.01]), 0.0, twist)
    assert quads.shape == (1, 4)
    turn = np.arctan2(pts[2, 1], pts[2, 0]) - np.arctan2(pts[0, 1], pts[0, 0])
    assert turn == pytest.approx(twist * 0.01, rel=1e-12)


@pytest.fixture(scope="module")
def main_job(tmp_path_factory):
    """The main job with wear on (so every flank field exists), written by the CLI."""
    from femgear.edge.cli import main

    out = tmp_path_factory.mktemp("pv") / "run"
    assert main(["-q", "run", str(BASE), "--out", str(out), "--no-plots", "--set", "wear.cycles=1e5",
                 "--set", 'physics.preset="fast"']) == 0
    return out


def _datasets(pvd: Path) -> list[dict]:
    return [d.attrib for d in ET.parse(pvd).getroot().iter("DataSet")]


def test_flanks_pvd_has_both_members_with_finite_fields(main_job):
    import json

    import meshio

    entries = _datasets(main_job / "flanks.pvd")
    assert [e["part"] for e in entries] == ["0", "1"]
    n_path = len(json.loads((main_job / "results.json").read_text())["along_path"]["s"])
    for e in entries:
        mesh = meshio.read(main_job / e["file"])
        assert set(mesh.point_data) == FLANK_FIELDS
        quads = mesh.cells_dict["quad"]                         # 2 helices x 9 points across the face
        assert len(mesh.points) == 2 * 9 * n_path and len(quads) == 2 * 8 * (n_path - 1)
        for name, values in mesh.point_data.items():
            assert values.shape == (len(mesh.points),) and np.all(np.isfinite(values)), name
        assert mesh.point_data["hertz_pressure"].min() > 1e8
        assert mesh.point_data["wear_depth"].max() > 0


def test_dynamics_pvd_is_one_mesh_cycle_of_finite_displacements(main_job):
    import meshio

    every = _datasets(main_job / "dynamics.pvd")
    entries = [e for e in every if e["part"] == "0"]
    times = np.array([float(e["timestep"]) for e in entries])
    assert 10 <= len(entries) <= 50 and times[0] == 0 and np.all(np.diff(times) > 0)
    f_m = 31 * 500 / 60
    assert times[-1] == pytest.approx(1 / f_m, rel=0.05)
    mesh = meshio.read(main_job / entries[len(entries) // 2]["file"])
    u, w = mesh.point_data["displacement"], mesh.point_data["vibration"]
    assert u.shape == w.shape == (4 * 72, 3) and np.all(np.isfinite(u)) and np.all(np.isfinite(w))
    assert 1e-10 < np.abs(w).max() < 1e-6                       # sub-micrometre vibration, not zero
    assert np.all(mesh.point_data["mesh_force"] > 0)
    # part 1: the four bearing stations with their loads, at the same times
    stations = [e for e in every if e["part"] == "1"]
    assert [float(e["timestep"]) for e in stations] == list(times)
    bearings = meshio.read(main_job / stations[len(stations) // 2]["file"])
    F = bearings.point_data["bearing_force"]
    assert F.shape == (4, 3) and np.all(np.isfinite(F)) and np.all(np.hypot(F[:, 0], F[:, 1]) > 100)
    assert np.allclose(F[:2].sum(axis=0), -F[2:].sum(axis=0), rtol=0.05)     # pinion and gear carry ± the mesh force


def test_screenshot_of_the_pvd_set_has_content(main_job, tmp_path, monkeypatch):
    """Off-screen pyvista rendering (EGL; stack.md): the picture is not blank."""
    monkeypatch.setenv("VTK_DEFAULT_OPENGL_WINDOW", "vtkEGLRenderWindow")
    pv = pytest.importorskip("pyvista")
    pv.OFF_SCREEN = True
    flanks = pv.get_reader(str(main_job / "flanks.pvd")).read()
    plotter = pv.Plotter(off_screen=True, window_size=(400, 300))
    for block in flanks:
        plotter.add_mesh(block, scalars="hertz_pressure", show_scalar_bar=False)
    plotter.view_isometric()
    image = plotter.screenshot(str(tmp_path / "flanks.png"), return_img=True)
    plotter.close()
    background = image[0, 0]
    covered = np.any(np.abs(image.astype(int) - background.astype(int)) > 30, axis=-1).mean()
    assert 0.02 < covered < 0.95, f"{covered:.3f} of the picture differs from the background"
    assert len(np.unique(image.reshape(-1, image.shape[-1]), axis=0)) > 20   # shaded, coloured by a field
    assert os.path.getsize(tmp_path / "flanks.png") > 2000


@pytest.mark.slow
def test_body_pvd_with_fe_thermal(tmp_path):
    """thermal = "fe": body.pvd holds both gear sections with finite temperature, displacement, stress."""
    import meshio

    from femgear.edge.cli import main

    out = tmp_path / "fe"
    assert main(["-q", "run", str(BASE), "--out", str(out), "--no-plots", "--set", 'physics.preset="fast"',
                 "--set", 'physics.thermal="fe"', "--set", 'physics.dynamics="none"',
                 "--set", 'physics.coupling="one-way"', "--set", "thermal.flank_temperature_rise=20.0"]) == 0
    entries = _datasets(out / "body.pvd")
    assert [e["name"] for e in entries] == ["body_pinion", "body_gear"]
    for e in entries:
        mesh = meshio.read(out / e["file"])
        T = mesh.point_data["temperature_rise"]
        assert T.max() == pytest.approx(20.0, rel=1e-6)        # the flank's Dirichlet value
        assert np.all(np.isfinite(mesh.point_data["displacement"]))
        assert np.all(np.isfinite(mesh.cell_data["von_mises"][0]))
