"""Cost shortcuts of the ``tehl-point`` level (issue 26), each against the answer without it:
a contact's solve reused across coupling passes within its estimated tolerance, the dense Newton
steps of the isothermal start on reused LU factors, the thermal re-solves' kept preconditioner."""

from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

from femgear.physics.tehl.reuse import ASSUMED_SENSITIVITY, REUSE_TOL, ReuseReport, reusable, sensitivity

BASELINE = Path(__file__).resolve().parents[2] / "studies" / "paper_baseline.toml"


def _r(mu, dT):
    return SimpleNamespace(mu=mu, dT_max=dT)


def test_reuse_rule_uses_the_measured_sensitivity_and_never_exceeds_its_tolerance():
    rep = ReuseReport()
    one = [(1000.0, _r(0.04, 20.0))]
    assert sensitivity(one) == ASSUMED_SENSITIVITY
    assert reusable(one, 1000.0 * (1 + 0.4 * REUSE_TOL), rep) is one[0][1]           # 2 × 0.4e-4 ≤ 1e-4
    assert reusable(one, 1000.0 * (1 + 0.6 * REUSE_TOL), rep) is None                # 2 × 0.6e-4 > 1e-4
    two = [(990.0, _r(0.0399, 19.9)), (1000.0, _r(0.04, 20.0))]                       # s = max(0.25, 0.5) / 0.0101
    s = sensitivity(two)
    assert s == pytest.approx(max(0.0001 / 0.0399, 0.1 / 19.9) / (10 / 990))
    assert reusable(two, 1000.0 * (1 + 0.9 * REUSE_TOL / s), rep) is two[1][1]
    assert reusable(two, 1000.0 * (1 + 1.1 * REUSE_TOL / s), rep) is None
    assert (rep.reused, rep.solved) == (2, 2) and rep.max_estimate <= REUSE_TOL


def test_reused_point_solve_is_within_its_tolerance_of_a_direct_solve():
    """The baseline's crowned contact at the static load: a load change of 2e-5 (the coupling's later passes
    move by ~1e-5) reuses the solve; a direct solve at the new load differs by less than the tolerance."""
    from femgear.case import build_case
    from femgear.levels.contact import contact_pass
    from femgear.levels.lubrication import tehl_point_solver
    from femgear.scene import load_scene

    scene = load_scene(BASELINE, ['physics.lubrication="tehl-point"', "modifications.crowning=10e-6"])
    case = build_case(scene)
    cp = contact_pass(case)
    i = 3
    w = float(np.broadcast_to(cp.load_per_length, cp.kin.R.shape)[i])
    args = dict(R=cp.kin.R[i], ue=cp.kin.ue[i], srr=abs(cp.kin.srr[i]), T=scene.operating.ambient_temperature)
    solve = tehl_point_solver(case)
    solve(w=w, **args)
    assert solve.latest.reuse.solved == 1
    mu, dT = solve(w=w * (1 + 2e-5), **args)
    assert solve.latest.reuse.reused == 1 and solve.latest.reuse.max_estimate <= REUSE_TOL
    mu_d, dT_d = tehl_point_solver(case)(w=w * (1 + 2e-5), **args)
    assert abs(mu[0] / mu_d[0] - 1) <= REUSE_TOL and abs(dT[0] / dT_d[0] - 1) <= REUSE_TOL
    mu2, _ = solve(w=w * 1.01, **args)                   # a real load change: solved again
    assert solve.latest.reuse.solved == 1 and mu2[0] != mu[0]


def test_reuse_across_a_bulk_temperature_change_is_bounded_by_the_viscosity_coefficient():
    """The coupling's bulk temperature moves from pass to pass: a solve reused at a temperature 1 mK away (and the
    same load) is estimated by β ΔT and within the tolerance of a direct solve there; with two solves at different
    temperatures the load sensitivity is the assumed one; 1 K away the contact is solved again, and β bounds the
    measured change (so the estimate is conservative)."""
    from femgear.case import build_case
    from femgear.levels.contact import contact_pass
    from femgear.levels.lubrication import tehl_point_solver
    from femgear.scene import load_scene

    rep = ReuseReport()
    hist = [(990.0, _r(0.0399, 19.9), 313.0), (1000.0, _r(0.04, 20.0), 313.5)]
    assert sensitivity(hist) == ASSUMED_SENSITIVITY
    assert reusable(hist, 1000.0, rep, 313.5 + 0.9 * REUSE_TOL / 0.04, 0.04) is hist[1][1]
    assert reusable(hist, 1000.0, rep, 313.5 + 1.1 * REUSE_TOL / 0.04, 0.04) is None

    scene = load_scene(BASELINE, ['physics.lubrication="tehl-point"', "modifications.crowning=10e-6"])
    case = build_case(scene)
    cp = contact_pass(case)
    i, T = 3, scene.operating.ambient_temperature
    w = float(np.broadcast_to(cp.load_per_length, cp.kin.R.shape)[i])
    args = dict(w=w, R=cp.kin.R[i], ue=cp.kin.ue[i], srr=abs(cp.kin.srr[i]))
    solve = tehl_point_solver(case)
    mu0, dT0 = solve(**args, T=T)
    mu, dT = solve(**args, T=T + 1e-3)
    assert solve.latest.reuse.reused == 1 and solve.latest.reuse.max_estimate <= REUSE_TOL
    mu_d, dT_d = tehl_point_solver(case)(**args, T=T + 1e-3)
    assert abs(mu[0] / mu_d[0] - 1) <= REUSE_TOL and abs(dT[0] / dT_d[0] - 1) <= REUSE_TOL
    mu1, dT1 = solve(**args, T=T + 1.0)
    assert solve.latest.reuse.solved == 1
    beta = case.oil.temperature_viscosity
    assert max(abs(mu1[0] / mu0[0] - 1), abs(dT1[0] / dT0[0] - 1)) <= beta * 1.0


def test_dense_reuse_converges_to_the_same_point_solution():
    """Newton on reused LU factors (GMRES steps) stops on the same residual test: the same film."""
    from femgear.physics.ehl.point import solve_point

    a = solve_point(200.0, 10.0, level=1, ratio=0.05, method="newton")
    b = solve_point(200.0, 10.0, level=1, ratio=0.05, method="newton", dense_reuse=True)
    assert max(b.history["krylov"]) > 0 and max(a.history["krylov"]) == 0       # the reuse did take steps
    assert b.Hc_hertz == pytest.approx(a.Hc_hertz, rel=1e-6) and b.Pmax == pytest.approx(a.Pmax, rel=1e-6)
    assert np.max(np.abs(b.P - a.P)) < 1e-6 * np.max(a.P)
