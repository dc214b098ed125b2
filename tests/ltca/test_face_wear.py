"""Face-resolved Archard wear from the LTCA's contact-line loads (:mod:`femgear.physics.wear.face`).

Validation against the face-uniform path model (same loads, same Archard form), against the LTCA's
own point loads (independent of the path grid and of the face interpolation) and against Archard's
volume law V = (K/H) ∫ Σ w' |v_s| dℓ dt over one mesh cycle.  Coarse LTCA model (tests/ltca/conftest).
"""

import math
from dataclasses import replace

import numpy as np
import pytest

from femgear.case import build_case
from femgear.levels.wear import static_setup
from femgear.physics.geometry import kinematics, path_positions
from femgear.physics.ltca.cycle import LTCACycle
from femgear.physics.wear import WearState, run_wear, wear_rates
from femgear.physics.wear.face import (
    FaceReference,
    FaceWearState,
    along_lines,
    archard_volume,
    face_mean,
    face_rates,
    flank_volume,
    run_face_wear,
)

N_ZETA = 21


@pytest.fixture(scope="module")
def grid(baseline_pair):
    return path_positions(baseline_pair, 61)


@pytest.fixture(scope="module")
def base(baseline_scene, baseline_pair, grid):
    return static_setup(build_case(baseline_scene), kinematics(baseline_pair, grid, 500 * 2 * math.pi / 60))


def _analysis(model, force, pair, u, mods=None):
    """(LTCA cycle, FaceReference) of a coarse cycle: 32 phases, 8 points per line."""
    from femgear.physics.ltca.analysis import mesh_cycle
    from femgear.system.coupling.setup import ltca_face_reference

    res = mesh_cycle(model, force, mods, n_phases=32, stagger=0.0, n_line=8)
    return res, ltca_face_reference(pair, u, LTCACycle.from_result(res, model, mods), np.zeros(u.size), n_zeta=N_ZETA)


def _mods(**kw):
    from femgear.scene.schema import FlankModification, Modifications

    pinion = {k: v for k, v in kw.items() if not k.startswith("helix")}
    return Modifications(pinion=FlankModification(**pinion), gear=FlankModification(),
                         **{k: v for k, v in kw.items() if k.startswith("helix")})


@pytest.fixture(scope="module")
def plain(coarse_model, baseline_force, baseline_pair, grid):
    return _analysis(coarse_model, baseline_force, baseline_pair, grid)


def _own_forces(setup, res, face):
    """The setup with the LTCA's own helix forces and its reference (the loads are then the LTCA's)."""
    return replace(setup, force=np.array([res.force_left, res.force_right]), reference=face.ref)


def _archard(setup, res, helix=None):
    sel = [np.ones(a.shape[0], bool) if helix is None else a[:, 0] == helix for a in res.line_load]
    return archard_volume(setup, [a[m, 2] for a, m in zip(res.line_load, sel)],
                          [a[m, 4] for a, m in zip(res.line_load, sel)], [dl[m] for dl, m in zip(res.line_length, sel)])


def test_unmodified_face_mean_equals_the_path_wear_and_the_face_is_nearly_uniform(plain, base, grid):
    """(a) Symmetric unmodified pair: the face mean of the face-resolved rate equals the path model's rate
    (they integrate the same loads): measured within 0.6 % inside the path (|u − ū| < 0.4 g_α), 6.7 % at
    the path ends (a load peak at the line ends, 32 phases against a 21-point face grid); both helices
    alike; over the inner 60 % of the face the depth varies by std/mean 0.3–11 % at interior u (regression
    band 0.15).  After 1e6 and 3e6 cycles (same stepping rule) the face mean is within 0.9 % / 0.5 % of
    the path depth inside the path (1.3 % / 0.5 % everywhere; band 2 %); since the path model shares the load
    with the exact line quadrature (:func:`femgear.physics.geometry.lines.line_weights`, which also loads the grid node
    just beyond each line end) the gear's face mean is 2.0 % off at 1e6 cycles (band 2.5 %)."""
    res, face = plain
    setup = replace(base, reference=face.ref)
    r1, r2, _ = face_rates(setup, face, FaceWearState.zero(grid.size, N_ZETA))
    p1, p2, _ = wear_rates(setup, WearState.zero(grid.size))
    inner = np.abs(grid - grid.mean()) < 0.4 * np.ptp(grid)
    for r, p in ((r1, p1), (r2, p2)):
        mean = face_mean(r, face.grid)
        assert np.allclose(mean[0], mean[1], rtol=1e-12)
        assert np.max(np.abs(mean[0][inner] / p[inner] - 1)) < 0.01
        assert np.max(np.abs(mean[0] / p - 1)) < 0.1
    z = face.grid
    mid = (z > 0.2 * z[-1]) & (z < 0.8 * z[-1])
    band = r1[0][inner][:, mid]
    assert np.max(band.std(axis=1) / band.mean(axis=1)) < 0.15
    for cycles in (1e6, 3e6):
        path = run_wear(setup, cycles)
        worn = run_face_wear(setup, face, cycles)
        h = worn.path_mean(face.grid)
        top = path.h1.max()
        assert np.max(np.abs(h[0][inner] - path.h1[inner])) < 0.02 * top
        assert np.max(np.abs(h[1][inner] - path.h2[inner])) < 0.025 * path.h2.max()


def _band_ratio(res, u, b, lo, hi, helix=None):
    """Mean LTCA point load w' over interior u (|u − ū| < 0.35 g_α) in the face bands ζ/b ∈ [lo, hi]."""
    out = []
    for a in res.line_load:
        m = np.abs(a[:, 2] - u.mean()) < 0.35 * np.ptp(u)
        if helix is not None:
            m &= a[:, 0] == helix
        sel = np.zeros(a.shape[0], bool)
        for x0, x1 in zip(lo, hi):
            sel |= (a[:, 3] >= x0 * b) & (a[:, 3] <= x1 * b)
        out.append(a[m & sel, 4])
    return float(np.concatenate(out).mean())


def test_lead_crowning_wears_the_mid_face_more_like_its_load(coarse_model, baseline_force, baseline_pair, grid, base):
    """(b) 2 µm pinion crowning: the mid-face (ζ/b ∈ [0.4, 0.6]) wears more than the quarter bands
    ([0.15, 0.35] ∪ [0.65, 0.85]) by the ratio of the LTCA's own point loads in those bands (measured
    1.190 against 1.198; tolerance 3 %), and the face ends wear about half of the middle (0.51); the
    path model wears every face position alike."""
    mods = _mods(crowning=2e-6)
    res, face = _analysis(coarse_model, baseline_force, baseline_pair, grid, mods)
    r1, _, _ = face_rates(replace(base, reference=face.ref), face, FaceWearState.zero(grid.size, N_ZETA))
    z = face.grid / face.grid[-1]
    cols = np.abs(grid - grid.mean()) < 0.35 * np.ptp(grid)
    mid = (z >= 0.4) & (z <= 0.6)
    quarter = ((z >= 0.15) & (z <= 0.35)) | ((z >= 0.65) & (z <= 0.85))
    depth_ratio = r1[:, cols][:, :, mid].mean() / r1[:, cols][:, :, quarter].mean()
    b = baseline_pair.b
    load_ratio = _band_ratio(res, grid, b, (0.4,), (0.6,)) / _band_ratio(res, grid, b, (0.15, 0.65), (0.35, 0.85))
    assert depth_ratio > 1.1
    assert depth_ratio == pytest.approx(load_ratio, rel=0.03)
    assert r1[:, cols][:, :, [0, -1]].mean() < 0.7 * r1[:, cols][:, :, mid].mean()


def test_a_helix_slope_deviation_on_one_helix_shifts_the_wear_to_the_other(coarse_model, baseline_force,
                                                                           baseline_pair, grid, base):
    """(c) f_Hβ = 10 µm on the left helix: the left helix carries 1224 N, the right 3353 N; the worn volume
    of each helix follows its Archard integral from the LTCA points (measured +1.4 % / +0.7 %; 2 %) and so
    the load shift: V_right / V_left ≈ F_right / F_left (measured 2.87 against 2.74; 10 %).  The path model
    wears both helices alike."""
    mods = _mods(helix_slope_deviation_left=10e-6)
    res, face = _analysis(coarse_model, baseline_force, baseline_pair, grid, mods)
    setup = _own_forces(base, res, face)
    r1, _, _ = face_rates(setup, face, FaceWearState.zero(grid.size, N_ZETA))
    v = [flank_volume(setup, r1[s:s + 1], face.grid, 1) for s in (0, 1)]
    for s in (0, 1):
        assert v[s] == pytest.approx(_archard(setup, res, s), rel=0.02)
    shift = res.force_right.mean() / res.force_left.mean()
    assert shift > 2
    assert v[1] / v[0] == pytest.approx(shift, rel=0.1)


@pytest.mark.parametrize("crowning", [0.0, 5e-6])
def test_the_face_wear_volume_is_archards(coarse_model, baseline_force, baseline_pair, grid, base, plain, crowning):
    """(d) Volume per pass of each member's flank = (K/H) ∫ Σ w' |v_s| dℓ dt of the LTCA points over one mesh
    cycle (measured +0.7 % / +0.85 % unmodified / 5 µm crowning: the path grid's quadrature; tolerance 2 %).
    The path model (the same grid) conserves it for the unmodified flanks (+0.8 %) but not with the crowning
    (+6.1 %: its passage mean leaves the open face ends out, the face-resolved field counts them as 0)."""
    res, face = plain if crowning == 0 else _analysis(coarse_model, baseline_force, baseline_pair, grid,
                                                      _mods(crowning=crowning))
    setup = _own_forces(base, res, face)
    r1, r2, _ = face_rates(setup, face, FaceWearState.zero(grid.size, N_ZETA))
    archard = _archard(setup, res)
    p = setup.pair
    assert flank_volume(setup, r1, face.grid, 1) == pytest.approx(archard, rel=0.02)
    assert flank_volume(setup, r2, face.grid, 2) * p.z2 / p.z1 == pytest.approx(archard, rel=0.02)
    p1 = wear_rates(setup, WearState.zero(grid.size))[0]
    path_error = flank_volume(setup, p1, None, 1) / archard - 1
    assert (path_error < 0.02) if crowning == 0 else (path_error > 0.04)


def test_the_face_field_is_read_back_along_the_lines_and_fed_to_the_ltca(plain, baseline_pair, grid):
    """along_lines interpolates the face grid exactly for a field linear in ζ; face_deviation puts the pinion's
    field at ρ₁ = u and the gear's at ρ₂ = T₁T₂ − u on the named helix only."""
    from femgear.physics.ltca.separation import face_deviation

    res, face = plain
    p, z = baseline_pair, face.grid
    field = np.broadcast_to(1e-6 * (1 + z / z[-1]) * np.array([1.0, 2.0])[:, None, None], (2, grid.size, z.size))
    got = along_lines(field, face.zeta, z)
    on = np.isfinite(face.zeta)
    expect = 1e-6 * (1 + face.zeta / z[-1]) * np.array([1.0, 2.0])[:, None, None]
    assert np.allclose(got[on], expect[on], rtol=1e-12) and np.all(got[~on] == 0)
    removed = np.zeros((2, 2, grid.size, z.size))
    removed[1, 1] = 1e-6 * np.linspace(0, 1, grid.size)[:, None] * z[None, :] / z[-1]
    dev = face_deviation(p, grid, z, removed)
    rho2 = p.line_of_action - grid[10]
    assert dev("right", 2, np.array([rho2]), np.array([z[-1]]))[0] == pytest.approx(removed[1, 1, 10, -1])
    assert dev("left", 2, np.array([rho2]), np.array([z[-1]]))[0] == 0.0
    assert dev("right", 1, np.array([grid[10]]), np.array([z[-1]]))[0] == 0.0
    with pytest.raises(ValueError, match="face_deviation"):
        face_deviation(p, grid, z, removed[0])
    with pytest.raises(ValueError, match="grid"):
        FaceReference(ref=face.ref, zeta=face.zeta, grid=np.array([0.0, 1e-3, 3e-3]))


def test_a_coupling_pass_reruns_the_ltca_on_the_face_field(plain, coarse_model, baseline_force, baseline_pair, grid):
    """The coupling's drive-flank deviation with ``wear.field = "face"``: 2 µm worn off the pinion's left helix
    only (its face mean over both helices is 1 µm) unloads the left helix in the re-run LTCA (to 0.55–0.60 of the
    right helix's load); the face-uniform
    deviation of the same mean leaves both helices alike.  The thermal growth enters uniform over the face."""
    from types import SimpleNamespace

    from femgear.physics.ltca.analysis import mesh_cycle
    from femgear.system.coupling.passes import removed_deviation

    _, face = plain
    p, z = baseline_pair, face.grid
    wear_face = np.zeros((2, 2, grid.size, z.size))
    wear_face[0, 0] = 2e-6
    zeta = np.full((2, grid.size), 0.1e-6)
    setup = SimpleNamespace(pair=p, kin=SimpleNamespace(u=grid), face=face)
    wear = np.array([face_mean(wear_face[j], z).mean(axis=0) for j in (0, 1)])
    runs = {}
    for name, field in (("face", wear_face), ("path", None)):
        dev = removed_deviation(setup, wear, zeta, field)
        runs[name] = mesh_cycle(coarse_model, baseline_force, None, n_phases=8, stagger=0.0, n_line=8, extra=dev,
                                keep_lines=False)
        if name == "face":
            assert dev("left", 1, grid[:3], z[:3]) == pytest.approx(1.9e-6) and dev("right", 1, grid[:3], z[:3]) \
                == pytest.approx(-0.1e-6)
    assert np.allclose(runs["path"].force_left, runs["path"].force_right, rtol=1e-9)
    assert np.all(runs["face"].force_left < 0.7 * runs["face"].force_right)     # measured 0.55–0.60


def test_face_wear_needs_the_ltca_stiffness(baseline_scene):
    """``wear.field = "face"`` is refused when the case is bound, naming the key, without the ltca stiffness."""
    from femgear.errors import SceneError
    from femgear.scene import load_scene
    from tests.conftest import BASELINE

    with pytest.raises(SceneError, match=r"wear\.field.*ltca"):
        build_case(load_scene(BASELINE, ['wear.field="face"']))
    with pytest.raises(SceneError, match=r"wear\.field"):
        load_scene(BASELINE, ['wear.field="surface"'])
    assert load_scene(BASELINE, ['wear.field="face"', 'physics.stiffness="ltca"']).wear.field == "face"
