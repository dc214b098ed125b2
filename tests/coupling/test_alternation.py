"""The coupling loop that settles into a two-pass cycle stops there, flagged, instead of running to max_iter."""

from types import SimpleNamespace

import numpy as np
import pytest

from femgear.errors import ConvergenceError
from femgear.system.coupling import loop


def _states(mu_of_pass, force_of_pass):
    """Synthetic passes: iteration 0 (the start) then one state per pass with its changes against the last."""
    prev = None
    for k, (mu, f) in enumerate(zip(mu_of_pass, force_of_pass)):
        mu, f = np.full(5, mu), np.full((2, 8), f)
        df = np.nan if prev is None else float(np.max(np.abs(f - prev[1])) / np.max(np.abs(f)))
        dmu = np.nan if prev is None else float(np.max(np.abs(mu - prev[0])))
        yield SimpleNamespace(iteration=k, mesh_force=f, mu=mu, mesh_force_change=df, mu_change=dmu, seconds=0.0)
        prev = (mu, f)


def _run(monkeypatch, mus, forces, **kw):
    monkeypatch.setattr(loop, "coupling_iterations", lambda setup, relax: _states(mus, forces))
    return loop.run_coupled(SimpleNamespace(case=SimpleNamespace(name="synthetic")), **kw)


def test_a_two_pass_cycle_stops_flagged_with_its_amplitude(monkeypatch, caplog):
    mus = [0.03, 0.0312, 0.0309, 0.0312, 0.0309, 0.0312, 0.0309, 0.0312]
    forces = [100.0, 101.0, 100.001, 100.002, 100.001, 100.002, 100.001, 100.002]
    res = _run(monkeypatch, mus, forces, max_iter=7)
    assert res.alternation is not None and res.state.iteration == 5     # passes 2-5: 4 = 2, 5 = 3
    assert res.alternation[1] == pytest.approx(3e-4)
    assert res.alternation[0] == pytest.approx(1e-3 / 100.002, rel=1e-6)
    assert "alternate between two states" in caplog.text


def test_a_converging_loop_is_not_taken_for_a_cycle(monkeypatch):
    mus = [0.03 + 1e-3 * 0.5**k for k in range(30)]
    res = _run(monkeypatch, mus, [100.0] * 30, max_iter=29)
    assert res.alternation is None and res.converged


def test_a_loop_that_neither_converges_nor_alternates_still_raises(monkeypatch):
    mus = [0.03 + 1e-3 * k for k in range(12)]
    with pytest.raises(ConvergenceError):
        _run(monkeypatch, mus, [100.0 + k for k in range(12)], max_iter=10)
