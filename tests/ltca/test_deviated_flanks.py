"""The LTCA re-run on deviated (worn, expanded) flanks that the coupling loop uses with ``ltca``.

Verification against exact properties of the contact problem: a depth removed uniformly
from a flank opens every gap by that depth, so the loads and the secant stiffness are
unchanged and the loaded TE, the no-load TE and the unloaded TE e_s all move by it.
"""

from dataclasses import replace

import numpy as np
import pytest

from femgear.physics.geometry import path_positions
from femgear.physics.ltca.cycle import LTCACycle


@pytest.fixture(scope="module")
def unworn(coarse_model, baseline_force):
    from femgear.physics.ltca.analysis import mesh_cycle
    from femgear.scene.schema import Modifications

    mods = Modifications(tip_relief=3e-6, tip_relief_length=2.5e-3, crowning=5e-6)
    options = {"n_phases": 16, "stagger": 0.0, "n_line": 8}
    res = mesh_cycle(coarse_model, baseline_force, mods, keep_lines=False, **options)
    return LTCACycle.from_result(res, coarse_model, mods)


def test_path_deviation_reads_each_member_at_its_roll_distance(baseline_pair):
    """Pinion: ρ₁ = u; gear: ρ₂ = T₁T₂ − u; the same on both helices, uniform over the face."""
    from femgear.physics.ltca.separation import path_deviation

    p = baseline_pair
    u = path_positions(p, 41)
    removed = np.array([2e-6 * (u - u[0]) / np.ptp(u), -1e-6 * (u[-1] - u) / np.ptp(u)])
    extra = path_deviation(p, u, removed)
    probe = np.linspace(u[0], u[-1], 17)
    for helix in ("left", "right"):
        for zeta in (0.0, 0.3 * p.b, p.b):
            z = np.full(probe.shape, zeta)
            assert np.allclose(extra(helix, 1, probe, z), 2e-6 * (probe - u[0]) / np.ptp(u), atol=1e-18)
            assert np.allclose(extra(helix, 2, p.line_of_action - probe, z), -1e-6 * (u[-1] - probe) / np.ptp(u),
                               atol=1e-18)
    with pytest.raises(ValueError, match="removed"):
        path_deviation(p, u, removed[:1])


def test_uniform_removal_moves_the_te_by_its_depth_and_keeps_the_loads(unworn, baseline_pair):
    from femgear.physics.ltca.separation import path_deviation

    u = path_positions(baseline_pair, 41)
    depth = 2e-6 + 1e-6                        # pinion 2 µm, gear 1 µm
    worn = unworn.deviated(path_deviation(baseline_pair, u, np.array([np.full(u.size, 2e-6),
                                                                               np.full(u.size, 1e-6)])))
    a, b = unworn.excitation, worn.excitation
    for h in ("left", "right"):
        assert np.allclose(b[f"force_{h}"], a[f"force_{h}"], rtol=1e-9)
        assert np.allclose(b[f"k_secant_{h}"], a[f"k_secant_{h}"], rtol=1e-7)
        assert np.allclose(b[f"lte_{h}"] - a[f"lte_{h}"], depth, rtol=1e-7)
        assert np.allclose(b[f"e_{h}"] - a[f"e_{h}"], depth, rtol=1e-6)
    assert worn.lte_peak_to_peak == pytest.approx(unworn.lte_peak_to_peak, rel=1e-6)
    assert (worn.force, worn.n_line, worn.model, worn.modifications) == (unworn.force, 8, unworn.model,
                                                                         unworn.modifications)


def test_a_worn_cycle_excites_the_drive_flanks_once_and_keeps_the_stiffness(unworn, baseline_pair, baseline_scene):
    """with_deviated_tooth_contact: e'_s = LTE − F_s/k_s,0 on the drive flanks (here e_s + depth), the unworn
    coast flanks and the unworn stiffness table (the integrators' propagators stay valid)."""
    from femgear.case import build_case
    from femgear.physics.ltca.separation import path_deviation
    from femgear.system.dynamics.build import build_model, with_deviated_tooth_contact

    class Source:
        ltca = unworn

    model = build_model(build_case(baseline_scene), stiffness=Source, friction=0.0)
    u = path_positions(baseline_pair, 41)
    worn = unworn.deviated(path_deviation(baseline_pair, u, np.full((2, u.size), 0.5e-6)))
    new = with_deviated_tooth_contact(model, unworn, worn)
    assert new.stiffness is model.stiffness
    assert np.allclose(new.base_deviation.drive - model.base_deviation.drive, 1e-6, rtol=1e-6)
    assert np.array_equal(new.base_deviation.coast, model.base_deviation.coast)
    with pytest.raises(ValueError, match="ltca"):
        with_deviated_tooth_contact(replace(model, base_deviation=None), unworn, worn)


def test_the_coupling_pass_counts_a_worn_flank_once(unworn, baseline_pair, baseline_scene):
    """In the loop with ``ltca`` a uniform 1 µm of pinion wear moves the drive-flank excitation by 1 µm in all
    (through the re-run LTCA), not 2 µm (LTCA + contact-line mean); a uniform expansion closes the coast flanks."""
    from types import SimpleNamespace

    from femgear.case import build_case
    from femgear.system.coupling.passes import deviated_model
    from femgear.system.dynamics.build import build_model

    class Source:
        ltca = unworn

    case = build_case(baseline_scene)
    model = build_model(case, stiffness=Source, friction=0.0)
    u = path_positions(baseline_pair, 41)
    setup = SimpleNamespace(kin=SimpleNamespace(u=u), pair=baseline_pair, case=SimpleNamespace(stagger=0.0),
                            n_phase=64, ltca=unworn, model=model)
    wear = np.array([np.full(u.size, 1e-6), np.zeros(u.size)])
    zeta = np.array([np.zeros(u.size), np.full(u.size, 0.4e-6)])
    state = SimpleNamespace(wear=wear, thermal_deviation=zeta, wear_face=None, thermal_face=None, deviated=None)
    base, extra, worn, deviated = deviated_model(setup, state)
    assert np.allclose(base.base_deviation.drive - model.base_deviation.drive, 1e-6 - 0.4e-6, rtol=1e-6)
    assert np.all(extra.drive == 0) and np.allclose(extra.coast, -0.4e-6, rtol=1e-12)
    assert worn.lte_peak_to_peak == pytest.approx(unworn.lte_peak_to_peak, rel=1e-6)
    again = deviated_model(setup, SimpleNamespace(wear=wear, thermal_deviation=zeta, wear_face=None, thermal_face=None,
                                                  deviated=deviated))
    assert again[2] is worn and again[3] is deviated       # the pass before ran this very deviation: reused
    same, none, cycle, record = deviated_model(setup, SimpleNamespace(wear=0 * wear, thermal_deviation=0 * zeta,
                                                                      wear_face=None, thermal_face=None, deviated=None))
    assert same is model and none is None and cycle is unworn and record is None


def test_worn_orders_records_the_smaller_band_in_both_cycles(unworn, baseline_pair, monkeypatch):
    """Face-resolved wear: the resolution check on the worn flanks sets the band of both cycles (the fewer of the
    two) without touching the unworn cycle the setup holds; a failed check keeps mesh order 1 and its message."""
    import femgear.physics.ltca.level as level
    from femgear.errors import ConvergenceError
    from femgear.physics.ltca.separation import path_deviation
    from femgear.system.coupling.passes import worn_orders

    u = path_positions(baseline_pair, 41)
    extra = path_deviation(baseline_pair, u, np.full((2, u.size), 0.5e-6))
    base = replace(unworn, resolved_orders=6)
    worn = base.deviated(extra)
    seen = {}

    def orders(model, force, mods, stagger, n_line, dev):
        seen.update(model=model, force=force, mods=mods, n_line=n_line, extra=dev)
        return 4, np.arange(3.0)

    monkeypatch.setattr(level, "resolved_orders", orders)
    a, b = worn_orders(base, worn, extra)
    assert seen == {"model": base.model, "force": base.force, "mods": base.modifications, "n_line": 8, "extra": extra}
    assert (a.resolved_orders, b.resolved_orders, base.resolved_orders) == (4, 4, 6)
    assert a.result is base.result and b.result is worn.result and np.array_equal(b.harmonic_change, np.arange(3.0))
    monkeypatch.setattr(level, "resolved_orders", lambda *a: (9, None))
    assert [c.resolved_orders for c in worn_orders(base, worn, extra)] == [6, 6]     # never more than unworn

    def fails(*a):
        raise ConvergenceError("LTCA phase 0.5", "no convergence")

    monkeypatch.setattr(level, "resolved_orders", fails)
    a, b = worn_orders(base, worn, extra)
    assert (a.resolved_orders, b.resolved_orders, b.harmonic_change) == (1, 1, None)
    assert "no convergence" in b.orders_check and a.orders_check is None
def test_warm_started_deviated_cycle_equals_the_cold_one(coarse_model, baseline_force, baseline_pair):
    """Each phase of a re-run on worn flanks started from the unworn loads (``mesh_cycle(start=)``) reaches
    the same contact solution as the cold start: the fixed point is unique (within its 1e-6 of the force)."""
    from femgear.physics.ltca.analysis import _start_loads, mesh_cycle
    from femgear.physics.ltca.contact import phase_points
    from femgear.physics.ltca.separation import path_deviation
    from femgear.scene.schema import Modifications

    mods = Modifications(tip_relief=3e-6, tip_relief_length=2.5e-3, crowning=5e-6)
    opts = {"n_phases": 8, "stagger": 0.0, "n_line": 8}
    unworn = mesh_cycle(coarse_model, baseline_force, mods, **opts)
    assert _start_loads(unworn, 3, phase_points(baseline_pair, 3 / 8, 0.0, 8), baseline_force) is not None
    u = path_positions(baseline_pair, 41)
    ramp = np.array([1.5e-6 * (u - u[0]) / np.ptp(u), 0.8e-6 * (u[-1] - u) / np.ptp(u)])
    extra = path_deviation(baseline_pair, u, ramp)
    cold = mesh_cycle(coarse_model, baseline_force, mods, extra=extra, **opts)
    warm = mesh_cycle(coarse_model, baseline_force, mods, extra=extra, start=unworn, **opts)
    assert np.max(np.abs(warm.lte - cold.lte)) < 1e-5 * np.max(np.abs(cold.lte))
    for side in ("left", "right"):
        a, b = getattr(warm, f"k_secant_{side}"), getattr(cold, f"k_secant_{side}")
        assert np.max(np.abs(a - b)) < 1e-5 * np.max(b)
    assert np.max(np.abs(warm.lte - unworn.lte)) > 1e-3 * np.max(np.abs(unworn.lte))      # the ramp did matter
