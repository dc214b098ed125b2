"""A path sequence whose contact misses the tolerance is solved once more, finer where the error is: more layers
across the film where the isothermal start met the tolerance on the level, else a finer level along it
(:func:`femgear.physics.tehl.solver._finer`)."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np

from femgear.physics.ehl.fd.line import MAX_LEVEL
from femgear.physics.tehl import solver
from femgear.physics.tehl.solver import MAX_LAYERS, _finer


def _r(iso: float | None):
    return SimpleNamespace(isothermal_estimate=iso)


def test_the_layers_double_where_the_isothermal_film_is_resolved_on_the_level():
    assert _finer(_r(0.004), 6, {"tol": 0.01, "spike": True}, 0.01) == {"tol": 0.01, "spike": True, "level": 6,
                                                                         "nz": 32}
    assert _finer(_r(0.004), 6, {"nz": 32}, 0.01) == {"nz": 64, "level": 6}


def test_a_level_finer_where_the_isothermal_film_misses_the_tolerance_or_the_layers_are_at_their_limit():
    assert _finer(_r(0.02), 6, {}, 0.01) == {"level": 7}
    assert _finer(_r(None), 6, {}, 0.01) == {"level": 7}
    assert _finer(_r(0.004), 6, {"nz": MAX_LAYERS}, 0.01) == {"nz": MAX_LAYERS, "level": 7}
    assert _finer(_r(0.02), MAX_LEVEL, {}, 0.01) is None


def test_the_sequence_is_solved_once_more_with_twice_the_layers(monkeypatch):
    """A fake solver whose estimate is 1.3 % with 16 layers and 0.4 % with 32 (the turbo zoo pair's path, whose
    finer level along x had left it at 1.26 %): the probe's level is kept and every contact ends with 32 layers."""
    calls = []

    def solve(w, R, ue, srr, T, *, level=None, nz=16, **kw):
        calls.append((level, nz))
        return SimpleNamespace(nodes=16 * 2 ** (level or 6) + 1, layers=nz, isothermal_estimate=0.002,
                               error_estimate={"hc": 0.013 if nz == 16 else 0.004, "hmin": 0.001}, history={})

    monkeypatch.setattr(solver, "solve_tehl_line", solve)
    setup = SimpleNamespace(kwargs=lambda: {}, oil=None, E_red=2.3e11)
    monkeypatch.setattr(solver, "ehl_oil_at", lambda oil, T: SimpleNamespace(eta0=0.01, alpha=2e-8))
    rs = solver.tehl_path_results(np.full(3, 1e5), np.full(3, 0.02), np.full(3, 50.0), np.array([0.1, 0.2, 0.3]),
                                  320.0, setup, tol=0.01)
    assert [r.layers for r in rs] == [32, 32, 32]
    assert calls[0] == (None, 16) and all(c == (6, 32) for c in calls[-3:])


_SETUP = SimpleNamespace(kwargs=lambda: {})


def _map_fakes(monkeypatch, film_level: int, differ: float, fail_coarse: bool = False):
    """solve_tehl_line and tehl_line_solver stand-ins: the films' corner solve ends on ``film_level``; μ on the
    coarser level is ``1 + differ`` times the film level's; the probes solved are recorded."""
    calls = []
    monkeypatch.setattr(solver, "solve_tehl_line", lambda *a, **k: SimpleNamespace(nodes=16 * 2 ** film_level + 1))

    def line_solver(setup, level, estimate, **kw):
        def solve(w, R, ue, srr, T):
            calls.append(level)
            if fail_coarse and level < film_level:
                raise solver.ConvergenceError("tehl line", "no convergence", {})
            mu = 0.03 * (1 + differ if level < film_level else 1.0)
            return np.atleast_1d(mu), np.atleast_1d(10.0)
        return solve

    monkeypatch.setattr(solver, "tehl_line_solver", line_solver)
    axes = {"w": np.array([1e5, 2e5, 4e5]), "R": np.array([0.01, 0.02]), "ue": np.array([10.0, 20.0]),
            "srr": np.array([0.0, 0.01, 0.04, 0.12, 0.3, 0.6, 1.0]), "T": np.array([313.0, 353.0])}
    return axes, calls


def test_a_map_is_built_one_level_coarser_where_its_fields_agree_at_every_probe(monkeypatch):
    axes, calls = _map_fakes(monkeypatch, 6, differ=0.02)
    assert solver.map_level(_SETUP, axes, tol=0.01) == 5 and calls.count(5) == calls.count(6) == 8


def test_a_map_keeps_its_films_level_at_the_first_probe_that_differs_or_fails(monkeypatch):
    axes, calls = _map_fakes(monkeypatch, 6, differ=0.03)
    assert solver.map_level(_SETUP, axes, tol=0.01) == 6 and calls == [5, 6]
    axes, calls = _map_fakes(monkeypatch, 6, differ=0.0, fail_coarse=True)
    assert solver.map_level(_SETUP, axes, tol=0.01) == 6 and calls == [5]
    axes, calls = _map_fakes(monkeypatch, solver.MIN_MAP_LEVEL, differ=0.0)
    assert solver.map_level(_SETUP, axes) == solver.MIN_MAP_LEVEL and calls == []


def test_the_baselines_map_keeps_513_nodes_for_its_light_load_slow_sliding_friction():
    """Validation of the probe on a real map: at the baseline's lightest load and a slow slide, μ converges at first
    order (0.00391, 0.00428, 0.00449, 0.00459 on 257 ... 2049 nodes, the Newtonian friction of the spike's
    viscosity), 7.6 % of 0.005 apart between 257 and 513 nodes: the map stays on its films' 513."""
    from femgear.case import build_case
    from femgear.levels.lubrication import tehl_axes, tehl_map_options, tehl_setup
    from femgear.scene import load_scene
    from tests.conftest import BASELINE

    case = build_case(load_scene(BASELINE, ['physics.lubrication="tehl"']))
    assert solver.map_level(tehl_setup(case), tehl_axes(case), **tehl_map_options(case)) == 5
