"""The rigid-isoviscous limit of the point-contact solver (issue 4, 'Limits').

With rigid surfaces and L = 0, H M^2 is independent of M (self-similarity of the groups)
and, on domains growing like R X_s, tends to its infinite-domain value as H_inf - C/R
(P ~ r^-3 upstream).  The extrapolated value is checked against Brewe, Hamrock & Taylor
(1979), 35.0 M^-2; NVM's fitted asymptote (41.3 M^-2) lies 17 % above it (see
``studies/ehl/ehl_rigid_limit.py`` and the README)."""

import sys
from pathlib import Path

import pytest

from femgear.physics.contact.film import rigid_isoviscous_point
from femgear.physics.ehl.point import solve_point

ROOT = Path(__file__).resolve().parents[2]
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))

from studies.ehl import ehl_rigid_limit as study  # noqa: E402


def test_brewe_hamrock_taylor_coefficient():
    assert rigid_isoviscous_point(1.0) == pytest.approx(35.03, abs=0.01)
    # wide contacts (lambda < 1) carry a thicker rigid film
    assert rigid_isoviscous_point(0.5) > rigid_isoviscous_point(1.0)


def test_rigid_isoviscous_is_self_similar_in_M():
    """H M^2 of the rigid, isoviscous problem does not depend on M (same scaled domain)."""
    hm2 = [solve_point(M, 0.0, level=1, coarse_level=1, rigid=True,
                       domain=study.ri_domain(M, 8.0)).Hc * M**2 for M in (5.0, 10.0)]
    assert hm2[0] == pytest.approx(hm2[1], rel=1e-6)


def test_inverse_radius_fit_recovers_a_known_law():
    h_inf, c = study.inverse_radius_fit([8, 16, 32], [35 - 80 / 8, 35 - 80 / 16, 35 - 80 / 32])
    assert (h_inf, c) == pytest.approx((35.0, 80.0))


@pytest.mark.slow
def test_rigid_isoviscous_limit_reaches_brewe_hamrock_taylor():
    """Level 4, R = 16 and 32: mesh-extrapolated, then 1/R-extrapolated H M^2 within 3 %
    of Brewe-Hamrock-Taylor; the truncated values rise with R."""
    rows = [study.solve_rigid_limit(study.M_RIGID, R, lmax=4) for R in (16.0, 32.0)]
    vals = [r["HM2_extrapolated"] for r in rows]
    assert vals[0] < vals[1]
    assert all(r["load_error"] < 1e-4 for r in rows)
    h_inf, _ = study.inverse_radius_fit([16.0, 32.0], vals)
    assert h_inf == pytest.approx(rigid_isoviscous_point(1.0), rel=0.03)


def test_elastic_solver_reaches_the_rigid_limit_at_small_M():
    """At M = 0.5 (L = 0) the elastic solution equals the rigid one to 1e-3: the full
    solver is in its rigid-isoviscous regime (the start widens the Hertz ellipse on a
    grid coarser than the contact)."""
    dom = study.ri_domain(0.5, 8.0)
    el, ri = (solve_point(0.5, 0.0, level=1, coarse_level=1, rigid=r, domain=dom) for r in (False, True))
    assert el.Hc == pytest.approx(ri.Hc, rel=1e-3)
    assert el.load_error < 1e-6
