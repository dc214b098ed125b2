"""Tier 2/3: Timoshenko shafts for spur and single-helical pairs (one mesh station per shaft, straddle or
overhung bearings, the thrust bearing) — beam theory, the stiff-shaft limit, hand statics, bad input."""

import math
import subprocess
import sys
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest
from scipy.linalg import eigh
from scipy.optimize import brentq

from femgear.case import build_case
from femgear.case.checks import bearing_stations, toothed_width
from femgear.errors import SceneError
from femgear.scene import load_scene
from femgear.system.dynamics import build_model, run_dynamics
from femgear.system.dynamics.bearings import static_bearing_loads
from femgear.system.dynamics.structure import _half_bodies, _station_springs, assemble_structure
from femgear.system.dynamics.timoshenko import ShaftSection, shaft_element
from tests.dynamics import hand_statics

ROOT = Path(__file__).resolve().parents[2]
ZOO = ROOT / "studies" / "zoo"


def _chain(section, z):
    """Full (unreduced) stiffness and consistent mass of Timoshenko elements between the nodes ``z``."""
    n = 6 * len(z)
    K, M = np.zeros((n, n)), np.zeros((n, n))
    for e in range(len(z) - 1):
        k, m = shaft_element(section, z[e + 1] - z[e])
        idx = np.arange(6 * e, 6 * e + 12)
        K[np.ix_(idx, idx)] += k
        M[np.ix_(idx, idx)] += m
    return K, M


def free_free_timoshenko(section, length: float) -> float:
    """Lowest root of the free–free Timoshenko beam's frequency equation [Hz] (Huang, J. Appl. Mech. 28:579,
    1961; Han, Benaroya & Wei, JSV 225:935, 1999).  Below the cut-off frequency w = Σ c_k φ_k(x) with
    φ = cosh αx, sinh αx, cos βx, sin βx and the section rotation ψ = g(α) sinh αx, g(α) cosh αx,
    −h(β) sin βx, h(β) cos βx (g(s) = s + ρAω²/(κGA s), h(β) = β − ρAω²/(κGA β)); the free ends
    ψ' = 0 (no moment) and w' − ψ = 0 (no shear force) at x = 0 and L make the 4×4 determinant vanish."""
    E, G, A, I, rho, kap = (section.youngs_modulus, section.shear_modulus, section.area, section.second_moment,
                            section.density, section.shear_coefficient)
    kGA, L = kap * G * A, length

    def det(omega):
        a4, b2, c0 = E * I * kGA, omega**2 * (E * I * rho * A + rho * I * kGA), rho * A * omega**2 * (rho * I * omega**2 - kGA)
        disc = math.sqrt(b2**2 - 4 * a4 * c0)
        al, be = math.sqrt((-b2 + disc) / (2 * a4)), math.sqrt((b2 + disc) / (2 * a4))
        g, h = al + rho * A * omega**2 / (kGA * al), be - rho * A * omega**2 / (kGA * be)
        rows = []
        for x in (0.0, L):
            ch, sh, c, s = math.cosh(al * x), math.sinh(al * x), math.cos(be * x), math.sin(be * x)
            rows.append([g * al * ch, g * al * sh, -h * be * c, -h * be * s])                  # ψ'
            rows.append([al * sh - g * sh, al * ch - g * ch, -be * s + h * s, be * c - h * c])  # w' − ψ
        return np.linalg.det(np.array(rows))

    eb = (4.730041 / L) ** 2 * math.sqrt(E * I / (rho * A))          # Euler-Bernoulli: an upper bound
    grid = np.linspace(0.5 * eb, 1.01 * eb, 400)
    vals = [det(w) for w in grid]
    i = next(k for k in range(len(grid) - 1) if vals[k] * vals[k + 1] < 0)
    return brentq(det, grid[i], grid[i + 1], xtol=1e-10) / (2 * math.pi)


@pytest.mark.parametrize("diameter, length", [(0.03, 0.2), (0.08, 0.3)])     # slender, and thick (shear)
def test_free_shaft_first_bending_frequency_is_timoshenkos(diameter, length):
    """The level's shaft elements, 8 per free shaft: the first bending frequency equals the free–free
    Timoshenko beam's to 1 % (and the thick shaft's lies clearly below Euler–Bernoulli's)."""
    sec = ShaftSection(diameter, 206e9, 0.3, 7850.0)
    K, M = _chain(sec, np.linspace(0.0, length, 9))
    f = np.sqrt(np.abs(eigh(K, M, eigvals_only=True))) / (2 * math.pi)
    bending = np.sort(f[f > 1.0])[0]
    exact = free_free_timoshenko(sec, length)
    assert bending == pytest.approx(exact, rel=0.01)
    eb = (4.730041 / length) ** 2 * math.sqrt(sec.youngs_modulus * sec.second_moment / (sec.density * sec.area))
    assert exact < (0.95 if diameter == 0.08 else 1.0) * eb / (2 * math.pi)


def _stations(case):
    return tuple(bearing_stations(n, m.bearing_span, m.face_offset, toothed_width(case.scene, n))
                 for n, m in zip(("pinion", "gear"), case.members))


@pytest.mark.parametrize("scene", ["automotive_spur", "small_spur", "wind"])
def test_one_station_reduction_keeps_the_first_bending_mode(scene):
    """The level's model of each shaft with its gear body (one Timoshenko element per segment, bearings
    condensed onto the mesh station) against the same shaft meshed with 16 elements per segment and nothing
    condensed: the first bending frequency within 1 %."""
    case = build_case(load_scene(ZOO / f"{scene}.toml"))
    st = assemble_structure(case.members, case.material, case.pair, True, _stations(case),
                            tuple(m.shaft_diameter for m in case.members), 0.0)
    M24, (Kb, _) = _half_bodies(case.members, case.pair), _station_springs(case.members)
    for member, mem in enumerate(case.members):
        idx = np.arange(6 * member, 6 * member + 6)
        reduced = np.sort(np.sqrt(np.abs(eigh(st.K[np.ix_(idx, idx)], st.M[np.ix_(idx, idx)], eigvals_only=True))))
        zL, zR = _stations(case)[member]
        ends = sorted([zL, zR, 0.0])
        z = np.concatenate([np.linspace(ends[0], ends[1], 17)[:-1], np.linspace(ends[1], ends[2], 17)])
        sec = ShaftSection(mem.shaft_diameter, case.material.youngs_modulus, case.material.poisson_ratio,
                           case.material.density)
        K, M = _chain(sec, z)
        g = 6 * int(np.argmin(np.abs(z)))
        M[g:g + 6, g:g + 6] += sum(M24[b:b + 6, b:b + 6] for b in (12 * member, 12 * member + 6))
        for j, zj in enumerate((zL, zR)):
            n0 = 6 * int(np.argmin(np.abs(z - zj)))
            K[n0:n0 + 3, n0:n0 + 3] += np.diag(Kb[2 * member + j])
        fine = np.sort(np.sqrt(np.abs(eigh(K, M, eigvals_only=True))))
        assert reduced[1] == pytest.approx(fine[1], rel=0.01)


def _hand_flexibility(span, a, EI, kGA):
    """(deflection, rotation) flexibility at a point a from the left of a shaft pinned at 0 and ``span``
    (a > span: overhung by a − span), bending and shear by the unit-load method [m/N, 1/N, 1/(N m)]."""
    if a <= span:                            # straddle: b = span − a
        b = span - a
        return np.array([[a**2 * b**2 / (3 * EI * span) + a * b / (kGA * span), a * b * (b - a) / (3 * EI * span)],
                         [a * b * (b - a) / (3 * EI * span), (a**3 + b**3) / (3 * EI * span**2) + 1 / (kGA * span)]])
    c = a - span
    return np.array([[c**2 * (span + c) / (3 * EI) + (c + c**2 / span) / kGA, c * (2 * span + 3 * c) / (6 * EI) + c / (span * kGA)],
                     [c * (2 * span + 3 * c) / (6 * EI) + c / (span * kGA), (span + 3 * c) / (3 * EI) + 1 / (span * kGA)]])


@pytest.mark.parametrize("offset", [0.0, 0.03, 0.13])          # symmetric and offset straddle, overhung
def test_gear_on_a_light_shaft_has_the_hand_bending_frequencies(offset):
    """A heavy gear body on a massless-like shaft on rigid bearings: the level's lateral–tilt frequencies of the
    member equal those of the 2-DOF disc with the Timoshenko shaft's hand flexibility at its station (exact:
    one element is exact in statics), placed where ``face_offset`` puts it."""
    span, d = 0.2, 0.03
    mat = SimpleNamespace(youngs_modulus=206e9, poisson_ratio=0.3, density=1e-3)
    mem = SimpleNamespace(mass=4.0, inertia=0.01, support_stiffness=1e17, support_damping=0.0, axial_stiffness=None,
                          axial_damping=None, thrust_bearing="both")
    pair = build_case(load_scene(ZOO / "automotive_spur.toml")).pair
    zs = (-offset - span / 2, -offset + span / 2)
    st = assemble_structure((mem, mem), mat, pair, True, (zs, zs), (d, d), 0.0)
    idx = [0, 4]                                           # x and θy of the pinion's station (the x–z plane)
    f = np.sort(np.sqrt(np.abs(eigh(st.K[np.ix_(idx, idx)], st.M[np.ix_(idx, idx)], eigvals_only=True))))
    sec = ShaftSection(d, 206e9, 0.3, 1.0)
    F = _hand_flexibility(span, span / 2 + offset, sec.youngs_modulus * sec.second_moment,
                          sec.shear_coefficient * sec.shear_modulus * sec.area)
    S = np.diag([1.0, -1.0])                               # the hand rotation counts against θy in the x–z plane
    Id = mem.inertia / 2 + mem.mass * pair.b**2 / 12
    hand = np.sort(np.sqrt(eigh(np.linalg.inv(S @ F @ S), np.diag([mem.mass, Id]), eigvals_only=True)))
    assert np.allclose(f, hand, rtol=1e-5)


def _stiff(scene):
    """The scene with shafts 1e4 times stiffer and nearly massless (a copy, past the input ranges)."""
    mat = scene.material.model_copy(update={"youngs_modulus": 1e4 * scene.material.youngs_modulus, "density": 1e-3})
    return scene.model_copy(update={"material": mat})


@pytest.mark.parametrize("scene", ["automotive_spur", "wind"])
def test_very_stiff_shafts_equal_the_lumped_level(scene):
    """The timoshenko level with rigid, massless shafts is the lumped level: the dynamic mesh force amplitude
    and mean, and the bearing loads, agree to 1 % (the stiffness "contact-line", independent of E)."""
    case = build_case(_stiff(load_scene(ZOO / f"{scene}.toml")), warn=False)
    runs = {lvl: run_dynamics(build_model(case, lvl, stiffness="contact-line", friction=0.0), cycles=40,
                              transient_cycles=20) for lvl in ("lumped", "timoshenko")}
    a, b = (runs[lvl].amplitudes for lvl in ("lumped", "timoshenko"))
    assert b["mesh_force.L.amplitude"] == pytest.approx(a["mesh_force.L.amplitude"], rel=0.01)
    assert b["mesh_force.L.mean"] == pytest.approx(a["mesh_force.L.mean"], rel=1e-3)
    la, lb = (runs[lvl].response.bearings for lvl in ("lumped", "timoshenko"))
    assert np.allclose(lb.mean, la.mean, rtol=1e-3, atol=1e-3 * np.abs(la.mean).max())


@pytest.mark.parametrize("level", ["lumped", "timoshenko"])
@pytest.mark.parametrize("mounting", [("0.0", "left"), ("0.12", "right"), ("0.75", "both")])
def test_single_helical_static_reactions_equal_the_hand_statics(level, mounting):
    """The wind pair (single helix) with its pinion straddle-mounted off centre or overhung and one thrust
    bearing: the static radial loads equal the hand statics from F_t, F_r and the tilting moment F_a r_w, the
    axial load F_a sits on the thrust bearing, to 0.5 %; the mean loads of a dynamic run too."""
    offset, thrust = mounting
    scene = load_scene(ZOO / "wind.toml", [f"pinion.face_offset={offset}", f'pinion.thrust_bearing="{thrust}"'])
    case = build_case(scene)
    m = build_model(case, level, stiffness="contact-line", friction=0.0)
    T1 = case.operating.pinion_torque
    hand = hand_statics.bearing_loads(case.pair, T1, (0.0,), (1,), np.array(_stations(case)))
    share = {"both": (0.5, 0.5), "left": (1.0, 0.0), "right": (0.0, 1.0)}[thrust]
    hand[0:2, 2] = hand[0:2, 2].sum() * np.array(share)           # F_a on the pinion's thrust bearing(s)
    static = static_bearing_loads(m)
    for loads, tol in ((static, 5e-3), (run_dynamics(m, cycles=30, transient_cycles=15).response.bearings.mean, 5e-3)):
        scale = np.abs(hand[:2]).max()
        assert np.allclose(loads[:2], hand[:2], rtol=tol, atol=tol * scale), (loads[:2], hand[:2])
    # the moment F_a r_w really is in: without it the pinion's two radial x loads would be in the lever ratio only
    assert abs(static[0, 0] - static[1, 0]) > 0.05 * abs(static[0, 0] + static[1, 0]) or offset != "0.0"


@pytest.mark.parametrize("level", ["lumped", "timoshenko"])
def test_default_mounting_is_todays_symmetric_layout(level):
    """Without face_offset / thrust_bearing the stations sit at ±bearing_span/2 and each takes half the
    axial support: the model equals the one built with explicit defaults."""
    base = load_scene(ZOO / "wind.toml")
    explicit = load_scene(ZOO / "wind.toml", ["pinion.face_offset=0.0", 'gear.thrust_bearing="both"'])
    m0, m1 = (build_model(build_case(s), level) for s in (base, explicit))
    assert np.array_equal(m0.K, m1.K) and np.array_equal(m0.M, m1.M)
    assert np.allclose(m0.bearings.z, [-0.45, 0.45, -0.5, 0.5])
    assert np.allclose(m0.bearings.stiffness[:, 2], [1e9, 1e9, 1.5e9, 1.5e9])


@pytest.mark.parametrize("override, key", [
    ("pinion.face_offset=0.3", "pinion.face_offset"),       # the right bearing under the 480 mm face
    ("gear.face_offset=-0.45", "gear.face_offset"),
    ("pinion.bearing_span=0.4", "pinion.bearing_span"),     # a shaft shorter than the face
])
def test_bearings_under_the_teeth_are_one_line_naming_the_key(override, key, tmp_path):
    with pytest.raises(SceneError) as err:
        build_case(load_scene(ZOO / "wind.toml", [override]))
    assert err.value.key == key
    out = tmp_path / "run"
    p = subprocess.run([sys.executable, "-m", "femgear", "run", str(ZOO / "wind.toml"), "--set", override, "--set",
                        'physics.dynamics="timoshenko"', "--out", str(out)], capture_output=True, text=True, cwd=ROOT)
    lines = [ln for ln in p.stderr.splitlines() if ln.strip()]
    assert p.returncode == 2 and len(lines) == 1 and key in lines[0], p.stderr
    assert not out.exists()
