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
