"""Longer TEHL checks (``make test-slow``): thermal film reduction over SRR against Gupta
et al. (1992), and a grid check of the thermal figures."""

import importlib.util
from pathlib import Path

import pytest

from femgear.friction.traction import gupta_thermal_factor
from femgear.tehl import solve_tehl_line

_spec = importlib.util.spec_from_file_location("_case", Path(__file__).with_name("_case.py"))
case = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(case)

pytestmark = pytest.mark.slow


def _phi(ue, srr, level=4):
    r = solve_tehl_line(case.W, case.R, ue, srr, case.T0, case.OIL, case.E_RED, case.PROPS, tau0=case.TAU0,
                        level=level)
    g = float(gupta_thermal_factor(r.ph, case.E_RED, srr, ue, case.OIL.viscosity(0.0, case.T0), case.OIL.beta_t,
                                   case.PROPS.k_oil))
    return r.hc / r.hc_isothermal, g


def test_film_reduction_over_srr_against_gupta():
    """Measured (u_e = 10 m/s): φ 0.759/0.757/0.725/0.617 at SRR 0/0.25/0.5/1 vs Gupta
    0.698/0.586/0.521/0.435: same direction, femgear's reduction by sliding is weaker.
    Not from the mean-temperature Reynolds: the Yang & Wen (1990) cross-film factors on the
    inlet (x < −b) raised φ to 0.799/0.759/0.665 at SRR 0/0.5/1 (cold walls carry less
    back-flow); nor from Eyring (Newtonian: 0.759/0.719/0.612).  The [−4.5 b, 1.5 b] inlet
    starves the isothermal film by 12 % at 10 m/s; from −8 b φ is 0.721/0.715/0.564 at SRR
    0/0.25/1 (studies/tehl_gupta.py), still +22/+30 % over Gupta with sliding."""
    rows = [(s, *_phi(10.0, s)) for s in (0.0, 0.25, 0.5, 1.0)]
    for s, phi, g in rows:
        print(f"SRR {s:4.2f}: phi {phi:.3f}  Gupta {g:.3f}")
    phis = [r[1] for r in rows]
    assert phis[-1] < phis[0] - 0.05                      # sliding reduces the film further
    assert abs(rows[0][1] / rows[0][2] - 1) < 0.1                  # rolling: within 10 %
    assert all(abs(phi / g - 1) < 0.45 for _, phi, g in rows)        # measured: up to +42 % at SRR 1


def test_thermal_figures_grid_converged():
    """Level 5/192 cells vs level 6/384 cells x 12 layers (measured: μ 0.0317 both, h_c equal,
    max ΔT 15.6 → 18.7 K: the peak sits on the pressure spike and converges slowly, as p_max)."""
    a = solve_tehl_line(case.W, case.R, case.UE, 0.5, case.T0, case.OIL, case.E_RED, case.PROPS, tau0=case.TAU0,
                        level=5, cells=192)
    b = solve_tehl_line(case.W, case.R, case.UE, 0.5, case.T0, case.OIL, case.E_RED, case.PROPS, tau0=case.TAU0,
                        level=6, cells=384, nz=12)
    assert b.mu == pytest.approx(a.mu, rel=0.03)
    assert b.dT_max == pytest.approx(a.dT_max, rel=0.25)
    assert b.hc == pytest.approx(a.hc, rel=0.01)
