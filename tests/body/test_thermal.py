"""Thermo-elastic expansion: exactness (uniform ΔT), the thick disc, refinement rate."""

import math

import numpy as np
import pytest

from femgear.case import build_case
from femgear.levels import REGISTRIES
from femgear.levels import thermal as thermal_levels
from femgear.physics.body.thermal import (
    analytic_flank_deviation,
    analytic_radial_displacement,
    disk_radial_displacement,
    disk_temperature,
    fe_flank_deviation,
    flank_displacement,
    gear_thermo_elastic,
    solve_temperature,
    thermo_elastic,
)
from femgear.physics.geometry.gear import GearPair
from femgear.physics.mesh.section import annulus, gear_section
from femgear.physics.stiffness.pem import contact_geometry

LAM, E, NU = 1.16e-5, 210e9, 0.3


def _small_pair():
    return GearPair.from_parameters(z1=18, z2=25, m_n=4e-3, alpha_n=math.radians(20), beta=math.radians(15),
                                    b=0.02, x1=0.2, x2=0.0)


def _uniform_exact(basis, dT):
    ix, iy = basis.split_indices()
    ex = np.zeros(basis.N)
    ex[ix] = LAM * dT * basis.doflocs[0, ix]
    ex[iy] = LAM * dT * basis.doflocs[1, iy]
    return ex


def test_uniform_rise_free_gear_is_exact():
    """Uniform ΔT on a free (statically determinate) whole gear: u = λ ΔT r to 1e-6."""
    p = _small_pair()
    rb = 0.5 * p.rf1
    mesh = gear_section(p, 1, h=1.2e-3, n_teeth=None, bore_radius=rb)
    temp = solve_temperature(mesh, 46.0, {"flank": 60.0, "fillet": 60.0, "tip": 60.0, "bore": 60.0})
    res = thermo_elastic(mesh, temp, E, NU, LAM, support="free", bore_radius=rb)
    ex = _uniform_exact(res.basis_u, 60.0)
    assert np.max(np.abs(res.u - ex)) <= 1e-6 * np.max(np.abs(ex))


def test_uniform_rise_sector_with_rollers_is_exact():
    p = _small_pair()
    res = gear_thermo_elastic(p, 2, 35.0, 35.0, LAM, E, NU, h=p.m_n / 4)
    ex = _uniform_exact(res.basis_u, 35.0)
    assert np.max(np.abs(res.u - ex)) <= 1e-6 * np.max(np.abs(ex))
    # and the flank moves along its normal by λ ΔT ρ (ρ: roll length)
    u = np.linspace(p.u_start, p.u_end, 6)
    r, alpha, rho = contact_geometry(p, 2, u)
    np.testing.assert_allclose(flank_displacement(res, p, 2, r), LAM * 35.0 * rho, rtol=2e-3)


def test_disk_solution_limits():
    r = np.linspace(0.02, 0.06, 7)
    np.testing.assert_allclose(disk_radial_displacement(r, 0.02, 0.06, 10.0, 10.0, LAM, NU), LAM * 10 * r, rtol=1e-12)
    # outer radius grows by λ b × (area-mean temperature)
    a, b = 0.02, 0.06
    rr = np.linspace(a, b, 20001)
    Tm = np.trapezoid(disk_temperature(rr, a, b, 20, 80) * rr, rr) * 2 / (b**2 - a**2)
    assert disk_radial_displacement(b, a, b, 20, 80, LAM, NU) == pytest.approx(LAM * b * Tm, rel=1e-7)


def _disk_error(h, order):
    from skfem import Functional

    a, b = 0.02, 0.06
    mesh = annulus(a, b, h)
    temp = solve_temperature(mesh, 46.0, {"inner": 20.0, "outer": 80.0}, order=order)
    res = thermo_elastic(mesh, temp, E, NU, LAM, support="free", bore_radius=a, order=order)

    @Functional
    def err2(w):
        x, y = w.x
        r = np.hypot(x, y)
        ur = disk_radial_displacement(r, a, b, 20.0, 80.0, LAM, NU)
        return (w.u[0] - ur * x / r) ** 2 + (w.u[1] - ur * y / r) ** 2

    @Functional
    def norm2(w):
        x, y = w.x
        r = np.hypot(x, y)
        return disk_radial_displacement(r, a, b, 20.0, 80.0, LAM, NU) ** 2

    e = math.sqrt(err2.assemble(res.basis_u, u=res.basis_u.interpolate(res.u)))
    return e / math.sqrt(norm2.assemble(res.basis_u))


def test_thick_disk_converges_at_second_order():
    """Plane-stress free ring, log temperature (Timoshenko & Goodier §150): L2 error ∝ h² for P1."""
    hs = np.array([8e-3, 4e-3, 2e-3])
    errs = np.array([_disk_error(h, order=1) for h in hs])
    rate = np.polyfit(np.log(hs), np.log(errs), 1)[0]
    assert 1.8 < rate < 2.4, (errs, rate)
    assert errs[-1] < 2e-3
    assert _disk_error(2e-3, order=2) < 2e-4


def test_analytic_level_matches_fe_with_radial_gradient():
    p = _small_pair()
    u = np.linspace(p.u_start, p.u_end, 5)
    za = analytic_flank_deviation(p, 1, u, 80.0, 40.0, LAM, NU)
    zf = fe_flank_deviation(p, 1, u, 80.0, 40.0, LAM, E, NU, h=p.m_n / 4)
    # model difference (tooth not at one temperature near its root), not discretisation error
    np.testing.assert_allclose(zf, za, rtol=0.15)
    assert np.all(np.diff(za) > 0)          # grows with the roll length
    with pytest.raises(ValueError, match="physics.thermal.*unknown level 'weber'"):
        REGISTRIES["thermal"]["weber"]


def test_analytic_uniform_is_lambda_dT_rho():
    p = _small_pair()
    u = np.linspace(p.u_start, p.u_end, 5)
    r, alpha, rho = contact_geometry(p, 1, u)
    ur = analytic_radial_displacement(p, 1, r, 30.0, 30.0, LAM, NU)
    np.testing.assert_allclose(ur, LAM * 30 * r, rtol=1e-12)
    z = analytic_flank_deviation(p, 1, u, 30.0, 30.0, LAM)
    np.testing.assert_allclose(z, LAM * 30 * rho * math.cos(p.beta_b), rtol=1e-12)


def test_scene_entry_point():
    """The scene's rises, material and bore reach the ``analytic`` level's unit responses: a uniform rise (flank =
    shaft = 35 K) is a free dilatation, so the flank moves by λ ΔT ρ cos β_b along the line of action
    (the closed form of ``test_analytic_uniform_is_lambda_dT_rho``) with the baseline's λ = 1.16e-5 /K;
    a flank-only rise gives what the physics' own call with the scene's values gives."""
    from pathlib import Path

    from femgear.scene import load_scene

    path = Path(__file__).resolve().parents[2] / "studies" / "paper_baseline.toml"
    sc = load_scene(path, overrides=["thermal.flank_temperature_rise=35", "thermal.shaft_temperature_rise=35",
                                     "physics.thermal=analytic"])
    case = build_case(sc)
    p, u = case.pair, case.path.u
    _, _, rho = contact_geometry(p, 1, u)
    lam = sc.material.thermal_expansion
    assert lam == 1.16e-5
    uniform = thermal_levels.of(case).deviation(35.0, 35.0)[0]
    np.testing.assert_allclose(uniform, lam * 35 * rho * math.cos(p.beta_b), rtol=1e-12)

    z = thermal_levels.of(case).deviation(35.0, 0.0)[0]
    explicit = analytic_flank_deviation(p, 1, u, 35.0, 0.0, lam, sc.material.poisson_ratio, sc.pinion.bore_radius)
    np.testing.assert_allclose(z, explicit, rtol=1e-12)
    assert np.all(z < lam * 35 * rho * math.cos(p.beta_b))     # a cool shaft holds the flank back
