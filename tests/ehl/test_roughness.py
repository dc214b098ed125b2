"""Roughness as a film term of the stationary EHL solvers, and the surface generator.

Validation: a stationary harmonic roughness in the Hertzian zone is flattened (the film is
steady and its flux rho H constant where eps -> 0), so the pressure ripple is the one that
flattens a wavy half-space, Johnson (Contact Mechanics 1985, sec. 13.2, eq. 13.3):
p* = pi E* A / lambda with E* = E'/2; in Hertzian units P* = k A (line, X = x/b) and
P* = (pi/4) k A (point, X = x/a), k = 2 pi / lambda.
"""

from __future__ import annotations

from functools import partial

import numpy as np
import pytest

from femgear.errors import ArgumentError, SceneError
from femgear.physics.ehl.core.surface import (
    correlation_length,
    harmonic,
    hertz_height,
    paper_peak,
    random_surface,
    surface_speed,
)
from femgear.physics.ehl.fe.line import solve_line
from femgear.physics.ehl.point import solve_point


def _ripple(x, dP, lam, half=0.5):
    """Least-squares amplitude of cos/sin(2 pi x/lam) in dP on |x| < half."""
    m = np.abs(x) < half
    k = 2 * np.pi / lam
    B = np.column_stack([np.cos(k * x[m]), np.sin(k * x[m]), np.ones(m.sum())])
    c = np.linalg.lstsq(B, dP[m], rcond=None)[0]
    return float(np.hypot(c[0], c[1]))


@pytest.fixture(scope="module")
def smooth_line():
    return solve_line(20.0, 10.0, level=6)


def test_smooth_limit_is_bit_identical(smooth_line):
    """A_b = 0 (and surface=None) leaves the line solution bit-identical and the point
    contact's discrete problem (its gap on every level) bit-identical. Two point solves are
    compared to 1e-9 only: its Newton-Krylov rebuilds the preconditioner on measured
    timings, so even two smooth solves differ in the last digits."""
    from femgear.physics.ehl.core.domain import default_domain
    from femgear.physics.ehl.core.grid import Grid
    from femgear.physics.ehl.core.rheology import Rheology
    from femgear.physics.ehl.core.surface import apply_surface, evaluate
    from femgear.physics.ehl.fe.level import Level

    r = solve_line(20.0, 10.0, level=6, surface=partial(paper_peak, amplitude=0.0, half_width=0.1))
    assert np.array_equal(r.P, smooth_line.P) and np.array_equal(r.H, smooth_line.H)
    lv = Level(Rheology(1.0), 1.0, 1.0, grid=Grid.build(default_domain(), 2))
    G = lv.geometry.copy()
    apply_surface(lv, evaluate(partial(paper_peak, amplitude=0.0, half_width=0.1), lv.X, lv.Y))
    assert np.array_equal(lv.geometry, G)
    p0 = solve_point(20.0, 10.0, level=2)
    p1 = solve_point(20.0, 10.0, level=2, surface=partial(paper_peak, amplitude=0.0, half_width=0.1))
    assert np.max(np.abs(p0.P - p1.P)) < 1e-9 and np.max(np.abs(p0.H - p1.H)) < 1e-9


def test_line_pressure_ripple_is_johnsons(smooth_line):
    """Stationary waviness lambda = 0.25 b, A = 0.005 (5 % of H_c): P* = k A within 2 %, and
    the film in the Hertzian zone keeps < 5 % of the roughness."""
    lam, A = 0.25, 0.005
    r = solve_line(20.0, 10.0, level=6, surface=partial(harmonic, amplitude=A, wavelength=lam))
    assert r.load_error < 1e-6
    assert _ripple(r.x, r.P - smooth_line.P, lam) == pytest.approx(2 * np.pi / lam * A, rel=0.02)
    assert _ripple(r.x, r.H - smooth_line.H, lam) < 0.05 * A


def test_point_pressure_ripple_is_johnsons():
    """Point contact, transverse waviness lambda = 0.5 a, A = 0.003 on 129^2: the centre-line
    ripple is (pi/4) k A within 3 %."""
    lam, A = 0.5, 0.003
    r0 = solve_point(20.0, 10.0, level=3, method="newton")  # the rough solve is Newton's
    r = solve_point(20.0, 10.0, level=3, surface=partial(harmonic, amplitude=A, wavelength=lam))
    j = int(np.argmin(np.abs(r.y)))
    assert _ripple(r.x, r.P[j] - r0.P[j], lam) == pytest.approx(np.pi / 4 * 2 * np.pi / lam * A, rel=0.03)


@pytest.mark.slow
def test_paper_peak_flattened_in_contact_followed_in_inlet(smooth_line):
    """The paper's peak (eq. 22): inside the Hertzian zone the film stays flat and the pressure
    rises under the peak; in the inlet (X = -3, no pressure) the film follows the roughness."""
    A = 0.03  # 30 % of the smooth central film
    r = solve_line(20.0, 10.0, level=6, surface=partial(paper_peak, amplitude=A, half_width=0.1, x0=-0.3))
    dH, dP = r.H - smooth_line.H, r.P - smooth_line.P
    near = np.abs(r.x + 0.3) <= 0.1
    assert np.ptp(dH[near]) < 0.15 * A
    assert abs(r.x[np.argmax(dP)] + 0.3) < 0.02 and dP.max() > 0.5 * (np.pi / 0.1) * A / 2
    s = solve_line(20.0, 10.0, level=6, surface=partial(paper_peak, amplitude=A, half_width=0.1, x0=-3.0))
    dH = s.H - smooth_line.H
    inlet = np.abs(s.x + 3.0) <= 0.3
    R = paper_peak(s.x[inlet], amplitude=A, half_width=0.1, x0=-3.0)
    shift = np.median(dH[np.abs(s.x + 3.5) < 0.1])  # the change of H0 + D there
    assert np.max(np.abs(dH[inlet] - shift + R)) < 0.05 * A


def test_paper_peak_shape():
    """Eq. 22: A_b at x0, A_b/2 at x0 +- l_b/2, 0 at and beyond +- l_b."""
    x = np.array([0.2, 0.25, 0.3, 0.35, 0.4, 0.5])
    R = paper_peak(x, amplitude=2.0, half_width=0.1, x0=0.3)
    assert R == pytest.approx([0.0, 1.0, 2.0, 1.0, 0.0, 0.0], abs=1e-12)
    with pytest.raises(ArgumentError, match="half_width"):
        paper_peak(x, amplitude=1.0, half_width=0.0)


def test_surface_speed_and_units():
    assert surface_speed(0.0, "pinion") == 1.0
    assert surface_speed(0.5, "pinion") == 1.25 and surface_speed(0.5, "gear") == 0.75
    with pytest.raises(ArgumentError, match="member"):
        surface_speed(0.5, "wheel")
    # 0.1 um on R = 20 mm, b = 200 um: H = h R / b^2 = 0.05
    assert hertz_height(0.1e-6, 0.02, 200e-6) == pytest.approx(0.05)


@pytest.mark.parametrize("acf", ["exponential", "gaussian"])
def test_random_surface_statistics(acf):
    """Rq within 5 % and the correlation length (ACF = 1/e) within 10 % of the targets:
    1-D, 2^16 nodes, beta = 20 h; 2-D, 512^2, beta = 8 h (isotropic: both axes)."""
    z = random_surface(1 << 16, 1e-6, rq=0.2e-6, corr_length=20e-6, acf=acf, seed=3)
    assert z.std() == pytest.approx(0.2e-6, rel=0.05)
    assert correlation_length(z, 1e-6) == pytest.approx(20e-6, rel=0.10)
    z2 = random_surface((512, 512), 1.0, rq=1.0, corr_length=8.0, acf=acf, seed=5)
    assert z2.std() == pytest.approx(1.0, rel=0.05)
    for axis in (0, 1):
        assert correlation_length(z2, 1.0, axis=axis) == pytest.approx(8.0, rel=0.10)
    assert np.array_equal(z, random_surface(1 << 16, 1e-6, rq=0.2e-6, corr_length=20e-6, acf=acf, seed=3))
    assert not np.array_equal(z, random_surface(1 << 16, 1e-6, rq=0.2e-6, corr_length=20e-6, acf=acf, seed=4))


def test_random_surface_bad_input():
    with pytest.raises(ArgumentError, match="corr_length"):
        random_surface(64, 1.0, rq=1.0, corr_length=0.0)
    with pytest.raises(ArgumentError, match="acf"):
        random_surface(64, 1.0, rq=1.0, corr_length=2.0, acf="fractal")


def test_surface_array_must_match_grid():
    with pytest.raises(ArgumentError, match="surface"):
        solve_line(20.0, 10.0, level=4, surface=np.zeros(7))


def _scene(*overrides):
    from pathlib import Path

    from femgear.scene.load import read_toml, scene_from_dict

    base = Path(__file__).resolve().parents[2] / "studies" / "paper_baseline.toml"
    return scene_from_dict(read_toml(base), list(overrides), warn=False)


def test_scene_roughness_tables():
    s = _scene()
    assert (s.roughness.rq, s.roughness.peak, s.roughness.synthetic) == (None, None, None)   # rq: per member, unset
    s = _scene("roughness.peak.amplitude=0.2e-6", "roughness.peak.wavelength=20e-6", "roughness.peak.x0=-1e-4",
               "roughness.synthetic.rq=0.1e-6", "roughness.synthetic.correlation_length=15e-6",
               "roughness.synthetic.seed=7")
    p, y = s.roughness.peak, s.roughness.synthetic
    assert (p.amplitude, p.wavelength, p.x0, p.member, p.moving) == (0.2e-6, 20e-6, -1e-4, "pinion", False)
    assert (y.rq, y.correlation_length, y.acf, y.seed) == (0.1e-6, 15e-6, "exponential", 7)


@pytest.mark.parametrize("overrides, key", [
    (("roughness.peak.amplitude=0.2e-6",), "roughness.peak.wavelength"),
    (("roughness.peak.amplitude=-1e-7", "roughness.peak.wavelength=1e-5"), "roughness.peak.amplitude"),
    (("roughness.peak.amplitude=1e-7", "roughness.peak.wavelength=1e-5", "roughness.peak.member='wheel'"),
     "roughness.peak.member"),
    (("roughness.synthetic.rq=1e-7",), "roughness.synthetic.correlation_length"),
    (("roughness.synthetic.rq=1e-7", "roughness.synthetic.correlation_length=1e-5", "roughness.synthetic.acf='pink'"),
     "roughness.synthetic.acf"),
])
def test_scene_roughness_errors_name_the_key(overrides, key):
    with pytest.raises(SceneError, match=key.replace(".", r"\.")):
        _scene(*overrides)


def test_scene_features_in_hertzian_units():
    """[roughness.peak] in metres -> Hertzian profile: A_b R / b^2 at x0/b, zero beyond l_b;
    [roughness.synthetic] -> heights with Rq R / b^2 (within 10 % on a long sample)."""
    from femgear.physics.ehl.core.surface import peak_feature, synthetic_feature

    s = _scene("roughness.peak.amplitude=0.2e-6", "roughness.peak.wavelength=20e-6", "roughness.peak.x0=-1e-4",
               "roughness.synthetic.rq=0.1e-6", "roughness.synthetic.correlation_length=5e-6")
    R, b = 0.02, 200e-6
    f = peak_feature(s.roughness.peak, R, b)
    assert f(np.array([-0.5, -0.5 + 0.1, 0.0])) == pytest.approx([0.2e-6 * R / b**2, 0.0, 0.0])
    g = synthetic_feature(s.roughness.synthetic, R, b, extent=(-50.0, 50.0), h=0.005)
    z = g(np.linspace(-50, 50, 20001))
    assert z.std() == pytest.approx(0.1e-6 * R / b**2, rel=0.10)
    from femgear.physics.ehl.core.surface import scene_features

    feats = scene_features(s.roughness, R, b, extent=(-50.0, 50.0), h=0.005)
    assert [(m, mv) for _, m, mv in feats] == [("pinion", False), ("pinion", True)]
    assert scene_features(_scene().roughness, R, b, extent=(-5.0, 2.0), h=0.01) == []
