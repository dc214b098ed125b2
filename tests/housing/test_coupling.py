"""The housing couplings against each other and the trends of the literature on the baseline pair."""

from dataclasses import replace

import numpy as np
import pytest

from femgear.levels.housing import HousingLayer
from femgear.physics.housing.fe import housing_frf, modal_damping
from femgear.system.dynamics.housing import couple_housing
from femgear.system.dynamics.nvh import housing_sweep

SPEEDS = np.linspace(100.0, 1500.0, 15)
SENSORS = ("S1", "S2", "S3", "S4")


def _fe(model, red):
    return housing_sweep(couple_housing(model, red), HousingLayer("fe", "craig-bampton", SENSORS, reduced=red), SPEEDS, 6)


def _frf(model, red, coupling, grid):
    return housing_sweep(model, HousingLayer("frf", coupling, SENSORS, frf=housing_frf(red, grid, SENSORS)), SPEEDS, 6)


def _stiff(red, factor=1e3):
    """The same housing ``factor`` times stiffer (K ∝ E; the modal damping at the new frequencies)."""
    return replace(red, K=factor * red.K, C=modal_damping(factor * red.K, red.M, red.damping_ratio))


def test_lm_fbs_with_the_fe_housings_own_frfs_equals_the_coupled_fe_housing(rigid_model, reduced):
    """LM-FBS (rotor with free bearing outer rings ⊕ the FE housing's receptances at the seats) is the coupled model
    in the frequency domain: sensors, bearing loads and mesh forces agree to round-off (the FRF grid holds every
    line's frequency, so no interpolation enters)."""
    fe = _fe(rigid_model, reduced)
    fbs = _frf(rigid_model, reduced, "lm-fbs", np.unique(fe.frequency))
    for name in ("sensor_acceleration", "bearing_force", "mesh_force"):
        a, b = getattr(fbs, name), getattr(fe, name)
        assert np.max(np.abs(a - b)) < 1e-9 * np.max(np.abs(b)), name


def test_receiver_equals_the_coupled_housing_in_the_stiff_limit_and_shows_the_coupling_otherwise(rigid_model, reduced):
    """Receiver: sensor = H · bearing forces of the rotor on a rigid housing.  On a housing 1000× stiffer than the
    baseline's (it no longer loads the bearings) it reads the coupled housing's sensors within 1 %; on the baseline
    housing the coupling changes them by more than 30 % somewhere in the sweep (its modes shift the rotor's)."""
    for red, lo, hi in ((_stiff(reduced), 0.0, 0.01), (reduced, 0.3, np.inf)):
        fe = _fe(rigid_model, red)
        rec = _frf(rigid_model, red, "receiver", np.unique(fe.frequency))
        diff = np.max(np.abs(rec.sensor_acceleration - fe.sensor_acceleration)) / np.max(np.abs(fe.sensor_acceleration))
        assert lo <= diff < hi, diff


def test_a_compliant_housing_lowers_the_natural_frequencies(rigid_model, reduced):
    """Shock and Vibration 2017, art. 4846532: housing compliance lowers the system's natural frequencies.  Here a
    theorem: the rigid housing is the coupled system with its seats held, so the k-th frequency can only fall
    (Rayleigh's constraint theorem); the lowest mode that strains the mesh (≥ 5 % of its strain energy: 2.76 kHz on a
    rigid housing, pinion torsion on the bearings) falls by more than 3 % (2.60 kHz on the coarse housing)."""
    coupled = couple_housing(rigid_model, reduced)
    f_r, f_c = np.array(rigid_model.flexible_modes_hz), np.array(coupled.flexible_modes_hz)
    assert np.all(f_c[:f_r.size] <= f_r * (1 + 1e-9))
    from femgear.system.dynamics.modal import RESONANCE_MESH_ENERGY, modal_analysis

    def mesh_mode(model):
        m = modal_analysis(model)
        return m.frequencies[(m.frequencies > 1.0) & (m.energy["mesh"] >= RESONANCE_MESH_ENERGY)][0]
    assert mesh_mode(coupled) < 0.97 * mesh_mode(rigid_model)


def test_housing_changes_the_bearing_forces_more_than_the_mesh_force(rigid_model, reduced):
    """The same paper: housing compliance changes the dynamic bearing forces significantly and the dynamic mesh force
    little.  Over 100–1500 rpm × mesh orders 1–6 of the baseline, the median relative change of the bearing loads
    is larger than that of the mesh forces (figures: studies/housing/housing_effect.py)."""
    change = _fe(rigid_model, reduced).force_change()
    assert np.median(change["bearing"]) > np.median(change["mesh"])


def test_timoshenko_level_is_refused(baseline_scene, reduced):
    from femgear.case import build_case
    from femgear.system.dynamics import build_model

    model = build_model(build_case(baseline_scene), "timoshenko", stiffness="contact-line", friction=0.0)
    with pytest.raises(ValueError, match="lumped dynamics level only"):
        couple_housing(model, reduced)
