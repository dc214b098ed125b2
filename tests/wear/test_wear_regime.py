"""Wear that knows the film (issue 37, item 3): the asperity-borne load wears (wear.load = "asperity", the default),
negligibly in full film; the paper's constant-coefficient form (wear.load = "total") stays for its studies and is
warned, naming λ, where the film carries the load; no NaN leaves the wear integration.

Before, Archard wear took the whole load whatever the film: 135 µm of pinion wear in 10 h on the turbo pair
(131 m/s), without a word.
"""

from __future__ import annotations

import math
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from femgear.case import build_case
from femgear.errors import ConvergenceError
from femgear.levels import wear as wear_levels
from femgear.physics.wear import WearState, run_wear
from femgear.physics.wear.archard import stepped
from femgear.physics.wear.regime import AsperityShare
from femgear.pipeline import run_case
from femgear.scene import load_scene

ZOO = Path(__file__).resolve().parents[2] / "studies" / "zoo"
STATIC = ['physics.dynamics="none"', 'physics.coupling="one-way"', 'physics.wear="archard"']
TEN_HOURS = 10 * 60 * 14676.0        #: pinion revolutions of the turbo pair in 10 h


def _wear(scene: str, *overrides: str):
    result = run_case(build_case(load_scene(ZOO / f"{scene}.toml", STATIC + list(overrides)), warn=False))
    return result.tribology


@pytest.fixture(scope="module")
def turbo():
    """The turbo pair's 10 h of wear with each load; and with superfinished flanks (σ = 0.15 µm)."""
    cycles = f"wear.cycles={TEN_HOURS}"
    return {(load, rq): _wear("turbo", cycles, f'wear.load="{load}"', *([f"roughness.rq={rq}"] if rq else []))
            for load in ("asperity", "total") for rq in (0.0, 1.5e-7)}


def test_in_full_film_the_asperity_borne_wear_is_negligible(turbo):
    """λ = h/σ > 3 all along the path (superfinished flanks): the asperities carry < 1e-9 of the load (Greenwood–
    Tripp's F_5/2 at t > 3), and 10 h wear less than a picometre, where the whole load would wear 135 µm."""
    full, whole = turbo["asperity", 1.5e-7], turbo["total", 1.5e-7]
    assert full.wear_film_parameter > 3 and full.wear_asperity_share < 1e-9
    assert whole.wear.max() > 100e-6
    assert full.wear.max() < 1e-12 and full.wear.max() < 1e-7 * whole.wear.max()
    assert full.wear_load == "asperity" and full.wear_warnings == ()


def test_on_the_turbo_pair_as_built_the_film_carries_the_load(turbo):
    """With ground flanks (R_a 0.4 µm: σ = 0.71 µm) the thermal film (Moes × Gupta's inlet heating at 131 m/s) leaves
    λ ≥ 1.2 along the path: the asperities carry at most 0.3 % of the load, so 10 h wear about a hundredth of what
    the constant-coefficient form says."""
    asperity, whole = turbo["asperity", 0.0], turbo["total", 0.0]
    assert 1.0 < asperity.wear_film_parameter < 3 and asperity.wear_asperity_share < 0.01
    assert asperity.wear.max() < 0.02 * whole.wear.max()


@pytest.mark.parametrize("rq", [0.0, 1.5e-7])
def test_the_papers_form_on_a_pair_whose_film_carries_the_load_is_warned_naming_lambda(turbo, rq):
    result = turbo["total", rq]
    assert len(result.wear_warnings) == 1
    text = result.wear_warnings[0]
    assert text.startswith("wear.load: ") and "λ = h/σ ≥" in text and f"{result.wear_film_parameter:.3g}" in text
    assert ("full film (λ > 3)" in text) == (rq > 0)


def test_the_warning_reaches_results_json(turbo, tmp_path):
    from femgear.edge.run import run_scene

    scene = load_scene(ZOO / "turbo.toml", STATIC + ["wear.cycles=1e5", 'wear.load="total"', "roughness.rq=1.5e-7"])
    wear = run_scene(scene, tmp_path, plots=False).summary["wear"]
    assert wear["load"] == "total" and wear["film_parameter_min"] > 3 and len(wear["warnings"]) == 1


def test_one_step_of_asperity_wear_is_the_whole_loads_times_the_share():
    """The identity of the form: Δh = (K/H) f_a(w̄') w̄' |v_s|/v_j, i.e. the whole load's first step × f_a pointwise."""
    case = build_case(load_scene(ZOO / "fzg_c14.toml", STATIC + ["wear.cycles=1.0"]), warn=False)
    model = wear_levels.of(case)
    setup = model.setup(case.pair, case.path, case.operating.normal_force, 2e10 * case.pair.b / case.pair.mean_contact_length)
    whole = replace(setup, share=None)
    one = next(stepped(setup, lambda s: _rates(setup, s), WearState.zero(case.path.u.size), 1.0))
    ref = next(stepped(whole, lambda s: _rates(whole, s), WearState.zero(case.path.u.size), 1.0))
    _, _, w = _rates(whole, WearState.zero(case.path.u.size))
    f = model.share(w)
    assert 0.001 < f.max() < 0.2             # FZG C at 8.3 m/s, 90 °C: mixed lubrication
    np.testing.assert_allclose(one.h1, ref.h1 * f, rtol=1e-12, atol=1e-30)
    np.testing.assert_allclose(one.h2, ref.h2 * f, rtol=1e-12, atol=1e-30)


def _rates(setup, state):
    from femgear.physics.wear import wear_rates

    return wear_rates(setup, state)


@pytest.mark.parametrize("contact", ["greenwood-tripp", "zhou-hoeprich"])
def test_the_share_grows_as_the_film_thins(contact):
    """Johnson–Greenwood–Poon with Greenwood–Tripp asperities, or the Zhou–Hoeprich share exp(−B λ^C) (the wear
    reads the tribology's ``roughness.contact``): rougher flanks, thinner film parameter, larger asperity share,
    monotonically (the same pair, the nominal load at the pitch point)."""
    shares, lams = [], []
    for rq in (1e-7, 3e-7, 1e-6, 3e-6):
        model = wear_levels.of(build_case(load_scene(ZOO / "paper_baseline.toml", STATIC + [
            f"roughness.rq={rq}", f'roughness.contact="{contact}"']), warn=False))
        t = model.share_table
        i = t.loads.size // 2
        shares.append(t.fraction[:, i].mean())
        lams.append(t.film_parameter[:, i].mean())
        if contact == "zhou-hoeprich":
            np.testing.assert_allclose(t.fraction[:, i], np.exp(-1.90 * t.film_parameter[:, i] ** 0.99), rtol=1e-12)
    assert np.all(np.diff(lams) < 0) and np.all(np.diff(shares) > 0)
    assert shares[0] < 1e-5 and shares[-1] > 0.03


def test_the_table_reads_back_its_own_samples_and_holds_its_ends():
    loads = np.geomspace(1e4, 1e6, 5)
    frac = np.array([[0.5, 0.2, 0.1, 0.05, 0.01], [0.4, 0.3, 0.2, 0.1, 0.0]])
    share = AsperityShare(loads=loads, fraction=frac, film_parameter=1 / (frac + 0.1), sigma=1e-6)
    np.testing.assert_allclose(share(np.tile(loads[2], 2)), frac[:, 2])
    np.testing.assert_allclose(share(np.array([1.0, 1e9])), [0.5, 0.0])      # held beyond the table
    mid = math.sqrt(loads[0] * loads[1])
    np.testing.assert_allclose(share(np.array([mid, mid])), 0.5 * (frac[:, 0] + frac[:, 1]))
    assert share(np.zeros((3, 2))).shape == (3, 2)                             # unloaded points, any leading axes
    with pytest.raises(ValueError, match="fraction"):
        AsperityShare(loads=loads, fraction=frac + 1.0, film_parameter=frac, sigma=1e-6)


def test_a_non_finite_wear_rate_raises_with_its_history_and_no_nan_leaves():
    case = build_case(load_scene(ZOO / "fzg_c14.toml", STATIC + ["wear.cycles=1e6"]), warn=False)
    setup = wear_levels.static_setup(case)
    n = case.path.u.size
    calls = {"n": 0}

    def rates(state):
        calls["n"] += 1
        from femgear.physics.wear import wear_rates

        r1, r2, w = wear_rates(setup, state)
        return (r1 * np.nan, r2, w) if calls["n"] > 2 else (r1, r2, w)

    with pytest.raises(ConvergenceError) as info:
        for _ in stepped(setup, rates, WearState.zero(n), 1e6):
            pass
    assert "non-finite" in str(info.value) and len(info.value.history["cycles"]) == 2


def test_no_load_wears_nothing_without_nan():
    """A pass in which the flanks lose contact (zero load everywhere) wears nothing and leaves finite depths."""
    case = build_case(load_scene(ZOO / "fzg_c14.toml", STATIC + ["wear.cycles=1e6"]), warn=False)
    setup = replace(wear_levels.static_setup(case), force=0.0)
    with np.errstate(all="raise"):
        state = run_wear(setup, 1e6)
    assert np.all(state.h1 == 0) and np.all(state.h2 == 0) and state.steps == 1
