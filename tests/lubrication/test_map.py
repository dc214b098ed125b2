"""Friction maps: exact at the nodes, error measured, envelope enforced."""

import numpy as np
import pytest

from femgear.case import build_case
from femgear.levels.lubrication import envelope_contact, line_friction
from femgear.physics.lubrication.map import FrictionMap, envelope_axes, hertz_level_solver

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
