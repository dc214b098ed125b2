"""A path sequence's spike-resolving grid that fails on a contact hands that contact to the plain grid (the
baseline's friction map at twice its load, w' 1.69e5 N/m, SRR 0.68, failed there and ended the ``tehl`` run)."""

from types import SimpleNamespace

import pytest

from femgear.errors import ConvergenceError
from femgear.physics.tehl import solver


def _fake(fail_plain: bool):
    calls = []

    def solve(w, R, ue, srr, T, spike=False, **kw):
        calls.append(spike)
        if spike or fail_plain:
            raise ConvergenceError("tehl line", "no convergence", {"residual": [1e-3, 2e-4]})
        return SimpleNamespace(nodes=513, error_estimate={"Hc": 0.001}, history={"continuation": []})

    return solve, calls


def test_failing_spike_grid_falls_back_to_the_plain_grid_and_says_so(monkeypatch):
    solve, calls = _fake(fail_plain=False)
    monkeypatch.setattr(solver, "solve_tehl_line", solve)
    r = solver._one(0, [1.687e5], [0.0126], [1.16], [0.6754], 313.0, {"spike": True, "level": 5})
    assert calls == [True, False]
    assert "plain grid" in r.history["continuation"][-1]["reason"]


def test_both_grids_failing_raises_with_both_histories(monkeypatch):
    solve, calls = _fake(fail_plain=True)
    monkeypatch.setattr(solver, "solve_tehl_line", solve)
    with pytest.raises(ConvergenceError) as exc:
        solver._one(1, [1e5, 1.687e5], [0.01, 0.0126], [1.0, 1.16], [0.5, 0.6754], 313.0, {"spike": True, "level": 5})
    assert "tehl path position 1" in str(exc.value) and "plain grid" in str(exc.value)
    assert set(exc.value.history) == {"spike residual", "plain residual"}


def test_plain_sequences_do_not_retry(monkeypatch):
    solve, calls = _fake(fail_plain=True)
    monkeypatch.setattr(solver, "solve_tehl_line", solve)
    with pytest.raises(ConvergenceError):
        solver._one(0, [1e5], [0.01], [1.0], [0.5], 313.0, {"spike": False})
    assert calls == [False]


def test_the_face_slices_fall_back_to_the_plain_grid_too(monkeypatch):
    """The ``tehl-point`` level's face slices are path sequences on the spike-resolving grids
    (:func:`femgear.levels.lubrication.tehl_path_options`): a slice whose spike grid fails is solved on the plain
    grid, said in its history, and the contact still has its figures."""
    import math

    from femgear.physics.tehl.slices import SliceGeometry, slice_contact

    calls = []

    def solve(w, R, ue, srr, T, spike=False, **kw):
        calls.append(spike)
        if spike:
            raise ConvergenceError("tehl line", "no convergence", {"residual": [1e-3, 2e-4]})
        return SimpleNamespace(nodes=513, layers=16, error_estimate={"hc": 0.001, "hmin": 0.002}, history={}, hc=1e-6,
                               hmin=5e-7, pmax=1e9, hc_isothermal=1.1e-6, dT_max=20.0, dT_surface=10.0,
                               mu_couette=-0.03 * math.copysign(1.0, srr))

    monkeypatch.setattr(solver, "solve_tehl_line", solve)
    om1 = 2 * math.pi * 3000 / 60
    geo = SliceGeometry(om1, om1 * 21 / 86, math.radians(14.1), 0.04, 0.0)
    setup = SimpleNamespace(kwargs=lambda: {}, E_red=2.3e11, oil=None)
    r = slice_contact(4e5, 0.012, 9.0, 0.3, 313.0, 0.012, math.inf, geo, setup, start_level=5, spike=True, tol=0.01)
    # the first contact's failure sends the sequence to the gentle bump once (_gentler), where every spike grid
    # fails too: each contact on the plain grid
    assert calls == [True, False] * (len(r.results) + 1)
    assert all("plain grid" in s.history["continuation"][-1]["reason"] for s in r.results)
    assert r.mu == pytest.approx(0.03) and r.dT_surface == 10.0


def test_a_stalled_steep_bump_resolves_the_whole_sequence_on_the_gentle_one(monkeypatch):
    """The marine zoo pair's case: the steep bump's thermal loop stalls at the slow-sliding contacts; the sequence is
    solved again on :data:`SPIKE_DENSITY_GENTLE`, every contact on it (one grid along the path, no plain fallback)."""
    from femgear.physics.ehl.fd.line_grid import SPIKE_DENSITY, SPIKE_DENSITY_GENTLE

    calls = []

    def solve(w, R, ue, srr, T, spike=False, spike_density=SPIKE_DENSITY, **kw):
        calls.append((srr, spike, spike_density))
        if spike and spike_density > SPIKE_DENSITY_GENTLE and srr < 0.05:
            raise ConvergenceError("tehl line", "thermal loop: no convergence", {"temperature_change": [2.0, 2.1]})
        return SimpleNamespace(nodes=1025, layers=16, error_estimate={"hc": 0.001}, isothermal_estimate=0.001,
                               history={"continuation": []})

    monkeypatch.setattr(solver, "solve_tehl_line", solve)
    setup = SimpleNamespace(kwargs=lambda: {})
    rs = solver.tehl_path_results([1e5] * 3, [0.02] * 3, [5.0] * 3, [0.3, 0.0, 0.2], 333.0, setup, level=6,
                                  spike=True)
    assert len(rs) == 3 and all(not r.history["continuation"] for r in rs)
    assert calls[-3:] == [(s, True, SPIKE_DENSITY_GENTLE) for s in sorted((0.3, 0.0, 0.2))]
    assert any(d == SPIKE_DENSITY for _, _, d in calls)
