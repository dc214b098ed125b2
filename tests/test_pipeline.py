"""The driver honours every physics level it accepts (none is silently ignored).

These tests read the typed :class:`femgear.results.RunResult` of :func:`femgear.pipeline.run_case`;
the JSON layout written from it is checked by the contract tests (tests/cli/test_cli_contract.py).
"""

import numpy as np
import pytest

from femgear.case import build_case
from femgear.case.pair import pair_from_scene
from femgear.levels import stiffness as stiffness_levels
from femgear.pipeline import run_case
from femgear.scene import load_scene


def _run(scene):
    return run_case(build_case(scene))


def _at_pitch(result, values) -> float:
    return float(np.interp(0.0, result.case.path.s, values))


@pytest.mark.parametrize("level", ["analytic"])
def test_thermal_level_reports_flank_deviation(baseline_path, level):
    scene = load_scene(baseline_path, [f'physics.thermal="{level}"', "thermal.flank_temperature_rise=30"])
    r = _run(scene)
    assert 1e-6 < _at_pitch(r, r.tribology.thermal_deviation[0]) < 2e-5


def contact_line_ripple(eps_alpha: float, eps_beta: float) -> float:
    """Peak-to-peak over mean of a helical pair's total contact-line length (the ISO 6336-1 picture:
    constant stiffness per unit line length).  L(t) ∝ ∫₀^εα g(x − t) dx with g the number of lines
    over a point, mean ε_β; the fluctuating part is the overlap of two periodic intervals of lengths
    a = frac(ε_α), c = frac(ε_β), which runs from max(0, a + c − 1) to min(a, c):
    ripple = (min(a, c) − max(0, a + c − 1)) / (ε_α ε_β)."""
    a, c = eps_alpha % 1.0, eps_beta % 1.0
    return (min(a, c) - max(0.0, a + c - 1.0)) / (eps_alpha * eps_beta)


def test_stiffness_level_is_computed(baseline_path):
    """The ``pem`` level reaches the results: its ripple is the sliced PEM's own (bit for bit) and
    follows the contact-line-length theory of the baseline (ε_α 1.369, ε_β 0.928, stagger 0: 5.63 %)
    to the share PEM's varying stiffness per unit line moves it (measured 4.90 %, the marine pair
    4.15 % against 4.07 %); the ``constant`` level has none."""
    scene = load_scene(baseline_path, ['physics.stiffness="pem"'])
    s = _run(scene).stiffness
    pair = pair_from_scene(scene)
    assert s.level == "pem"
    assert s.ripple() == pytest.approx(stiffness_levels.of(build_case(scene)).ripple(), rel=1e-12)
    theory = contact_line_ripple(pair.eps_alpha, pair.eps_beta)
    assert theory == pytest.approx(0.0563, abs=1e-4)
    assert s.ripple() == pytest.approx(theory, rel=0.2)
    const = _run(load_scene(baseline_path, ['physics.stiffness="constant"'])).stiffness
    assert const.ripple() == 0.0


def test_pem_ripple_follows_contact_line_theory_on_the_marine_pair():
    """The same check on another pair (marine, ε_α 1.414, ε_β 3.18): theory 4.07 %, PEM measured 4.15 %."""
    from pathlib import Path

    scene = load_scene(Path(__file__).resolve().parents[1] / "studies" / "zoo" / "marine.toml",
                       ['physics.stiffness="pem"'])
    pair = pair_from_scene(scene)
    theory = contact_line_ripple(pair.eps_alpha, pair.eps_beta)
    assert theory == pytest.approx(0.0407, abs=1e-4)
    assert stiffness_levels.of(build_case(scene)).ripple() == pytest.approx(theory, rel=0.2)


def test_lubrication_levels(baseline_path):
    none = _run(load_scene(baseline_path, ['physics.lubrication="none"'])).tribology
    const = _run(load_scene(baseline_path, ['physics.lubrication="constant"', "friction.coefficient=0.07"])).tribology
    assert none.friction_coefficient is None and none.temperature_rise is None
    np.testing.assert_allclose(const.friction_coefficient, 0.07, rtol=1e-12)


def test_ehl_line_level_gives_a_u_shaped_friction(baseline_path):
    scene = load_scene(baseline_path, ['physics.lubrication="ehl-line"', 'physics.dynamics="none"',
                                       'physics.coupling="one-way"', "numerics.path_points=9", "numerics.ehl_level=4"])
    r = _run(scene)
    mu = r.tribology.friction_coefficient
    assert _at_pitch(r, mu) < 1e-3 < 0.01 < mu.max() < 0.1


@pytest.mark.parametrize("level", ["lumped", "timoshenko"])
@pytest.mark.parametrize("scene_file", ["fzg_c14.toml", "single_helical.toml"])
def test_one_mesh_pairs_run_coupled_dynamics(scene_file, level):
    """Spur and single-helical pairs through the coupled pipeline (one mesh station per shaft, in the
    mid-plane of the face): the mean dynamic mesh force carries F_bn (within the friction-loss share, 1 %),
    the absent right mesh carries nothing, and a spur pair has no axial response."""
    from pathlib import Path

    base = Path(__file__).resolve().parents[1] / "studies" / scene_file
    scene = load_scene(base, [f'physics.dynamics="{level}"', 'physics.coupling="one-way"',
                              "numerics.dynamics_cycles=40.0", "numerics.transient_cycles=20.0"])
    r = _run(scene)
    a = r.coupled.state.amplitudes
    assert a["mesh_force.L.mean"] == pytest.approx(r.contact.normal_force, rel=0.01)
    assert a["mesh_force.R.mean"] == 0.0 and a["mesh_force.R.amplitude"] == 0.0
    if scene_file.startswith("fzg"):
        assert a["gear.displacement.z"] < 1e-12 and a["pinion.displacement.z"] < 1e-12


def test_the_te_analysis_and_the_ltca_maps_of_a_gear_driven_run_carry_the_pinion_torque(baseline_path, monkeypatch):
    """A gear-driven scene: ``operating.torque`` is the gear's (T2 = T1 z2/z1), but the LTCA cycle of the run is
    loaded by F_bn = T1/(r_b1 cos β_b), so its TE analysis and load maps are labelled (and their figures computed)
    with the operating point's pinion torque T1, not the driver's."""
    from types import SimpleNamespace

    import femgear.physics.ltca.maps as maps
    import femgear.physics.ltca.te as te
    from femgear.pipeline import transmission_error
    from femgear.stages import ltca_maps

    case = build_case(load_scene(baseline_path, ['operating.driver="gear"']))
    T1, T2 = case.operating.pinion_torque, case.scene.operating.torque
    assert T2 == pytest.approx(T1 * case.pair.z2 / case.pair.z1) and abs(T2 - T1) > 0.05 * T1
    seen = {}
    monkeypatch.setattr(te, "analyse_cycle", lambda r, pair, E, nu, torque, n: seen.setdefault("te", torque))
    monkeypatch.setattr(maps, "load_maps", lambda r, pair, E, nu, torque, *a: seen.setdefault("maps", torque))
    stiffness = SimpleNamespace(ltca=SimpleNamespace(result=SimpleNamespace(line_load=[1.0])))
    transmission_error(case, stiffness)
    ltca_maps(SimpleNamespace(case=case, stiffness=stiffness, transmission_error=SimpleNamespace(worst_phase=0)))
    assert seen == {"te": T1, "maps": T1}
