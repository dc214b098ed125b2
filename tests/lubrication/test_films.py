"""The film of the level that ran (issue 25, item 5): labelled with its level, and each level's film is that
level's own model (the formula films for the cheap levels, the FE line EHL, the thermal line EHL)."""

from __future__ import annotations

import numpy as np
import pytest

from femgear.case import build_case
from femgear.levels.contact import contact_pass
from femgear.levels.lubrication import lubrication_solver
from femgear.scene import load_scene


def _case(path, *overrides):
    return build_case(load_scene(path, ["numerics.path_points=5", *overrides]))


def test_the_formula_film_is_the_contact_pass_film(baseline_path):
    case = _case(baseline_path)
    contact = contact_pass(case)
    film = lubrication_solver(case).film(contact.line_load)
    assert film.level == "formula" and "Moes" in film.method
    assert np.allclose(film.central, contact.film_central, rtol=1e-12)
    assert np.allclose(film.minimum, contact.film_minimum, rtol=1e-12)


def test_the_fe_line_film_is_close_to_moes_and_the_thermal_film_is_thinner(baseline_path):
    """FE line EHL 0–25 % below Moes's fit: the level runs Roelands viscosity and Dowson–Higginson density, whose
    weaker piezoviscosity and compression thin the film against Moes's Barus, incompressible fit (measured 13 %
    on the baseline; the Barus solver itself is held to Moes in tests/ehl); the thermal line EHL below the isothermal FE
    film (inlet shear heating thins the film: Murch & Wilson's reduction) but within a factor 2."""
    iso = _case(baseline_path, 'physics.lubrication="ehl-line"')
    contact = contact_pass(iso)
    w = contact.line_load
    fe = lubrication_solver(iso).film(w)
    assert fe.level == "ehl-line" and np.all(fe.minimum < fe.central)
    ratio = fe.central / contact.film_central
    assert np.all((ratio > 0.75) & (ratio < 1.0))
    hot = lubrication_solver(_case(baseline_path, 'physics.lubrication="tehl"')).film(w)
    assert hot.level == "tehl" and hot.temperature_rise is not None and np.all(hot.temperature_rise > 0)
    assert np.all(hot.central < fe.central) and np.all(hot.central > 0.5 * fe.central)


def test_a_run_reports_the_film_of_its_level_and_lambda(baseline_path, tmp_path):
    import json

    from femgear.edge.run import run_scene

    scene = load_scene(baseline_path, ['physics.dynamics="none"', 'physics.coupling="one-way"',
                                       'physics.lubrication="ehl-line"', "numerics.path_points=5"])
    written = run_scene(scene, tmp_path, plots=False)
    film = written.summary["film"]
    assert film["level"] == "ehl-line"
    path = json.loads((tmp_path / "results.json").read_text())["along_path"]
    assert path["film_central"] != path["film_central_formula"]
    assert min(path["film_minimum"]) == pytest.approx(film["minimum"], rel=1e-12)
    Ra = 0.4e-6      # rating.finishing default "ground"
    assert np.allclose(np.array(path["specific_film"]) * Ra, path["film_minimum"], rtol=1e-9)


def test_the_point_film_reuses_the_runs_last_solves(baseline_path, monkeypatch):
    """tehl-point: the film of the run's last pass comes from that pass's solves (no second set of point
    solves); at other inputs it is solved afresh."""
    import femgear.physics.tehl.point_level as pl

    case = _case(baseline_path, 'physics.lubrication="tehl-point"', "modifications.crowning=10e-6",
                 "numerics.path_points=3")
    k, T = case.path, case.operating.ambient_temperature
    w = contact_pass(case).line_load
    solver = lubrication_solver(case, repeated=True)
    mu, dT = solver(w=w, R=k.R, ue=k.ue, srr=np.abs(k.srr), T=np.full(w.shape, T))

    def no_solve(*args, **kw):
        raise AssertionError("solved again")

    monkeypatch.setattr(pl, "solve_tehl_point", no_solve)
    film = solver.film(w)
    assert film.level == "tehl-point" and np.allclose(film.thermal["flash_tehl"], dT, rtol=0, atol=0)
    with pytest.raises(AssertionError, match="solved again"):
        solver.film(1.1 * w)
