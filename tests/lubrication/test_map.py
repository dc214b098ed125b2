"""Friction maps: exact at the nodes, error measured, envelope enforced."""

from dataclasses import replace

import numpy as np
import pytest

from femgear.case import build_case
from femgear.levels.lubrication import envelope_contact, line_friction
from femgear.physics.lubrication.map import MU_TOLERANCE, FrictionMap, envelope_axes, hertz_level_solver

AXES = dict(w=np.geomspace(1e4, 1e5, 3), R=np.geomspace(0.01, 0.02, 2), ue=np.geomspace(0.5, 2.0, 3),
            srr=np.linspace(0, 0.6, 4), T=np.linspace(313, 353, 2))


def multilinear(w, R, ue, srr, T):
    """Linear in the map's coordinates (log w, log R, log ue, srr, T): interpolated exactly."""
    mu = 0.01 + 0.001 * np.log(w) - 0.002 * np.log(R) + 0.003 * np.log(ue) + 0.05 * np.abs(srr) - 1e-4 * (T - 300)
    return mu, 10 * np.abs(srr) + 0.1 * (T - 300)


def test_interpolation_is_exact_for_functions_linear_in_the_map_coordinates():
    fmap = FrictionMap.build(multilinear, AXES).validate(multilinear, samples=100)
    assert fmap.error.mu_max_abs < 1e-12 and fmap.error.dT_max_abs < 1e-9


def test_the_map_reproduces_its_nodes_and_is_even_in_the_srr():
    fmap = FrictionMap.build(multilinear, AXES)
    mu, _ = fmap(1e4, 0.01, 0.5, -0.2, 313)
    assert mu == pytest.approx(multilinear(1e4, 0.01, 0.5, 0.2, 313)[0], rel=1e-12)


def test_queries_outside_the_envelope_are_refused():
    fmap = FrictionMap.build(multilinear, AXES)
    with pytest.raises(ValueError, match="ue outside"):
        fmap(5e4, 0.015, 3.0, 0.1, 320)


def test_bad_axes_are_refused():
    with pytest.raises(ValueError, match="axes missing"):
        FrictionMap.build(multilinear, {k: v for k, v in AXES.items() if k != "T"})
    with pytest.raises(ValueError, match="axis srr"):
        FrictionMap.build(multilinear, AXES | {"srr": np.array([0.5, 0.1])})


def test_baseline_formula_map_error_is_small(baseline_scene):
    case = build_case(baseline_scene)
    solver = hertz_level_solver(line_friction(case))
    axes = envelope_axes(envelope_contact(case), case.operating.ambient_temperature, 1)
    fmap = FrictionMap.build(solver, axes).validate(solver, samples=150)
    assert fmap.error.mu_max_abs < 3e-3        # μ itself is 0.01–0.05 here
    assert fmap.error.dT_max_abs < 1.0


def curved(w, R, ue, srr, T):
    """μ with a knee in the SRR, which two SRR nodes cannot follow: the map's error is above its tolerance."""
    return 0.05 * np.tanh(np.abs(srr) / 0.02) + 1e-3 * np.log(w), 30 * np.tanh(np.abs(srr) / 0.02)


def test_the_maps_error_is_measured_beside_its_tolerance_and_flagged_above_it(caplog):
    """``validate`` states the error against :data:`MU_TOLERANCE` and the ΔT tolerance (5 % of the map's largest ΔT,
    at least 1 K), and logs a warning when it exceeds them: a coarse map of a knee is flagged, a fine one of a
    multilinear law is not (never silent)."""
    coarse = FrictionMap.build(curved, AXES | {"srr": np.array([0.0, 0.6])})
    with caplog.at_level("WARNING", logger="femgear.physics.lubrication"):
        bad = coarse.validate(curved, samples=50).error
    assert not bad.within_tolerance and bad.mu_max_rel > MU_TOLERANCE and "ABOVE" in bad.message()
    assert any("friction map error" in r.message for r in caplog.records)
    assert bad.dT_tolerance == pytest.approx(0.05 * float(np.max(coarse.temperature_rise)))
    caplog.clear()
    with caplog.at_level("WARNING", logger="femgear.physics.lubrication"):
        good = FrictionMap.build(multilinear, AXES).validate(multilinear, samples=50).error
    assert good.within_tolerance and not caplog.records


def test_the_maps_error_goes_into_the_friction_summary():
    """``summary.friction`` carries a map's error, its tolerances and the verdict where a map stood in for the
    level (the ``tehl`` level with dynamics), and nothing of it for direct solves."""
    from femgear.edge.io.run import tribology_summary
    from femgear.edge.io.summary_schema import kind_of
    from femgear.results import Tribology

    err = FrictionMap.build(curved, AXES | {"srr": np.array([0.0, 0.6])}).validate(curved, samples=20).error
    s = np.linspace(-1e-3, 1e-3, 5)
    t = Tribology(load_per_length=np.full(5, 1e5), friction_coefficient=np.full(5, 0.03),
                  temperature_rise=np.full(5, 5.0), flank_temperature_rise=0.0, thermal_deviation=None, wear=None)
    assert not any(k.startswith("map") for k in tribology_summary(t, s, True, "tehl")["friction"])
    f = tribology_summary(replace(t, friction_map_error=err), s, False, "tehl")["friction"]
    assert f["map_within_tolerance"] is False and f["map_mu_error"] == err.mu_max_rel and "ABOVE" in f["map_error"]
    assert all(kind_of(f"friction.{k}") is not None for k in f)
