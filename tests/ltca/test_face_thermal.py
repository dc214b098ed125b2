"""Face-resolved thermal growth in the LTCA re-run (``thermal = "fe3d"`` with ``wear.field = "face"``).

The 3-D unit solutions (:mod:`femgear.physics.ltca.thermal`) vary over the face: a flank rise grows the
flank less at the free outer end (ζ = 0) and more at the apex (ζ = b) than mid-face (README: −11 %,
+5 % at body level 2).  With the face-resolved wear field the coupling re-runs the LTCA on
wear − ζ_T(member, helix, u, ζ) instead of a face-uniform ζ_T(u).
"""

from types import SimpleNamespace

import numpy as np
import pytest

from femgear.physics.geometry import path_positions
from femgear.physics.ltca.flank import roll_range
from femgear.physics.ltca.thermal import Thermal3DUnits
from femgear.physics.wear.face import face_mean
from femgear.system.coupling.passes import pass_thermal, removed_deviation
from femgear.system.coupling.thermal import ThermalUnits, roll_distances

N_ZETA = 21


def _synthetic(pair, member, n_z):
    """Unit solutions whose ζ variation is not linear (a cosine over the face), on n_z points."""
    r0, r1 = roll_range(pair, member)
    rho, zeta = np.linspace(r0, r1, 7), np.linspace(0.0, pair.b, n_z)
    shape = 1.0 + 0.1 * np.cos(np.pi * zeta / pair.b)[None, :]
    flank = 1e-6 * np.stack([rho[:, None] * shape, rho[:, None] * shape[:, ::-1]])
    return Thermal3DUnits(member, rho, zeta, flank, 0.3 * flank)


def test_face_field_mean_is_the_face_uniform_deviation(baseline_pair):
    """Its face mean over both helices is :meth:`ThermalUnits.deviation` (what the loop's ζ_T(u) is): exact when
    the units' ζ nodes are nodes of the face grid (5 units' points in 21), within the interpolation of a
    9-point units' grid on the 21-point grid otherwise (a few 1e-4 of the value for this cosine)."""
    p = baseline_pair
    u = path_positions(p, 31)
    rho, grid = roll_distances(p, u), np.linspace(0.0, p.b, N_ZETA)
    for n_z, rtol in ((5, 1e-12), (9, 2e-3)):
        units = ThermalUnits.from_bodies((_synthetic(p, 1, n_z), _synthetic(p, 2, n_z)), rho)
        face = units.face(rho, grid, 30.0, 10.0)
        assert face.shape == (2, 2, u.size, N_ZETA)
        mean = np.array([face_mean(face[j], grid).mean(axis=0) for j in (0, 1)])
        np.testing.assert_allclose(mean, units.deviation(30.0, 10.0), rtol=rtol)
        assert np.ptp(face[0, 0], axis=1).min() > 0.05 * face[0, 0].min()    # it does vary over the face
    assert ThermalUnits(flank=units.flank, shaft=units.shaft).face(rho, grid, 30.0, 10.0) is None


@pytest.fixture(scope="module")
def units_3d(baseline_scene, baseline_pair, grid):
    """Baseline pinion and gear at body level 0 on a 7 × 5 grid (≈ 10 s, not cached)."""
    from femgear.physics.ltca.thermal import thermal_units_3d

    m = baseline_scene.material
    bodies = tuple(thermal_units_3d(baseline_pair, j, m.thermal_expansion, m.youngs_modulus, m.poisson_ratio,
                                    level=0, n_rho=7, n_z=5, cache=False) for j in (1, 2))
    return ThermalUnits.from_bodies(bodies, roll_distances(baseline_pair, grid))


@pytest.fixture(scope="module")
def grid(baseline_pair):
    return path_positions(baseline_pair, 41)


def _load_centre(res) -> float:
    """Load-weighted mean face coordinate ζ of all contact points of the cycle, over both helices [m]."""
    w = np.concatenate([a[:, 4] for a in res.line_load])
    z = np.concatenate([a[:, 3] for a in res.line_load])
    return float(np.sum(w * z) / np.sum(w))


@pytest.mark.slow
def test_face_resolved_growth_loads_the_apex_more(units_3d, coarse_model, baseline_force, baseline_pair, grid):
    """ΔT_f = 30 K, no wear, the loop's own ``_thermal`` and ``_removed_deviation`` (≈ 25 s).

    Expected from the 3-D figures: ζ_T grows from the free outer end (ζ = 0) to the apex (ζ = b), so the
    face-resolved −ζ_T closes the gap at the apex more than the face-uniform one of the same mean: the load
    moves towards ζ = b on both helices.  The field is first checked to have that shape (apex above the
    outer end by > 5 %), then the load centre of the re-run LTCA cycle to lie nearer the apex than with the
    face-uniform growth (measured: apex/outer end 1.13 mid-path; load centre 0.525 b → 0.553 b)."""
    from femgear.physics.ltca.analysis import mesh_cycle

    p = baseline_pair
    face_grid = SimpleNamespace(grid=np.linspace(0.0, p.b, N_ZETA))
    case = SimpleNamespace(thermal=SimpleNamespace(flank_temperature_rise=30.0, shaft_temperature_rise=0.0,
                                                   bulk_fraction=0.7))
    setup = SimpleNamespace(pair=p, kin=SimpleNamespace(u=grid), face=face_grid, thermal=units_3d, case=case)
    rise, zeta, zeta_face = pass_thermal(setup, np.zeros(grid.size))
    assert rise == 30.0 and zeta_face.shape == (2, 2, grid.size, N_ZETA)
    inner = slice(grid.size // 4, 3 * grid.size // 4)
    assert np.all(zeta_face[:, :, inner, -1] > 1.05 * zeta_face[:, :, inner, 0])    # apex above the outer end
    mean = np.array([face_mean(zeta_face[j], face_grid.grid).mean(axis=0) for j in (0, 1)])
    np.testing.assert_allclose(mean, zeta, rtol=1e-3)
    wear, wear_face = np.zeros((2, grid.size)), np.zeros((2, 2, grid.size, N_ZETA))
    centre = {}
    for name, field in (("face", zeta_face), ("uniform", None)):
        dev = removed_deviation(setup, wear, zeta, wear_face, field)
        res = mesh_cycle(coarse_model, baseline_force, None, n_phases=8, stagger=0.0, n_line=8, extra=dev,
                         keep_lines=True)
        centre[name] = _load_centre(res)
    assert centre["face"] > centre["uniform"] + 0.005 * p.b, centre
