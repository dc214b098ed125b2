"""Wear removes material, so it opens the backlash; thermal growth closes it (issue 37, item 3).

The model of each coupling pass (:func:`femgear.system.coupling.passes.pass_model`) is read here for the thing it
must get right: with wear w on the drive flanks the drive flanks touch w later and the dead zone's half-width
grows by w/2; a pair without backlash never jams from wear; and where the flanks would jam, the refusal says that
the thermal growth closes the dead zone and the wear opens it.  Before, that refusal read "the flank deviations
close the dead zone", after a wear study had computed for minutes: the user took it for wear closing the
backlash.
"""

from __future__ import annotations

import itertools
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from femgear.case import build_case
from femgear.errors import SceneError
from femgear.scene import load_scene
from femgear.system.coupling import CouplingSetup, coupling_iterations
from femgear.system.coupling.passes import pass_model

FZG = Path(__file__).resolve().parents[2] / "studies" / "zoo" / "fzg_c14.toml"
COUPLED = ['physics.dynamics="lumped"', 'physics.coupling="bidirectional"', 'physics.stiffness="pem"',
           'physics.wear="archard"', "wear.cycles=1e6", 'physics.thermal="analytic"',
           "numerics.dynamics_cycles=30", "numerics.transient_cycles=10"]


def _start(backlash: float):
    setup = CouplingSetup.from_case(build_case(load_scene(FZG, COUPLED + [f"pair.backlash={backlash}"]), warn=False),
                                    n_phase=64)
    return setup, next(coupling_iterations(setup))


@pytest.fixture(scope="module")
def start():
    return _start(50e-6)


def _thresholds(model):
    """(drive, coast) contact thresholds of each helix over one mesh period: δ > drive or δ < −coast touches."""
    t = np.arange(64) / 64 / model.mesh_frequency
    half = model.backlash_at(t)
    shift = np.zeros_like(half) if model.deviation is None else \
        np.array([np.interp(np.arange(64) / 64, np.arange(model.deviation.shift.shape[1]) / model.deviation.shift.shape[1],
                            model.deviation.shift[s], period=1.0) for s in range(2)])
    return half + shift, half - shift


def test_uniform_wear_opens_the_drive_side_by_its_depth(start):
    setup, state = start
    n = setup.kin.u.size
    zero = np.zeros((2, n))
    new, *_ = pass_model(setup, replace(state, wear=zero, thermal_deviation=zero))
    worn, *_ = pass_model(setup, replace(state, wear=np.full((2, n), 2e-6), thermal_deviation=zero))   # h1 + h2 = 4 µm
    d0, c0 = _thresholds(new)
    d1, c1 = _thresholds(worn)
    np.testing.assert_allclose(d1 - d0, 4e-6, rtol=1e-9)      # the drive flanks touch 4 µm later
    np.testing.assert_allclose(c1 - c0, 0.0, atol=1e-15)      # the coast flanks are not worn
    t = np.arange(64) / 64 / new.mesh_frequency
    np.testing.assert_allclose(worn.backlash_at(t) - new.backlash_at(t), 2e-6, rtol=1e-9)   # the play opens


def test_the_computed_wear_opens_and_the_thermal_growth_closes(start):
    setup, state = start
    n = setup.kin.u.size
    assert state.wear.max() > 0 and state.thermal_deviation.max() > 0
    zero = np.zeros((2, n))
    t = np.arange(64) / 64 / setup.model.mesh_frequency
    base = pass_model(setup, replace(state, wear=zero, thermal_deviation=zero))[0].backlash_at(t)
    worn = pass_model(setup, replace(state, thermal_deviation=zero))[0].backlash_at(t)
    hot = pass_model(setup, replace(state, wear=zero))[0].backlash_at(t)
    assert np.all(worn >= base) and np.any(worn > base)
    assert np.all(hot < base)


def test_a_pair_without_backlash_never_jams_from_wear():
    setup, state = _start(0.0)
    worn = replace(state, thermal_deviation=np.zeros_like(state.thermal_deviation))
    model, *_ = pass_model(setup, worn)
    assert np.all(model.backlash_at(np.linspace(0, 1 / model.mesh_frequency, 33)) >= 0)


def test_a_jam_names_the_thermal_growth_as_what_closes_and_the_wear_as_what_opens():
    setup, state = _start(0.0)
    with pytest.raises(SceneError) as info:
        pass_model(setup, state)
    err = info.value
    assert err.key == "pair.backlash"
    assert "the thermal growth closes it by up to" in err.message and "the wear opens it by" in err.message
    assert "bulk flank temperature rise" in err.message


def test_the_coupled_run_reports_the_same_refusal():
    setup, _ = _start(0.0)
    with pytest.raises(SceneError, match="the thermal growth closes it"):
        list(itertools.islice(coupling_iterations(setup), 2))
