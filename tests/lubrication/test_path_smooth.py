"""Smooth along the path (issue 43, item 3): the path fields of a lubrication level are smooth to the solver's
tolerance, second differences along the path below 2 % of the field's maximum wherever the load is smooth.

Mask: a position is judged only where the solver's inputs are smooth there, i.e. where the second difference of
the load per length w' (and of |SRR|, whose kink at the pitch point μ follows) is below LOAD_SMOOTH of its maximum;
at the load steps where the number of teeth in contact changes the fields step with the load, and no solver could
smooth them.  Reference: a smooth function sampled on the path's grid has second differences of order
(Δs/ℓ)^2, 0.003-0.1 % here (the load and SRR of the baseline themselves), far below the 2 %."""

import numpy as np
import pytest

from femgear.case import build_case
from femgear.levels.contact import contact_pass, reduced_modulus_of
from femgear.levels.lubrication import oil_law
from femgear.physics.ehl.path import line_ehl_path

LOAD_SMOOTH = 0.005   #: the mask: second difference of the inputs below 0.5 % of their maximum [-]


def second_differences(a) -> np.ndarray:
    a = np.asarray(a, dtype=float)
    return np.abs(a[:-2] - 2.0 * a[1:-1] + a[2:]) / np.max(np.abs(a))


def smooth_mask(*inputs) -> np.ndarray:
    """The interior positions where every input's second difference is below :data:`LOAD_SMOOTH` (module docstring)."""
    return np.all([second_differences(x) < LOAD_SMOOTH for x in inputs], axis=0)


@pytest.fixture(scope="module")
def baseline_path(baseline_scene):
    case = build_case(baseline_scene)
    contact = contact_pass(case)
    return case, contact.line_load


@pytest.mark.slow
def test_ehl_line_peak_pressure_is_smooth_along_the_baseline_path(baseline_path):
    """The ``ehl-line`` films and peak pressure on the baseline's first 12 path positions (one grid level, the path's):
    the peak pressure's second differences were 7 % of it (the outlet spike, narrower than a cell, crossing the
    nodes); on the spike-resolving grids below 2 %."""
    case, w = baseline_path
    k, sl = case.path, slice(0, 12)
    f = line_ehl_path(w[sl], k.R[sl], k.ue[sl], case.operating.ambient_temperature, oil_law(case),
                      reduced_modulus_of(case))
    mask = smooth_mask(w[sl], np.abs(k.srr[sl]))
    assert mask.sum() >= 8
    for name in ("central", "minimum", "pressure_max"):
        d2 = second_differences(getattr(f, name))[mask]
        assert d2.max() < 0.02, (name, d2.max())
