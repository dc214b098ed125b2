"""The face slices of a wide helix as a quadrature along the contact line (:mod:`femgear.physics.tehl.slices`):
the Gauss rules against their defining exactness, the split at the pitch point against a step-like integrand,
and a split line solved with the previous contact's level (the hand-over's reuse of its grid level)."""

import math

import numpy as np
import pytest

from femgear.physics.tehl.slices import SliceGeometry, slice_inputs, slice_nodes, slice_rule


@pytest.mark.parametrize("rule, exact_to", [("legendre", 7), ("lobatto", 5), ("radau", 6)])
def test_gauss_rules_integrate_polynomials_to_their_degree(rule, exact_to):
    """An n-point rule integrates x^k over [−1, 1] exactly to k = 2n−1 (Legendre), 2n−2 (Radau), 2n−3 (Lobatto)
    (Abramowitz & Stegun 25.4.29–32), and not one degree further; Lobatto and Radau hold their fixed nodes."""
    x, w = slice_rule(4, rule)
    for k in range(exact_to + 2):
        exact = (1 - (-1) ** (k + 1)) / (k + 1)
        err = abs(np.dot(w, x**k) - exact)
        assert (err < 1e-13) if k <= exact_to else (err > 1e-4), (rule, k)
    assert (x[0] == -1.0) == (rule != "legendre") and (x[-1] == 1.0) == (rule == "lobatto")


def test_the_split_at_the_pitch_point_follows_the_sign_change_of_the_friction():
    """A friction force that turns its sign within a small slide at the pitch point (tanh of width 0.05 of the
    half-line): 6 split Radau nodes integrate it to 0.33 % of ∫|f| (the line's friction force without the sign
    change), 7 equal slices (the former rule) miss it by 2.5 %; without a pitch point inside, the rule is Lobatto over the line (the ends are nodes)."""
    p, d = 0.3, 0.05
    f = lambda s: np.tanh((s - p) / d)  # noqa: E731
    exact = d * (math.log(math.cosh((1 - p) / d)) - math.log(math.cosh((-1 - p) / d)))
    s, w = slice_nodes(2.0, p, 7, ends=True)
    assert s.size == 6 and w.sum() == pytest.approx(2.0, rel=1e-12) and s[0] == -1.0 and s[-1] == 1.0
    assert not np.any(np.isclose(s, p))                       # no node at the pitch point itself
    assert abs(np.dot(w, f(s)) - exact) < 0.005 * 2.0
    mid = (np.arange(7) + 0.5) * 2 / 7 - 1
    assert abs(2 / 7 * f(mid).sum() - exact) > 0.02 * 2.0
    s, w = slice_nodes(2.0, 0.97, 7, ends=True)                # the pitch point within the margin: one line
    assert s.size == 7 and s[0] == -1.0 and s[-1] == 1.0 and w.sum() == pytest.approx(2.0, rel=1e-12)


def test_the_slices_carry_the_contact_load_and_split_where_the_sliding_turns():
    """Uncrowned: every slice carries w and the weighted loads sum to F = w L (1e-12); the slices on the two
    sides of the pitch point slide in opposite directions; the pitch point's position follows from v1 = v2."""
    om1 = 2 * math.pi * 3000 / 60
    geo = SliceGeometry(om1, om1 * 21 / 86, math.radians(14.1), 0.04, 0.0)
    w, ue = 4e5, 9.0
    s, wj, Rj, uej, srrj, W = slice_inputs(w, 0.012, ue, 0.004, 0.012, math.inf, geo, 2.3e11)
    assert np.dot(W, wj) == pytest.approx(w * geo.contact_length, rel=1e-12) and np.allclose(wj, w)
    assert np.any(srrj > 0) and np.any(srrj < 0) and s.size == 6
    assert np.all(np.diff(np.sign(srrj)) <= 0) or np.all(np.diff(np.sign(srrj)) >= 0)
