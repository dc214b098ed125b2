"""``numerics.body_elements = "p2-bending"``: quadratic elements in the loaded tooth and the rim of the LTCA bodies.

The zone, the cache key and the estimate are checked fast; the LTCA of the baseline with it is a
slow test: a validation (it is more compliant than P1 at a finer level, as P1's stiff bending
predicts) and a named regression band of the measured mean stiffness (docs/cost.md).
"""

from __future__ import annotations

import numpy as np
import pytest

from femgear.physics.ltca.compliance import BENDING, RIM_DEPTH, ZONE_DEPTH, bending_elements, build_estimate, cache_path
from femgear.physics.mesh.segment import default_spec, helix_frame, member_body


@pytest.fixture(scope="module")
def pinion_body(baseline_pair):
    spec = default_spec(baseline_pair, 1, 0, r_bore=0.010)      # the baseline's 20 mm shaft
    return spec, member_body(baseline_pair, 1, spec)


def test_zone_is_the_loaded_tooth_and_the_rim(baseline_pair, pinion_body):
    spec, mesh = pinion_body
    zone = bending_elements(mesh, baseline_pair, 1, spec)
    c = mesh.p[:, mesh.t].mean(axis=1)
    th = helix_frame(baseline_pair, 1, spec).theta(c[2])
    sx, sy = np.cos(th) * c[0] + np.sin(th) * c[1], -np.sin(th) * c[0] + np.cos(th) * c[1]
    r, m = np.hypot(sx, sy), baseline_pair.m_n
    rf = baseline_pair.rf1
    in_tooth = zone & (r > rf - ZONE_DEPTH * m)
    assert in_tooth.any() and np.all(c[2, in_tooth] <= baseline_pair.b)          # the left (loaded) helix only
    assert np.all(np.abs(np.arctan2(sx[in_tooth], sy[in_tooth])) < np.pi / baseline_pair.z1)
    assert (r < rf - RIM_DEPTH * m).sum() > 1000 and np.all(zone[r < rf - RIM_DEPTH * m])   # the whole rim
    other_teeth = (r > rf - ZONE_DEPTH * m) & (np.abs(np.arctan2(sx, sy)) > 1.5 * 2 * np.pi / baseline_pair.z1)
    assert other_teeth.any() and not zone[other_teeth].any()
    assert 0.1 < zone.mean() < 0.6


def test_the_bending_body_has_its_own_cache_key_and_a_larger_estimate(baseline_pair):
    spec = default_spec(baseline_pair, 1, 1)
    assert cache_path(baseline_pair, 1, spec, 210e9, 0.3, BENDING) != cache_path(baseline_pair, 1, spec, 210e9, 0.3, 1)
    p1, p2 = build_estimate(baseline_pair, 1, spec, 1), build_estimate(baseline_pair, 1, spec, BENDING)
    assert 1.3 * p1.dofs < p2.dofs < 3.0 * p1.dofs and p2.memory_bytes > p1.memory_bytes
    assert "p2-bending" in p2.stage


def test_unknown_order_is_refused(baseline_pair):
    from femgear.physics.ltca.compliance import member_compliance

    with pytest.raises(ValueError, match="order"):
        member_compliance(baseline_pair, 1, default_spec(baseline_pair, 1, 0), 210e9, 0.3, order=3, cache=False)


@pytest.mark.slow
def test_baseline_ltca_with_bending_elements(tmp_path, monkeypatch):
    """Validation: P1's bending is stiff, so the p2-bending bodies at level 0 are more compliant than P1 at level 3
    (k mean 6.99e8 N/m, docs/cost.md).  Regression: k mean 6.859e8 N/m and LTE p-p 0.4838 µm (26 Nov 2026,
    ``python studies/benchmarks/cost.py --pairs baseline --levels 0 --elements p2-bending``), ±0.5 %."""
    from femgear.case import build_case
    from femgear.levels import stiffness
    from femgear.scene import load_scene
    from tests.conftest import BASELINE

    monkeypatch.setenv("FEMGEAR_CACHE", str(tmp_path))
    scene = load_scene(BASELINE, ["numerics.body_level=0", 'numerics.body_elements="p2-bending"'])
    ms = stiffness.of(build_case(scene), "ltca")
    assert ms.mean < 6.9869e8                                   # P1 at level 3 (docs/cost.md's level table)
    assert ms.mean == pytest.approx(6.859e8, rel=5e-3)
    assert ms.ltca.lte_peak_to_peak * 1e6 == pytest.approx(0.4838, rel=5e-3)
