"""Longer TEHL checks (``make test-slow``): thermal film reduction over SRR against Gupta
et al. (1992), and a grid check of the thermal figures."""

import importlib.util
import math
from pathlib import Path

import pytest

from femgear.physics.lubrication.traction import gupta_thermal_factor
from femgear.physics.tehl import solve_tehl_line

_spec = importlib.util.spec_from_file_location("_case", Path(__file__).with_name("_case.py"))
case = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(case)

pytestmark = pytest.mark.slow


def _phi(ph, ue, srr):
    """φ = h_c/h_c,iso from the long inlet [−8 b, 1.5 b] (level 5, 256 thermal cells: the
    isothermal film within 1.5 % of its −24 b value here) and Gupta's factor with S = SRR."""
    w = 2.0 * math.pi * case.R * ph**2 / case.E_RED
    r = solve_tehl_line(w, case.R, ue, srr, case.T0, case.OIL, case.E_RED, case.PROPS, tau0=case.TAU0,
                        level=5, cells=256, x0=-8.0)
    g = float(gupta_thermal_factor(ph, case.E_RED, srr, ue, case.OIL.viscosity(0.0, case.T0), case.OIL.beta_t,
                                   case.PROPS.k_oil))
    return r.hc / r.hc_isothermal, g


def test_film_reduction_over_srr_against_gupta():
    """φ vs Gupta (studies/ehl/tehl_gupta.py, p_h 0.5–1.5 GPa, u_e 5–10 m/s, Eyring and Newtonian).
    Rolling agrees everywhere within 3.5 % (inlet −8 b: 1.034/1.017 at 0.5 GPa and 10/5 m/s,
    0.972/1.002 at 1 GPa, 0.990/1.015 at 1.5 GPa).  Sliding reduces femgear's film about half
    as much as the fit with S = SRR = (v1 − v2)/u_e: at 0.5 GPa, 10 m/s φ = 0.722/0.669/0.566
    at SRR 0/0.5/1 vs Gupta 0.698/0.521/0.435 (φ/G 1.03/1.28/1.30); at 1 and 1.5 GPa, 5 m/s
    φ/G is 1.19–1.28 at SRR 0.5–1 and at 1–1.5 GPa, 10 m/s 1.31–1.45, so the gap is not a
    load-range effect; Newtonian shear changes φ by < 0.01.  With S = SRR/2 (slide-to-sum speed) φ/G is
    1.03/1.14/1.08 (0.5 GPa, 10 m/s), 1.02/1.10/1.09 (5 m/s), 1.11–1.15 at 1–1.5 GPa and 5 m/s,
    1.16 at 1 GPa, 10 m/s, SRR 0.5: closer, but no tested range is within 10 % over SRR 0…1
    in either convention (which one Gupta used is not verified here).  Part of the
    difference is the thermal expansion of the hot Hertz-zone oil (ρh constant: at 1 GPa,
    5 m/s φ(SRR 0.5)/φ(0) is 1.02, and 0.97 with ε = 0), absent from an inlet-only fit."""
    rows = [(s, *_phi(0.5e9, 10.0, s)) for s in (0.0, 0.5, 1.0)]
    for s, phi, g in rows:
        print(f"SRR {s:4.2f}: phi {phi:.3f}  Gupta {g:.3f}")
    phis = [r[1] for r in rows]
    assert phis[2] < phis[1] < phis[0] - 0.03                         # sliding reduces the film further
    assert abs(rows[0][1] / rows[0][2] - 1) < 0.05                    # rolling: within 5 % of Gupta
    phi, g = _phi(1.0e9, 10.0, 0.0)
    assert abs(phi / g - 1) < 0.05                                    # rolling at 1 GPa (measured −2.8 %)


def test_regression_sliding_film_reduction_gap_to_gupta():
    """Regression, not a validation: femgear's film with sliding stays 15–40 % above Gupta's fit
    (measured +28/+30 % at SRR 0.5/1, 0.5 GPa, 10 m/s; see the test above for the reading).
    A change of the thermal model that moves this gap shows here."""
    for s in (0.5, 1.0):
        phi, g = _phi(0.5e9, 10.0, s)
        assert 1.15 < phi / g < 1.40


def test_thermal_figures_grid_converged():
    """Level 5/192 cells vs level 6/384 cells x 12 layers: μ within 3 % and h_c within 1 % (the
    figures the coupling uses; measured: μ 0.0317 both, h_c equal).  The peak film temperature
    sits on the pressure spike and converges slowly, as p_max (15.6 → 18.7 K): it is checked
    only to grow with the grid by less than a quarter, a regression band, not a convergence."""
    a = solve_tehl_line(case.W, case.R, case.UE, 0.5, case.T0, case.OIL, case.E_RED, case.PROPS, tau0=case.TAU0,
                        level=5, cells=192)
    b = solve_tehl_line(case.W, case.R, case.UE, 0.5, case.T0, case.OIL, case.E_RED, case.PROPS, tau0=case.TAU0,
                        level=6, cells=384, nz=12)
    assert b.mu == pytest.approx(a.mu, rel=0.03)
    assert b.dT_max == pytest.approx(a.dT_max, rel=0.25)
    assert b.hc == pytest.approx(a.hc, rel=0.01)
