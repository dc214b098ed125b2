"""Results that carry their own error: Richardson estimates, tol-driven levels, flags and
the inlet-adequacy refusal (issue 16)."""

import json
import math

import pytest

from femgear.edge.cli import main
from femgear.errors import SceneError
from femgear.physics.contact.film import nvm_central
from femgear.physics.ehl.core import accuracy as acc
from femgear.physics.ehl.core.grid import Domain
from femgear.physics.ehl.fe.line import solve_line
from femgear.physics.ehl.point import solve_point


def test_richardson_recovers_a_second_order_sequence():
    f = [1.0 + 0.3 * h**2 for h in (1.0, 0.5, 0.25, 0.125)]
    exact_err = (f[-1] - 1.0) / f[-1]
    assert acc.richardson(f) == pytest.approx(exact_err, rel=1e-12)
    assert acc.richardson(f[:2]) == pytest.approx((f[1] - 1.0) / f[1], rel=1e-12)
    assert acc.richardson(f[:1]) is None


def test_richardson_is_conservative_outside_the_asymptotic_range():
    # changes that grow, or change sign: the last change itself is the estimate
    assert acc.richardson([1.0, 1.01, 1.05]) == pytest.approx(0.04 / 1.05)
    assert acc.richardson([1.0, 1.04, 1.02]) == pytest.approx(0.02 / 1.02)
    # a faster-than-second-order sequence is not trusted beyond second order
    assert acc.richardson([1.0, 1.1, 1.101]) == pytest.approx(0.001 / 3 / 1.101)


def test_inlet_distance_hamrock_dowson():
    assert acc.inlet_distance(0.0) == 1.0
    assert acc.inlet_distance(1.0) == pytest.approx(4.06)
    assert acc.inlet_problem(-4.5, 0.5) is None
    assert "m* = 6" in acc.inlet_problem(-4.5, 2.33)


@pytest.mark.parametrize("M", [1.0, 3.0])
def test_low_M_point_is_refused_with_the_reason(M):
    """(1, 10), (3, 10): the default inlet X = -4.5 truncates the inlet build-up (the
    solver gave Hc 3.81 against NVM's 41.6 at M = 1, -44 % at M = 3): refused."""
    with pytest.raises(SceneError) as exc:
        solve_point(M, 10.0, level=1)
    msg = str(exc.value)
    assert exc.value.key == "M" and "fully flooded inlet" in msg and "domain=" in msg


def test_explicit_truncating_domain_is_flagged():
    r = solve_point(20.0, 10.0, level=2, domain=Domain(-1.6, 1.3, -1.3, 1.3))
    assert r.flags and any(f.startswith("domain:") for f in r.flags)
    assert r.summary()["warning"] is not None


def test_point_result_carries_its_estimate():
    r = solve_point(20.0, 10.0, level=2)
    est = r.error_estimate
    assert set(est) == {"Hc", "Hmin"} and all(e is not None and e >= 0 for e in est.values())
    # the estimate from the 33^2 / 65^2 pair, order 2
    hc = [lv["Hc"] for lv in r.levels]
    assert est["Hc"] == pytest.approx(abs(hc[1] - hc[0]) / 3 / hc[1])
    assert r.tol == acc.DEFAULT_TOL
    assert (est["Hc"] > r.tol) == any(f.startswith("Hc:") for f in r.flags)
    s = r.summary()
    assert s["error_estimate"] == est and isinstance(s["flags"], list)


def test_tol_picks_the_cheapest_level_meeting_it():
    """tol = 1.5 % stops at 65^2 at (20, 10); tol = 0.5 % needs 129^2, whose estimate
    meets it, and the coarser answer is within its own estimate (x 2) of the finer."""
    loose = solve_point(20.0, 10.0, tol=0.015, method="newton")
    tight = solve_point(20.0, 10.0, tol=0.005, max_level=3, method="newton")
    assert loose.nodes == 65 * 65 and tight.nodes == 129 * 129
    for r in (loose, tight):
        assert all(e <= r.tol for e in r.error_estimate.values()) and not r.flags
    assert abs(loose.Hc / tight.Hc - 1) <= 2 * loose.error_estimate["Hc"] + tight.error_estimate["Hc"]


def test_unmet_tolerance_is_flagged_not_silent():
    r = solve_point(20.0, 10.0, tol=1e-4, max_level=2)
    assert r.nodes == 65 * 65
    assert r.flags and r.warning and "exceeds tol" in r.warning


def test_line_default_is_flagged_where_the_grid_is_not_converged():
    """Line (1000, 10) on the default level 6: Hmin moves 19 % to the next grids; the
    result must carry the flag (or be within 2 % of the grid-converged value)."""
    r = solve_line(1000.0, 10.0)
    converged_hmin = 2.43  # levels 8 / 9: 2.416 / 2.430
    converged_hc = 3.27  # levels 8 / 9: 3.283 / 3.271
    ok = (abs(r.Hmin / converged_hmin - 1) <= 0.02 and abs(r.Hc / converged_hc - 1) <= 0.02)
    assert ok or r.flags
    # each quantity that misses by more than 2 % carries its own flag (Hc is 7 % off)
    for k, conv in (("Hc", converged_hc), ("Hmin", converged_hmin)):
        if abs(getattr(r, k) / conv - 1) > 0.02:
            assert any(f.startswith(f"{k}:") for f in r.flags), (k, r.flags)


def test_unresolved_level_pair_shares_the_larger_estimate():
    lv = [{"nodes": 513, "Hc": 3.0687, "Hmin": 0.6087}, {"nodes": 1025, "Hc": 3.0408, "Hmin": 1.8563}]
    est = acc.error_estimate(lv)
    assert est["Hc"] == est["Hmin"] == pytest.approx((1.8563 - 0.6087) / 3 / 1.8563)
    resolved = [{"nodes": 4, "Hc": 1.0, "Hmin": 0.5}, {"nodes": 9, "Hc": 1.01, "Hmin": 0.52}]
    est = acc.error_estimate(resolved)
    assert est["Hc"] == pytest.approx(0.01 / 3 / 1.01) and est["Hmin"] == pytest.approx(0.02 / 3 / 0.52)


def test_line_low_M_default_inlet_refused():
    with pytest.raises(SceneError):
        solve_line(0.2, 10.0, level=4)
    r = solve_line(20.0, 10.0, level=4, x0=-1.5)  # explicit short inlet: solved, flagged
    assert math.isfinite(r.Hc) and any(f.startswith("domain:") for f in r.flags)


def test_cli_tol_reports_estimate(capsys):
    rc = main(["ehl", "point", "--M", "20", "--L", "10", "--tol", "0.015", "--json"])
    d = json.loads(capsys.readouterr().out.strip().splitlines()[-1])
    # the multigrid default (FD scheme) needs 129^2 where the Newton FE scheme needs 65^2
    assert rc == 0 and d["nodes"] in (65 * 65, 129 * 129) and d["tol"] == 0.015
    assert d["error_estimate"]["Hc"] <= 0.015 and d["warning"] is None
    assert d["Hc"] == pytest.approx(float(nvm_central(20.0, 10.0)), rel=0.04)
