"""The ``tehl-point`` level's coupling-loop solver for pairs of line contacts: face slices read off a line TEHL
friction map (:mod:`femgear.physics.tehl.slice_map`) against the direct face-slice hand-over."""

from __future__ import annotations

import numpy as np
import pytest

from femgear.physics.lubrication.map import DT_FLOOR, DT_TOLERANCE, MU_TOLERANCE
from femgear.physics.tehl.slices import slice_inputs
from tests.conftest import BASELINE


@pytest.fixture(scope="module")
def baseline():
    from femgear.case import build_case
    from femgear.levels.contact import contact_pass
    from femgear.scene import load_scene

    case = build_case(load_scene(BASELINE, ['physics.lubrication="tehl-point"']))
    return case, contact_pass(case)


def test_the_axes_cover_every_slice_of_the_envelope(baseline):
    """Every slice of the envelope's contacts at the map's two outer loads lies inside the axes (none clamped);
    the uncrowned line's slices carry its load, so the load axis is the ``tehl`` map's (0.5, 1, 2 × w̄)."""
    from femgear.levels.lubrication import envelope_contact, point_geometry, tehl_setup
    from femgear.physics.tehl.slice_map import all_slender, slice_map_axes

    case, _ = baseline
    geo, slices = point_geometry(case)
    contact = envelope_contact(case)
    E = tehl_setup(case).E_red
    axes = slice_map_axes(contact, geo, slices, E, 313.0)
    assert all_slender(geo, contact.kin.R)
    np.testing.assert_allclose(axes["w"], contact.load_per_length * np.array([0.5, 1.0, 2.0]), rtol=1e-12)
    k = contact.kin
    for i in range(k.R.size):
        for f in (0.5, 2.0):
            _, wj, Rj, uej, srrj, _ = slice_inputs(f * contact.load_per_length, k.R[i], k.ue[i], abs(k.srr[i]),
                                                   k.R[i], np.inf, slices, E)
            for name, v in (("w", wj), ("R", Rj), ("ue", uej), ("srr", np.abs(srrj))):
                assert axes[name][0] * (1 - 1e-12) <= v.min() and v.max() <= axes[name][-1] * (1 + 1e-12), name
    # the slices at the line's ends reach beyond the centre path: the map spans more than the path's radii
    assert axes["R"][0] < k.R.min() and axes["R"][-1] > k.R.max()


def test_a_crowned_pair_with_point_contacts_keeps_its_direct_solves(baseline):
    """The paper's 10 µm crowning makes elliptic contacts (R_x/R_y ≈ 0.0045 > 0.004): no slice map."""
    from femgear.case import build_case
    from femgear.levels.lubrication import slice_map_solver_of
    from femgear.scene import load_scene

    crowned = build_case(load_scene(BASELINE, ['physics.lubrication="tehl-point"', "modifications.crowning=10e-6"]))
    assert slice_map_solver_of(crowned) is None
    assert slice_map_solver_of(baseline[0]) is not None


def test_slices_off_the_map_agree_with_direct_slices_within_the_maps_tolerance(baseline):
    """Validation of the stand-in: at three path positions (both flanks' sliding and beside the pitch point) and a
    bulk temperature between the map's two, μ and the surface rise of the slices read off the map agree with the
    direct hand-over's solved slices to the map's own tolerances (5 % of μ, 5 % of the largest rise or 1 K);
    the map's measured error is within its tolerance and is what the level reports."""
    from femgear.levels.lubrication import lubrication_solver, tehl_point_solver

    case, cp = baseline
    k = cp.kin
    idx = np.array([0, k.R.size // 2 - 3, k.R.size - 1])
    w = np.broadcast_to(cp.load_per_length, k.R.shape)[idx]
    T = np.full(idx.size, case.operating.ambient_temperature + 10.0)
    lub = lubrication_solver(case, repeated=True)
    assert lub.map_error is None                        # built on first use
    mu_m, dT_m = lub(w, k.R[idx], k.ue[idx], np.abs(k.srr[idx]), T)
    mu_d, dT_d = tehl_point_solver(case)(w=w, R=k.R[idx], ue=k.ue[idx], srr=np.abs(k.srr[idx]), T=T)
    assert np.all(np.abs(mu_m - mu_d) <= MU_TOLERANCE * np.maximum(mu_d, 0.005))
    assert np.all(np.abs(dT_m - dT_d) <= max(DT_TOLERANCE * dT_d.max(), DT_FLOOR))
    assert lub.map_error is not None and lub.map_error.within_tolerance
