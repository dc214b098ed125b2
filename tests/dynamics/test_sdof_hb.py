"""Tier 3: the Kahraman–Singh jump by harmonic-balance continuation (issue 42 item 2).

Both branches of the slowly swept time integration (:func:`femgear.system.dynamics.sdof.kahraman_singh_sweep`,
the oscillator of Kahraman & Singh, JSV 142:49, 1990) are solutions of the continuation: the up-sweep follows the
stable lower branch to the upper fold and jumps, the down-sweep the stable resonant branch to the lower fold.
"""

import numpy as np
import pytest

from femgear.system.dynamics.sdof import kahraman_singh_sweep
from femgear.system.dynamics.sdof_hb import kahraman_singh_hb

W = np.linspace(0.6, 1.3, 36)          # the grid of ``femgear dynamics --kahraman-singh``
STEP = W[1] - W[0]


@pytest.fixture(scope="module")
def branches():
    return (kahraman_singh_hb(at=W), kahraman_singh_sweep(W, direction="up"),
            kahraman_singh_sweep(W, direction="down"))


def test_continuation_passes_both_folds_with_an_unstable_middle_branch(branches):
    hb, up, down = branches
    assert len(hb.folds) == 2 and hb.folds[0] > hb.folds[1]          # softening: turns back, then forward
    lo, hi = min(hb.folds), max(hb.folds)
    middle = (hb.frequency > lo + 0.005) & (hb.frequency < hi - 0.005) & (hb.contact_loss > 0.0)
    between = np.flatnonzero(np.diff(np.sign(np.gradient(hb.frequency))) != 0)
    assert middle.any()
    seg = slice(between[0] + 2, between[-1] - 1)                     # the branch between the two folds
    assert np.all(~hb.stable[seg])
    assert hb.stable[0] and hb.stable[-1]


def test_swept_branches_are_stable_solutions_of_the_continuation(branches):
    """Each swept amplitude equals a stable harmonic-balance solution at its Ω to 1 %, but at the grid points next
    to a fold, where the slow sweep has not settled onto the branch (the saddle-node's slow passage)."""
    hb, up, down = branches
    near_fold = np.min(np.abs(W[:, None] - np.array(hb.folds)[None, :]), axis=1) < STEP
    for amp in (up.amplitude, down.amplitude[::-1]):
        err = np.nanmin(np.abs(hb.stable_at / amp[:, None] - 1), axis=1)
        assert np.all(err[~near_fold] < 0.01), err
    bistable = np.sum(~np.isnan(hb.stable_at[:, 1]))
    assert 4 <= bistable <= 7                                        # two stable branches over 0.80–0.91


def test_jumps_of_the_sweeps_fall_at_the_folds(branches):
    """Each sweep jumps within one grid step of the fold that ends its branch: the up-sweep between the two grid
    points around the upper fold, the down-sweep around the lower one."""
    hb, up, down = branches
    for amp, fold in ((up.amplitude, max(hb.folds)), (down.amplitude[::-1], min(hb.folds))):
        j = int(np.argmax(np.abs(np.diff(amp))))                     # the jump lies between W[j] and W[j + 1]
        assert W[j] - STEP <= fold <= W[j + 1] + STEP
    assert np.argmax(np.diff(up.amplitude)) > np.argmax(np.diff(down.amplitude[::-1]))   # hysteresis


def test_spur_pair_with_its_own_mesh_stiffness_by_continuation():
    """The spur pair of ``studies/dynamics/spur_jump.py`` (FZG C14, PEM stiffness, 20 N m, 50 µm backlash): the
    time-varying stiffness is the excitation.  Both swept branches are stable continuation solutions to 1 %; the
    up-sweep jumps at the upper fold, the impacting branch the down-sweep follows reaches below the sweep's range."""
    import sys
    from pathlib import Path

    sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "studies" / "dynamics"))
    from spur_jump import run, setup

    res = run(*setup(), coarse=True)
    stable = np.array(res["hb"]["stable_at_ratio"])
    for d in ("up", "down"):
        err = np.nanmin(np.abs(stable / res[d]["amplitude"][:, None] - 1), axis=1)
        assert np.all(err < 0.01), (d, err)
    upper, lower = max(res["hb"]["folds"]), min(res["hb"]["folds"])
    r, a_up = res["ratio"], res["up"]["amplitude"]
    j = int(np.argmax(np.diff(a_up)))
    assert r[j] <= upper <= r[j + 1] and lower < r[0]
