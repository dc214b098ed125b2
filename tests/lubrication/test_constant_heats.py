"""``lubrication = "constant"`` heats (issue 37, item 4): Blok's flash temperature with the constant μ, and with it
the bulk flank temperature and the thermal growth, as the other levels do (on main: ΔT = 0, no growth)."""

from __future__ import annotations

import numpy as np
import pytest

from femgear.case import build_case
from femgear.levels.contact import contact_pass, reduced_modulus_of
from femgear.levels.lubrication import friction_along_path, lubrication_solver
from femgear.physics.lubrication.flash import blok_flash_temperature, thermal_effusivity
from femgear.pipeline import run_case
from femgear.scene import load_scene

MU = 0.07


def test_the_constant_level_gives_bloks_flash_temperature_with_its_mu(baseline_path):
    case = build_case(load_scene(baseline_path, ['physics.lubrication="constant"', f"friction.coefficient={MU}"]))
    w = contact_pass(case).line_load
    mu, dT = friction_along_path(case, w, lubrication_solver(case))
    k, m = case.path, case.material
    b = np.sqrt(8 * w * k.R / (np.pi * reduced_modulus_of(case)))
    B = thermal_effusivity(m.conductivity, m.density, m.specific_heat)
    expected = blok_flash_temperature(MU, w, k.vs, b, k.v1, k.v2, B, B)      # Blok (1937), ISO/TS 6336-20's form
    np.testing.assert_allclose(mu, MU, rtol=0)
    np.testing.assert_allclose(dT, expected, rtol=1e-9)
    assert dT.max() > 1.0 and lubrication_solver(case).heats
    none = build_case(load_scene(baseline_path, ['physics.lubrication="none"']))
    assert not lubrication_solver(none).heats


def test_a_coupled_constant_run_grows_thermally_with_its_heat(baseline_path):
    """One-way coupled, analytic thermal: the flank bulk rise is bulk_fraction × the mean contact rise of the
    constant μ (ISO/TS 6336-21's integral estimate), and the flanks grow with it."""
    scene = load_scene(baseline_path, ['physics.lubrication="constant"', f"friction.coefficient={MU}",
                                       'physics.coupling="one-way"', "numerics.path_points=9",
                                       "numerics.dynamics_cycles=20", "numerics.transient_cycles=10"])
    t = run_case(build_case(scene)).tribology
    assert t.temperature_rise is not None and t.temperature_rise.max() > 1.0
    assert t.flank_temperature_rise == pytest.approx(0.7 * np.mean(t.temperature_rise), rel=0.05)
    assert np.max(np.abs(t.thermal_deviation)) > 1e-8
