"""Point-contact TEHL (strip-wise energy): exact isothermal recovery and energy balance at
the seed paper's benchmark condition (500 N, 10 m/s, 80 °C; R = 20 mm assumed)."""

import importlib.util
from pathlib import Path

import numpy as np

from femgear.physics.ehl.dimensional import solve_point_dimensional
from femgear.physics.tehl.line import ehl_oil_at
from femgear.physics.tehl.point import solve_tehl_point

_spec = importlib.util.spec_from_file_location("_case", Path(__file__).with_name("_case.py"))
case = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(case)

F, RP, UEP, TP = 500.0, 0.02, 10.0, 353.0


def test_point_heat_off_exact_and_heat_on_balanced():
    off = solve_tehl_point(F, RP, UEP, 0.3, TP, case.OIL, case.E_RED, case.PROPS, tau0=case.TAU0, level=1,
                           heat=False)
    iso = solve_point_dimensional(F, RP, None, UEP, case.E_RED, ehl_oil_at(case.OIL, TP), level=1,
                                  dense_reuse=True)         # the TEHL start's settings (its LU factors reused)
    assert np.array_equal(off.p, iso.p) and np.array_equal(off.h, iso.h) and off.dT_max == 0.0
    on = solve_tehl_point(F, RP, UEP, 0.3, TP, case.OIL, case.E_RED, case.PROPS, tau0=case.TAU0, level=1)
    assert abs(on.heat["balance_error"]) < 0.01 and on.heat["convected"] > 0
    assert on.hc < on.hc_isothermal and 5.0 < on.dT_max < 300.0 and 0.005 < on.mu < 0.1
