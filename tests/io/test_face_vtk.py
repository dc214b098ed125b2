"""``flank_face.vtu``: the face-resolved wear and thermal fields on the 3-D flanks of both members."""

from __future__ import annotations

import json
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

from femgear.edge.io.paraview_run import face_mesh
from femgear.physics.wear.face import face_mean
from femgear.results import Tribology

ROOT = Path(__file__).resolve().parents[2]
BASE = ROOT / "studies" / "paper_baseline.toml"


def _check(mesh, n_u: int, grid: np.ndarray, fields: dict, path_mean: dict | None = None):
    """Both members, both helices, n_u × len(grid) points each; the fields as given; their face mean."""
    per_helix = n_u * grid.size
    assert len(mesh.points) == 4 * per_helix and np.all(np.isfinite(mesh.points))
    assert len(mesh.cells_dict["quad"]) == 4 * (n_u - 1) * (grid.size - 1)
    member, helix = mesh.point_data["member"], mesh.point_data["helix"]
    for j in (0, 1):
        for s in (0, 1):
            on = (member == j + 1) & (helix == s)
            assert on.sum() == per_helix
            zeta = mesh.point_data["zeta"][on].reshape(n_u, grid.size)
            assert np.allclose(zeta, grid[None, :])
            for name, field in fields.items():
                values = mesh.point_data[name][on].reshape(n_u, grid.size)
                np.testing.assert_array_equal(values, field[j, s])
    for name, mean in (path_mean or {}).items():
        v = mesh.point_data[name].reshape(2, 2, n_u, grid.size)
        got = np.array([face_mean(v[j], grid).mean(axis=0) for j in (0, 1)])
        np.testing.assert_allclose(got, mean, rtol=1e-9, atol=1e-15)


def test_face_mesh_carries_the_fields_on_both_helices_of_both_members(tmp_path, baseline_scene):
    """Synthetic fields (distinct per member and helix): written atomically, read back with meshio, each on its
    (member, helix) with the (u, ζ) shape; without face fields no mesh."""
    import meshio

    from femgear.case import build_case
    from femgear.edge.io.paraview import write_vtu

    case = build_case(baseline_scene)
    n, grid = case.path.u.size, np.linspace(0.0, case.pair.b, 7)
    base = np.arange(n)[:, None] * 1e-9 + grid[None, :] * 1e-4
    wear = np.array([[base + 1e-6 * (2 * j + s) for s in (0, 1)] for j in (0, 1)])
    thermal = -0.5 * wear[:, ::-1]
    t = Tribology(load_per_length=np.zeros(n), friction_coefficient=None, temperature_rise=None,
                  flank_temperature_rise=30.0, thermal_deviation=None, wear=None, face_grid=grid, wear_face=wear,
                  thermal_face=thermal)
    path = write_vtu(tmp_path / "flank_face.vtu", face_mesh(SimpleNamespace(tribology=t, case=case)))
    assert [p.name for p in tmp_path.iterdir()] == ["flank_face.vtu"]           # no temporary left
    mesh = meshio.read(path)
    _check(mesh, n, grid, {"wear_depth": wear, "thermal_deviation": thermal})
    pts = mesh.points.reshape(2, 2, n, grid.size, 3)
    b, g = case.pair.b, case.groove_width
    for j in (0, 1):                                  # left helix at z = ζ, right mirrored to z = 2b + g − ζ
        np.testing.assert_allclose(pts[j, 0, ..., 2], np.broadcast_to(grid, (n, grid.size)), atol=1e-12)
        np.testing.assert_allclose(pts[j, 1, ..., 2], np.broadcast_to(2 * b + g - grid, (n, grid.size)), atol=1e-12)
    r_pinion = np.hypot(*pts[0, 0, ..., :2].T)
    assert r_pinion.min() > 0.9 * case.pair.rb1 and r_pinion.max() < case.pair.ra1 * 1.001
    none = Tribology(load_per_length=np.zeros(n), friction_coefficient=None, temperature_rise=None,
                     flank_temperature_rise=0.0, thermal_deviation=None, wear=None)
    assert face_mesh(SimpleNamespace(tribology=none, case=case)) is None


@pytest.mark.slow
def test_main_job_writes_flank_face_vtu_with_fe3d_and_face_wear(tmp_path):
    """The CLI run (ltca, fe3d, face wear, one-way, coarse; ≈ 1–2 min): ``flank_face.vtu`` is written and listed,
    carries both fields on both helices of both members, its wear's face mean is results.json's path wear and
    its ζ_T's face mean results.json's ζ_T (to the interpolation of the units' 9-point ζ grid: < 1e-3)."""
    import meshio

    from femgear.edge.cli import main

    out = tmp_path / "run"
    over = ["numerics.path_points=31", "numerics.dynamics_cycles=20", "numerics.transient_cycles=10",
            'physics.stiffness="ltca"', 'physics.thermal="fe3d"', 'wear.field="face"', "wear.cycles=1e6",
            'physics.coupling="one-way"', "thermal.flank_temperature_rise=30.0", "modifications.crowning=5e-6"]
    args = ["-q", "run", str(BASE), "--out", str(out), "--no-plots", "--json"]
    for o in over:
        args += ["--set", o]
    assert main(args) == 0
    mesh = meshio.read(out / "flank_face.vtu")
    data = json.loads((out / "results.json").read_text())
    along = data["along_path"]
    n = len(along["s"])
    grid = np.unique(mesh.point_data["zeta"])
    assert grid.size == 21
    wear = np.array([along["wear_pinion"], along["wear_gear"]])
    assert wear.max() > 0
    _check(mesh, n, grid, {}, {"wear_depth": wear})
    v = mesh.point_data["thermal_deviation"].reshape(2, 2, n, grid.size)
    zeta = np.array([along["thermal_deviation_pinion"], along["thermal_deviation_gear"]])
    got = np.array([face_mean(v[j], grid).mean(axis=0) for j in (0, 1)])
    np.testing.assert_allclose(got, zeta, rtol=1e-3)
    assert np.ptp(v[0, 0], axis=1).min() > 0.05 * v[0, 0].mean()               # varies over the face
