"""The wear and contact load map of the ``ltca`` level: the LTCA's own load along the contact lines.

Checks: equilibrium at every phase (the map carries each helix's force), agreement with the
Winkler layer for unmodified flanks where both should agree (inside the path; the LTCA
concentrates load at the path ends, which the uniform Winkler layer cannot), a pinion tip
relief that unloads the pinion tip and so lowers its wear rate, and the two-analysis blend
that reproduces each analysis at its own deviation.
"""

import math
from dataclasses import replace

import numpy as np
import pytest

from femgear.case import build_case
from femgear.levels.wear import static_setup
from femgear.physics.geometry import kinematics, path_positions
from femgear.physics.geometry.lines import line_weights
from femgear.physics.ltca.cycle import LTCACycle
from femgear.physics.wear.load_sharing import load_map, reference_load_map, reference_loads

C_L = 1.5e10        #: a Winkler line stiffness of the order of the baseline's [N/m²]


@pytest.fixture(scope="module")
def grid(baseline_pair):
    return path_positions(baseline_pair, 61)


def _cycle(model, force, mods=None, extra=None):
    from femgear.physics.ltca.analysis import mesh_cycle

    return mesh_cycle(model, force, mods, n_phases=16, stagger=0.0, n_line=8, extra=extra)


def _reference(pair, u, res, deviation=None, mods=None, extra=None):
    """The coupling's reference of an LTCA cycle: its loads and secant stiffness w'/(δ − ε) on the grid."""
    from femgear.system.coupling.setup import ltca_reference

    dev = np.zeros(u.size) if deviation is None else deviation
    return ltca_reference(pair, u, LTCACycle.from_result(res, modifications=mods), dev, extra)


@pytest.fixture(scope="module")
def plain(coarse_model, baseline_force):
    return _cycle(coarse_model, baseline_force)


def test_the_ltca_load_map_carries_each_helix_force_at_every_phase(plain, baseline_pair, grid):
    """Σ∫ w' dl = F_s(φ) to 1e-6 for the LTCA's own helix forces, for a dynamic force that differs from
    the LTCA's, and after a deviation change (the Winkler update keeps equilibrium)."""
    p, u = baseline_pair, grid
    ref = _reference(p, u, plain)
    W = line_weights(p, u, plain.phase) / math.sin(p.beta_b)    # both helices in phase (stagger 0)

    def carried(w):
        return np.sum(w * W, axis=-1)

    own = np.array([plain.force_left, plain.force_right])
    dynamic = own * (1 + 0.2 * np.sin(2 * np.pi * plain.phase))[None, :]
    bump = 1e-6 * np.exp(-(((u - u.mean()) / (0.1 * np.ptp(u))) ** 2))
    for force, dev in ((own, 0 * u), (dynamic, 0 * u), (dynamic, bump)):
        w = reference_loads(p, u, force, dev, C_L, ref)
        assert np.all(w >= 0)
        assert np.max(np.abs(carried(w) - force) / force) < 1e-6
    # each line carries its LTCA load on the grid (lines shorter than the grid spacing would be lost)
    assert np.max(np.abs(carried(ref.load) / own - 1)) < 1e-3
    assert np.max(np.abs(carried(plain.path_load(p, u)) / own - 1)) > 0.01     # the plain interpolation does not


def test_unmodified_ltca_mean_intensity_is_close_to_the_winkler_map(plain, baseline_pair, grid, baseline_force):
    """Both carry the same force at every phase (:func:`test_the_ltca_load_map_carries_each_helix_force_at_every_phase`,
    ``tests/wear/test_line_sharing.py``).  The LTCA
    loads the ends of the path more (the contact lines meet the tip edges there: measured +26 % at A
    and +27 % at E on this coarse model, +43 % and +56 % on the level-1 model of the ``ltca`` level),
    so inside the path it carries less than the uniform Winkler layer: regression bands, measured
    −3.6 % on average (−4.0 % level 1) and −7.8 … +2.3 % pointwise (−9.2 … +2.1 %);
    ``python studies/ltca/ltca_wear_load.py`` prints both."""
    p, u = baseline_pair, grid
    F = baseline_force / 2
    ltca = reference_load_map(p, u, F, np.zeros(u.size), C_L, _reference(p, u, plain))
    wink = load_map(p, u, F, np.zeros(u.size), C_L, 16)
    inner = (wink.loaded_fraction > 0.2) & (np.abs(u - u.mean()) < 0.4 * np.ptp(u))
    ratio = ltca.mean_load[inner] / wink.mean_load[inner]
    assert -0.06 < ltca.mean_load[inner].mean() / wink.mean_load[inner].mean() - 1 < 0
    assert np.max(np.abs(ratio - 1)) < 0.12
    assert ltca.mean_load[0] > 1.1 * wink.mean_load[0] and ltca.mean_load[-1] > 1.1 * wink.mean_load[-1]


def test_a_pinion_tip_relief_lowers_the_wear_rate_at_the_pinion_tip(coarse_model, baseline_force, baseline_pair,
                                                                       baseline_scene, plain, grid):
    """Pinion tip (path end E, u → u_E): a 10 µm linear relief over 3 mm opens the gap there, the LTCA
    unloads it and the Archard rate falls; the gear's tip (start A) is untouched and keeps its rate."""
    from femgear.physics.wear import WearState, wear_rates
    from femgear.scene.schema import FlankModification, Modifications

    p, u = baseline_pair, grid
    mods = Modifications(pinion=FlankModification(tip_relief=10e-6, tip_relief_length=3e-3), gear=FlankModification())
    relieved = _cycle(coarse_model, baseline_force, mods)
    kin = kinematics(p, u, 500 * 2 * math.pi / 60)
    base = static_setup(build_case(baseline_scene), kin)
    zero = WearState.zero(u.size)
    r1_plain = wear_rates(replace(base, reference=_reference(p, u, plain)), zero)[0]
    r1_relief = wear_rates(replace(base, reference=_reference(p, u, relieved, mods=mods)), zero)[0]
    tip = u > u[-1] - 1.5e-3                 # the outer half of the relief
    assert np.all(r1_relief[tip] < 0.5 * r1_plain[tip])
    start = u < u[0] + 1.5e-3
    assert np.allclose(r1_relief[start], r1_plain[start], rtol=0.3)


def test_the_blended_reference_reproduces_each_analysis_at_its_deviation(coarse_model, baseline_force,
                                                                          baseline_pair, plain, grid):
    """A path from an unworn analysis to one on worn flanks: at its start the unworn loads, at its end
    the worn LTCA's loads (both scaled to the same force), in between a blend in equilibrium."""
    from femgear.physics.ltca.separation import path_deviation

    p, u = baseline_pair, grid
    wear = 3e-6 * ((u - p.u_pitch) / np.ptp(u)) ** 2 * 4
    worn = _cycle(coarse_model, baseline_force, extra=path_deviation(p, u, np.array([wear, 0 * wear])))
    end = _reference(p, u, worn, wear, extra=path_deviation(p, u, np.array([wear, 0 * wear])))
    ref = replace(_reference(p, u, plain), end=end, start=np.zeros(u.size))
    F = np.array([worn.force_left, worn.force_right])
    at_end = reference_loads(p, u, F, wear, C_L, ref)
    assert np.allclose(at_end, reference_loads(p, u, F, wear, C_L, end), rtol=1e-9, atol=1e-9)
    at_start = reference_loads(p, u, F, 0 * wear, C_L, ref)
    assert np.allclose(at_start, reference_loads(p, u, F, 0 * wear, C_L, _reference(p, u, plain)), rtol=1e-9,
                       atol=1e-9)
    assert ref.progress(0.5 * wear) == pytest.approx(0.5)
    half = reference_loads(p, u, F, 0.5 * wear, C_L, ref)
    W = line_weights(p, u, ref.phases) / math.sin(p.beta_b)
    assert np.max(np.abs(np.sum(half * W, axis=-1) - F) / F) < 1e-6
    # the worn ends carry less than the unworn ones
    assert np.mean(at_end[:, :, 0]) < np.mean(at_start[:, :, 0])


def test_a_reference_of_the_wrong_shape_is_refused(plain, baseline_pair, grid):
    ref = _reference(baseline_pair, grid, plain)
    with pytest.raises(ValueError, match="reference load shape"):
        reference_loads(baseline_pair, grid[:-1], 1e3, np.zeros(grid.size - 1), C_L, ref)


def test_a_coupling_pass_shares_the_wear_and_the_contact_load_like_its_ltca_cycles(plain, coarse_model,
                                                                                   baseline_force, baseline_pair, grid):
    """The contact response reads the pass's deviated cycle at its own deviation (h1 + h2 − ζ_T); the wear
    integration starts from the unworn cycle (at h = Σζ_T), or with ``"pass"`` blends towards the deviated one."""
    from types import SimpleNamespace

    from femgear.physics.ltca.separation import path_deviation
    from femgear.system.coupling.passes import reference_loads

    p, u = baseline_pair, grid
    wear = np.array([2e-6 * ((u - p.u_pitch) / np.ptp(u)) ** 2, np.zeros(u.size)])
    zeta = np.full((2, u.size), 0.3e-6)
    worn = _cycle(coarse_model, baseline_force, extra=path_deviation(p, u, wear - zeta))
    unworn_info, worn_info = (LTCACycle.from_result(r) for r in (plain, worn))
    setup = SimpleNamespace(pair=p, kin=SimpleNamespace(u=u), ltca=unworn_info, wear_anchor="unworn", n_phase=64)
    ref_wear, ref_contact = reference_loads(setup, worn_info, wear, zeta)
    assert np.array_equal(ref_contact.load, worn.path_load(p, u, scaled=True))
    assert np.allclose(ref_contact.deviation, wear.sum(axis=0) - zeta.sum(axis=0), rtol=0, atol=1e-18)
    assert np.array_equal(ref_wear.load, plain.path_load(p, u, scaled=True)) and ref_wear.end is None
    assert np.allclose(ref_wear.deviation, zeta.sum(axis=0), rtol=0, atol=1e-18)
    setup.wear_anchor = "pass"
    blended, _ = reference_loads(setup, worn_info, wear, zeta)
    assert np.array_equal(blended.end.load, ref_contact.load) and blended.progress(wear.sum(axis=0)) == 1.0
    assert reference_loads(setup, None, wear, zeta) == (None, None)
    same, _ = reference_loads(setup, unworn_info, 0 * wear, 0 * zeta)
    assert same.end is None and np.array_equal(same.load, ref_wear.load)
    setup.n_phase = 6                        # every third of the 16 phases
    fewer, _ = reference_loads(setup, unworn_info, 0 * wear, 0 * zeta)
    assert np.array_equal(fewer.phases, plain.phase[::3]) and np.array_equal(fewer.load, same.load[:, ::3])


def test_a_loaded_point_unloads_once_the_deviation_change_reaches_its_elastic_approach(plain, baseline_pair, grid):
    """The secant update: removing the point's approach δ − ε (× 1.1) at the stiffest loaded point (the
    highest load over its approach, at the path ends) unloads it at that phase; the uniform c_l would
    keep it loaded (a peak w' > c_l (δ − ε) survives a removal of δ − ε)."""
    p, u = baseline_pair, grid
    ref = _reference(p, u, plain)
    c_l = np.full(u.size, C_L)
    stiff = ref.stiffness(c_l)
    s, i, k = np.unravel_index(np.argmax(np.where(ref.load > 0, stiff, 0.0)), stiff.shape)
    assert stiff[s, i, k] > 1.2 * C_L
    dev = np.zeros(u.size)
    dev[k] = 1.1 * ref.approach[s, i, k]
    F = np.array([plain.force_left, plain.force_right])
    assert reference_loads(p, u, F, dev, c_l, ref)[s, i, k] == 0.0
    assert reference_loads(p, u, F, dev, c_l, replace(ref, approach=None))[s, i, k] > 0.0
