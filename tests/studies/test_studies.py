"""The paper-comparison studies at their coarsest level: they run, and what they show holds.

Each study's ``run()`` runs once (``coarse=True``, as CI does) in a module fixture.  Tests
are labelled by what they prove: ``test_*`` check physics that could be false (identities
of the model, monotonic trends a mechanism implies); ``test_transcription_*`` check our
copy of the paper's tables, not femgear; ``test_regression_*`` keep a measured femgear
band so that a change is noticed (not a validation).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from studies import _common as C
from studies.paper import dynamic_backlash, meshing_error, rig_conditions, temperature_rise, wear_cycles


def _finite_amplitudes(row: dict) -> bool:
    return all(math.isfinite(row[f"{m}.{q}.{ax}"]) and row[f"{m}.{q}.{ax}"] > 0 for m, q, ax in C.AMPLITUDE_KEYS)


def test_transcription_of_the_paper_tables():
    """A data check of our transcription: Table 7's theory is within its stated 20 % of its
    test values, Table 4's amplitudes grow with wear.  It says nothing about femgear."""
    theory = np.array([v[0::2] for v in C.PAPER_TABLE7.values()])
    test = np.array([v[1::2] for v in C.PAPER_TABLE7.values()])
    assert len(C.PAPER_TABLE7) == 15
    assert np.max(np.abs(theory - test) / test) < 0.20
    for member in ("gear", "pinion"):
        rows = np.array([C.PAPER_TABLE4[member][n] for n in range(4)])
        assert np.all(np.diff(rows, axis=0) >= 0)


@pytest.fixture(scope="module")
def temperature():
    return temperature_rise.run(coarse=True)


@pytest.fixture(scope="module")
def backlash():
    return dynamic_backlash.run(coarse=True)


@pytest.fixture(scope="module")
def rig():
    return rig_conditions.run(coarse=True)


def test_wear_cycles_claims():
    res = wear_cycles.run(coarse=True, cycles=(0.0, 1e6, 2e6))
    rows = res["rows"]
    assert all(_finite_amplitudes(r) for r in rows)
    depth = [r["max_wear_pinion_um"] for r in rows]
    assert depth[0] == 0.0 and depth[0] < depth[1] < depth[2]          # wear deepens with cycles
    assert 1.0 < depth[1] < 30.0                                       # µm after 1e6 cycles (K = 1e-6)
    worn = res["cases"][1]                                             # the typed RunResult of the 1e6 case
    wear = worn.tribology.wear
    i_pitch = int(np.argmin(np.abs(worn.case.path.u - worn.case.pair.u_pitch)))
    assert wear[0, i_pitch] < 0.2 * wear[0].max()                      # least wear at the pitch point (Fig. 15)
    # wear acts on the drive flanks only, once (issue 13): the coast tables carry only the thermal
    # closing (≤ 0) and drive − coast is the contact-line mean of h1 + h2, within its extremes
    drive, coast = C.deviation_tables(worn)
    assert np.all(coast <= 0.0)
    h, worn_table = wear.sum(axis=0), drive - coast
    assert h.min() < worn_table.min() <= worn_table.max() < h.max()
    mu = worn.tribology.friction_coefficient
    assert mu[i_pitch] < 0.2 * mu.max()                                # U-shaped μ, minimum at the pitch point


def test_temperature_rise_claims(temperature):
    rows = {r["case"]: r for r in temperature["rows"]}
    assert all(_finite_amplitudes(r) for r in rows.values())
    dev = [rows[k]["max_thermal_deviation_um"] for k in ("off", "15 K", "30 K", "45 K")]
    assert dev[0] == 0.0 and dev[1] < dev[2] < dev[3]                  # expansion grows with the rise
    assert dev[2] == pytest.approx(2 * dev[1], rel=1e-6)               # linear (analytic model)
    assert rows["lubrication"]["flank_temperature_rise_K"] > 0


def test_regression_temperature_rise_barely_changes_the_response(temperature):
    """Regression (femgear's measured band, not a validation): a nearly uniform expansion only
    closes the backlash; the response changes by < 5 % from 0 to 45 K."""
    rows = {r["case"]: r for r in temperature["rows"]}
    for key in ("gear.displacement.y", "gear.velocity.y", "pinion.displacement.y", "pinion.velocity.y"):
        assert abs(rows["45 K"][key] / rows["off"][key] - 1) < 0.05


def test_dynamic_backlash_identities(backlash):
    """The half-width b0 + (d_D + d_C)/2 of the dead zone: wear (drive flanks, d ≥ 0) opens it,
    expansion (both flanks, d < 0) closes it, and both together add (the tables are linear)."""
    rows, b0 = backlash["rows"], backlash["b0_um"]
    assert b0 == pytest.approx(50.0)
    assert np.allclose(rows["none"]["b_um"], b0)
    assert rows["wear"]["mean_um"] > b0 and rows["wear"]["min_um"] >= b0
    assert rows["thermal"]["mean_um"] < b0 and rows["thermal"]["max_um"] <= b0
    both = rows["wear+thermal"]["mean_um"] - b0
    assert both == pytest.approx((rows["wear"]["mean_um"] - b0) + (rows["thermal"]["mean_um"] - b0), rel=0.05)


def test_regression_balanced_backlash_crosses_b0(backlash):
    """Regression: at the flank rise where thermal closing balances the mean wear opening, the
    intra-cycle wear ripple straddles b0 (the paper's 'first above, then below')."""
    assert backlash["rows"]["balanced"]["crosses_b0"]


def test_meshing_error_claims():
    res = meshing_error.run(coarse=True)
    rows = res["rows"]
    assert rows["none"]["peak_to_peak_um"] == 0.0
    assert rows["wear"]["peak_to_peak_um"] > 10 * rows["thermal"]["peak_to_peak_um"] > 0
    assert rows["wear"]["fit_residual_rms_um"] < 0.5 * rows["wear"]["rms_fluctuation_um"]


def test_rig_conditions_table(rig):
    v = rig["variants"]["free"]
    acc = np.asarray(v["acceleration"])
    assert acc.shape == (15, 2) and np.all(np.isfinite(acc)) and np.all(acc > 0)
    assert len(rig["conditions"]) == 15 and len(v["error_percent"]) == 30
    raw = np.asarray(v["acceleration_unfiltered"])
    assert np.all(acc < raw)                   # a low-pass filter can only remove content


def test_regression_rig_acceleration_character(rig):
    """Regression (femgear's measured character, not the rig's): the lighter pinion's bearings
    vibrate more than the gear's, and the filtered acceleration grows with torque (the
    stiffness ripple scales with load; the rig's values do not)."""
    v = rig["variants"]["free"]
    acc, raw = np.asarray(v["acceleration"]), np.asarray(v["acceleration_unfiltered"])
    assert np.all(raw[:, 0] > raw[:, 1])
    assert np.all(np.diff(acc[:, 0].reshape(5, 3), axis=1) > 0)


def test_transcription_of_the_papers_own_errors(rig):
    """Our copy of Table 7: the paper's own theory-vs-test errors stay below its 20 %."""
    assert rig["paper_errors"]["max_error_percent"] < 20.0
