"""The LTCA tool's analysis (femgear.physics.ltca.te, .maps, .tool) on the coarse baseline model (fast)."""

import dataclasses
import math
from pathlib import Path

import numpy as np
import pytest

from femgear.case.pair import pair_from_scene
from femgear.errors import ArgumentError, SceneError
from femgear.physics.ltca.cycle import LTCACycle
from femgear.scene.schema import Modifications

RELIEF = Modifications(tip_relief=10e-6, tip_relief_length=2.5e-3)
TORQUES = (100.0, 200.0, 300.0)


@pytest.fixture(scope="module")
def tool(coarse_model, baseline_pair):
    from femgear.physics.ltca.tool import LTCAOptions, run_ltca

    opts = LTCAOptions(n_phases=16, n_line=8, n_harmonics=5)
    return run_ltca(baseline_pair, 210e9, 0.3, RELIEF, TORQUES, 200.0, "pinion", {}, harris_torques=(50.0, 200.0),
                    options=opts, model=coarse_model)


@pytest.fixture(scope="module")
def plain(coarse_model, baseline_pair):
    from femgear.physics.ltca.tool import LTCAOptions, run_ltca

    return run_ltca(baseline_pair, 210e9, 0.3, Modifications(), (200.0,), 200.0, "pinion", {},
                    options=LTCAOptions(n_phases=16, n_line=8, n_harmonics=5), model=coarse_model)


def test_te_and_harmonics_equal_the_study_functions(tool, coarse_model, baseline_pair):
    """TE p-p and mesh-order amplitudes are those of ``LTCAResult.lte_peak_to_peak``/``harmonics`` that the study
    scripts print (studies/ltca/ltca_study.py), to 1e-9 of the p-p, at each torque; the refined check is the 2×-points
    cycle's."""
    from femgear.physics.ltca.analysis import mesh_cycle, normal_force

    for a, t in zip(tool.analyses, TORQUES, strict=True):
        r = mesh_cycle(coarse_model, normal_force(baseline_pair, t), RELIEF, n_phases=16, n_line=8)
        fine = mesh_cycle(coarse_model, normal_force(baseline_pair, t), RELIEF, n_phases=16, n_line=16)
        assert a.peak_to_peak == pytest.approx(r.lte_peak_to_peak(), rel=1e-9)
        np.testing.assert_allclose(a.harmonics, r.harmonics(5), rtol=0, atol=1e-9 * r.lte_peak_to_peak())
        np.testing.assert_allclose(a.harmonics_refined, fine.harmonics(5), rtol=0, atol=1e-9 * r.lte_peak_to_peak())
        assert a.torque == t and a.force == pytest.approx(normal_force(baseline_pair, t), rel=1e-15)
    assert tool.analyses[1] is tool.design or tool.design.torque == 200.0


def test_harmonics_are_the_amplitudes_of_a_least_squares_fourier_fit(tool):
    """Independent of the FFT: a least-squares fit of cos/sin at the mesh orders 1…N to the sampled loaded TE (exact
    on equally spaced samples for N < n/2) gives the same amplitudes √(a² + b²)."""
    a = tool.analyses[1]
    x = 2 * np.pi * a.phase
    cols = [np.ones_like(x)] + [f(h * x) for h in range(1, 8) for f in (np.cos, np.sin)]
    coef = np.linalg.lstsq(np.column_stack(cols), a.lte, rcond=None)[0]
    amp = np.hypot(coef[1::2], coef[2::2])[:5]
    np.testing.assert_allclose(a.harmonics, amp, rtol=1e-9, atol=1e-15)


def test_unmodified_flanks_zero_unloaded_te_and_loads_balance(plain, coarse_model, baseline_pair, baseline_force):
    """Unmodified: unloaded TE zero at every phase; the loaded TE p-p is the LTCA's own (test_ltca's cycle); the
    helices' loads sum to the applied normal force at every phase; a symmetric body shares it equally."""
    from femgear.physics.ltca.analysis import mesh_cycle

    a = plain.analyses[0]
    assert np.all(a.nlte == 0.0) and a.nlte_peak_to_peak == 0.0
    r = mesh_cycle(coarse_model, baseline_force, Modifications(), n_phases=16, n_line=8)
    assert a.peak_to_peak == pytest.approx(r.lte_peak_to_peak(), rel=1e-12) and a.peak_to_peak > 0
    np.testing.assert_allclose(a.force_left + a.force_right, baseline_force, rtol=1e-9)
    assert a.balance_error < 1e-9
    assert np.all(a.interior_force > 0) and np.all(a.interior_force <= np.array([a.force_left, a.force_right]))
    assert a.share_left == pytest.approx(0.5, abs=1e-9) and a.share_right == pytest.approx(0.5, abs=1e-9)
    assert a.stiffness_mean == pytest.approx(np.mean(r.k_secant), rel=1e-12)
    assert a.stiffness_ripple == pytest.approx(np.ptp(r.k_secant) / np.mean(r.k_secant), rel=1e-12)


def test_helix_alone_te_carries_its_share_and_is_symmetric(plain):
    """Each helix alone at half the load: both helices' TE are equal on the symmetric body, positive, and the
    common approach of both helices loaded together (the cross-helix compliance softens the body) lies above it."""
    a = plain.analyses[0]
    np.testing.assert_allclose(a.lte_left, a.lte_right, rtol=1e-9)
    assert np.all(a.lte_left > 0)
    assert np.all(a.lte > a.lte_left)


def test_peak_pressure_is_hertz_at_the_located_point_and_edges_are_flagged(plain, baseline_pair):
    """The peak equals √(w E′/(2πR)) of the point it names; unmodified flanks: the peak is an edge contact (a contact
    line's end at the tip or a face end), above the largest pressure away from the edges."""
    from femgear.physics.ltca.halfspace import reduced_modulus

    a = plain.analyses[0]
    p = a.pressure
    assert p.edge and p.where != "interior" and p.pressure > p.interior_pressure > 0
    L = baseline_pair.line_of_action
    R = p.u * (L - p.u) / L / math.cos(baseline_pair.beta_b)
    w = p.pressure ** 2 * 2 * math.pi * R / reduced_modulus(210e9, 0.3)
    assert 1e4 < w < 1e7                                       # a load per length in N/m of a gear contact
    assert a.phase[a.worst_phase] == p.phase


def test_harris_map_matches_single_cycles(tool, coarse_model, baseline_pair):
    from femgear.physics.ltca.analysis import mesh_cycle, normal_force

    h = tool.harris
    assert h.torque.tolist() == [50.0, 200.0] and h.design_torque == 200.0
    r = mesh_cycle(coarse_model, normal_force(baseline_pair, 50.0), RELIEF, n_phases=16, n_line=8, keep_lines=False)
    assert h.peak_to_peak[0] == pytest.approx(r.lte_peak_to_peak(), rel=1e-12)
    assert h.peak_to_peak[1] == pytest.approx(tool.analyses[1].peak_to_peak, rel=1e-12)


@pytest.mark.parametrize("torques, text", [((), "no torque"), ((-5.0,), "positive"), ((float("nan"),), "positive"),
                                           ((1e6,), "nominal contact stress"), ((1.0,) * 51, "at most")])
def test_bad_torques_are_refused_naming_the_key(baseline_pair, torques, text):
    from femgear.physics.ltca.te import check_torques

    with pytest.raises(ArgumentError, match=text) as err:
        check_torques(torques, baseline_pair, 210e9, 0.3)
    assert str(err.value).startswith("--torques: ")
    assert check_torques((100, 200.5), baseline_pair, 210e9, 0.3) == (100.0, 200.5)


def test_a_helix_losing_contact_at_the_design_load_is_refused(coarse_model, baseline_pair):
    """A 200 µm helix slope deviation on the left helix opens it far more than the flanks deflect (≈ 5 µm): the
    left helix carries nothing, and the tool stops naming the key."""
    from femgear.physics.ltca.tool import LTCAOptions, run_ltca

    mods = Modifications(helix_slope_deviation_left=200e-6)
    with pytest.raises(SceneError, match="left helix loses contact") as err:
        run_ltca(baseline_pair, 210e9, 0.3, mods, (200.0,), 200.0, "pinion", {},
                 options=LTCAOptions(n_phases=8, n_line=8, n_harmonics=3), model=coarse_model)
    assert err.value.key == "modifications.helix_slope_deviation_left"


@pytest.mark.parametrize("scene", ["paper_baseline.toml", "zoo/marine.toml", "fzg_c14.toml"])
def test_both_members_are_turned_into_mesh_along_a_contact_line(scene):
    """After :func:`to_mesh` the pinion's and the gear's flank points of one contact line coincide and their normals
    are opposite, on both helices, for a grooved, staggered body (the right helix's line s p_bt further on); the
    baseline, the marine pair (m_n 6 mm, 29/97) and the FZG C spur pair (profile-shifted), geometry only."""
    from pathlib import Path

    from femgear.physics.ltca.flank import flank_normals, flank_points
    from femgear.physics.ltca.maps import to_mesh
    from femgear.physics.mesh.segment import frame_of
    from femgear.scene import load_scene

    pair = pair_from_scene(load_scene(Path(__file__).resolve().parents[2] / "studies" / scene))
    L, tb = pair.line_of_action, math.tan(pair.beta_b)
    u_p = pair.rb1 * math.tan(pair.alpha_wt)
    groove, s = 8e-3, 0.3
    for helix, shift in (("left", 0.0), ("right", s * pair.p_bt)):
        z = np.linspace(0.0, pair.b, 201)
        u = u_p + (z - pair.b / 2) * tb + shift
        on = (u > pair.u_start) & (u < pair.u_end)                 # the line's part on the path of contact
        z, u = z[on], u[on]
        assert z.size > 10
        pts, nrm = [], []
        for member, rho in ((1, u), (2, L - u)):
            f = frame_of(pair, member, groove, s)
            p, n = flank_points(pair, member, rho, z), flank_normals(pair, member, rho, z)
            if helix == "right":
                p, n = f.to_right(p), f.to_right(p + 1e-6 * n) - f.to_right(p)
            pts.append(to_mesh(pair, member, p.T))
            q = to_mesh(pair, member, (p + n).T) - pts[-1]
            nrm.append(q / np.linalg.norm(q, axis=1)[:, None])
        assert np.abs(pts[0] - pts[1]).max() < 1e-12 * pair.m_n / 3e-3 * 10, helix
        np.testing.assert_allclose(np.sum(nrm[0] * nrm[1], axis=1), -1.0, atol=1e-6)
    # the gear is turned, not only shifted: its body-frame tooth 0 points along +y, in mesh towards the pinion
    g = to_mesh(pair, 2, flank_points(pair, 2, np.array([L - u_p]), np.array([pair.b / 2])).T)[0]
    assert g[0] == pytest.approx(pair.rw1, rel=1e-9) and abs(g[1]) < 1e-12


def test_maps_of_both_members_read_back_and_integrate_to_the_helix_loads(tool, baseline_pair, tmp_path):
    """``write_maps``: one collection per torque, the pinion and the gear part; read back with meshio, each member's
    load map integrates (Σ_ρ w_mean, trapezoid in ζ, / cos β_b) to each helix's cycle-mean LTCA load within 3 %; the
    gear's nodes lie on its involute about its own axis (r² = ρ₂² + r_b2²)."""
    import xml.etree.ElementTree as ET

    import meshio

    from femgear.edge.io.ltca import write_maps

    pair = baseline_pair
    for a, m in zip(tool.analyses, tool.maps, strict=True):
        pvd = write_maps(tmp_path, m)
        files = [tmp_path / d.get("file") for d in ET.parse(pvd).getroot().iter("DataSet")]
        assert len(files) == 2 and pvd.name == f"ltca_maps_T{a.torque:g}Nm.pvd"
        for member, f in zip((1, 2), files, strict=True):
            mesh = meshio.read(f)
            d = mesh.point_data
            assert np.all(d["member"] == member)
            for h, F in ((0, a.force_left), (1, a.force_right)):
                on = d["helix"] == h
                zeta = np.unique(d["zeta"][on])
                w = d["w_mean"][on].reshape(-1, zeta.size)
                got = np.trapezoid(w.sum(axis=0), zeta) / math.cos(pair.beta_b)
                assert got == pytest.approx(F.mean(), rel=0.03), (member, h)
            assert d["p_max"].max() > 1e8 and d["edge_contact"].any() and d["w_worst"].max() > 0
            if member == 2:
                r = np.hypot(mesh.points[:, 0] - pair.a_w, mesh.points[:, 1])
                np.testing.assert_allclose(r, np.hypot(d["rho"], pair.rb2), rtol=1e-9)


def test_main_job_summary_and_key_figures_carry_the_loaded_te(coarse_model, baseline_force, baseline_scene):
    """A quasi-static run whose stiffness carries an LTCA cycle (the coarse one): ``results.json``'s summary holds
    ``transmission_error`` with the cycle's loaded TE p-p and harmonics, units, and the key figures show it."""
    from femgear.case import build_case
    from femgear.edge.cli.report import key_figures
    from femgear.edge.io.run import run_summary
    from femgear.physics.ltca.analysis import mesh_cycle
    from femgear.pipeline import run_case, transmission_error

    scene = baseline_scene.model_copy(update={"physics": baseline_scene.physics.model_copy(update={
        "dynamics": "none", "coupling": "one-way", "lubrication": "constant", "thermal": "none", "wear": "none",
        "stiffness": "iso6336"})})
    case = build_case(scene)
    result = run_case(case)
    assert result.transmission_error is None and "transmission_error" not in run_summary(result)
    r = mesh_cycle(coarse_model, baseline_force, None, n_phases=16, n_line=8)
    ms = dataclasses.replace(result.stiffness, level="ltca", ltca=LTCACycle.from_result(r, resolved_orders=7))
    result = dataclasses.replace(result, stiffness=ms, transmission_error=transmission_error(case, ms))
    te = run_summary(result)["transmission_error"]
    assert te["lte_peak_to_peak"] == r.lte_peak_to_peak() and np.allclose(te["lte_harmonics"], r.harmonics(5))
    assert te["units"]["lte_peak_to_peak"] == "m" and te["resolved_orders"] == 7
    rows = {q: v for q, v, _ in key_figures(run_summary(result))}
    assert rows["loaded TE p-p (LTCA, normal); harmonics 1-3"].startswith(f"{r.lte_peak_to_peak() * 1e6:.4f}")


def test_the_tool_builds_the_bodies_the_scene_asks_for(monkeypatch, tmp_path):
    """``femgear ltca`` takes the member bodies' resolution and elements from the scene (``numerics.body_level``,
    ``numerics.body_elements``), as the ``ltca`` stiffness level does; it built level 1, P1 whatever they said."""
    import femgear.physics.ltca.tool as tool
    from femgear.edge.cli import main

    seen = {}

    class Stop(Exception):
        pass

    def capture(*args, **kwargs):
        seen["options"] = args[9]
        raise Stop

    monkeypatch.setattr(tool, "run_ltca", capture)
    base = Path(__file__).resolve().parents[2] / "studies" / "paper_baseline.toml"
    with pytest.raises(Stop):
        main(["ltca", str(base), "--out", str(tmp_path / "o"), "--set", "numerics.body_level=0",
              "--set", 'numerics.body_elements="p2-bending"', "--debug"])
    assert (seen["options"].level, seen["options"].order) == (0, "p2-bending")
