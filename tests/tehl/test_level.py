"""The ``tehl`` lubrication level: registry, coupling solver (a TEHL map), static path
of ``femgear run`` and the along-path study helpers."""

from pathlib import Path

import numpy as np
import pytest

from femgear.case import build_case
from femgear.levels.contact import contact_pass
from femgear.levels.lubrication import tehl_axes, tehl_setup
from femgear.physics.tehl.path import tehl_along_path
from femgear.physics.tehl.solver import tehl_line_solver, tehl_map
from femgear.scene import load_scene
from femgear.scene.levels import check_level

BASELINE = Path(__file__).resolve().parents[2] / "studies" / "paper_baseline.toml"


@pytest.fixture(scope="module")
def scene():
    return load_scene(BASELINE, ["physics.lubrication=tehl", "numerics.ehl_level=3"])


@pytest.fixture(scope="module")
def case(scene):
    return build_case(scene)


def test_level_is_available_and_selected(case):
    from femgear.levels.lubrication import lubrication_solver

    assert check_level("lubrication", "tehl") is None
    lub = lubrication_solver(case, repeated=True)
    assert lub.level == "tehl" and lub.friction and lub.heats
    assert hasattr(lub.solve, "cache") and "map" not in lub.solve.cache   # a lazily built TEHL map


def test_map_of_tehl_solves_and_its_measured_error(case):
    axes = tehl_axes(case)
    axes = {k: v[[0, -1]] for k, v in axes.items()}
    solver = tehl_line_solver(tehl_setup(case), level=3, estimate=False)     # what the map's points solve
    nested = tehl_line_solver(tehl_setup(case), level=3)
    fmap = tehl_map(tehl_setup(case), axes=axes, level=3, validate=2)
    assert fmap.mu.shape == (2, 2, 2, 2, 2) and np.all(np.isfinite(fmap.mu))
    assert fmap.error.samples == 2 and fmap.error.mu_max_abs < 0.02
    mu, dT = fmap(**{k: v[:1] for k, v in axes.items()})
    mu_ref, dT_ref = solver(**{k: v[:1] for k, v in axes.items()})
    assert mu == pytest.approx(mu_ref, abs=1e-12) and dT == pytest.approx(dT_ref, abs=1e-9)
    mu_n, dT_n = nested(**{k: v[:1] for k, v in axes.items()})     # the nested loop's fixed point, within its tolerance
    assert mu == pytest.approx(mu_n, rel=2e-3) and dT == pytest.approx(dT_n, abs=0.2)


def test_path_mu_u_shaped_minimum_at_pitch_and_vtk(scene, case, tmp_path):
    contact = contact_pass(case, n=5)
    path = tehl_along_path(contact, tehl_setup(case), case.operating.ambient_temperature, level=3)
    i_pitch = int(np.argmin(np.abs(path.s)))
    assert int(np.argmin(path.mu)) == i_pitch
    assert np.all(np.diff(path.mu[: i_pitch + 1]) < 0) and np.all(np.diff(path.mu[i_pitch:]) > 0)
    assert 5.0 < path.dT_max.max() < 100.0                            # tens of K
    import meshio

    from femgear.edge.io.fields import write_tehl_vtu

    g = meshio.read(write_tehl_vtu(tmp_path / "t.vtu", path.results[0]))
    assert np.max(g.cell_data["temperature"][0]) == pytest.approx(path.results[0].T_film.max())
    assert path.dT_max[0] + scene.operating.ambient_temperature >= path.results[0].T_film.max()  # the peak's vertex


def test_static_pass_reports_tehl_figures(scene):
    """The lubrication registry's ``tehl`` level (direct solves) equals the TEHL path solver."""
    from femgear.levels.lubrication import friction_along_path

    case = build_case(scene.model_copy(update={"numerics": scene.numerics.model_copy(update={"path_points": 3})}))
    contact = contact_pass(case, n=3)
    mu, dT = friction_along_path(case, np.full(case.path.u.size, contact.load_per_length))
    direct = tehl_along_path(contact, tehl_setup(case), case.operating.ambient_temperature,
                             tol=case.numerics.ehl_tol, min_level=case.numerics.ehl_level)
    assert mu == pytest.approx(direct.mu) and dT == pytest.approx(direct.dT_surface)
