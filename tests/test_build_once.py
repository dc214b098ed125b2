"""Build once (issue 27): one run of the baseline binds the gear pair, the operating point (with F_bn)
and the path once; every sub-model takes them from the Case.

Instrumented run: the binding (:func:`femgear.case.pair.pair_from_scene`), every :class:`GearPair` of the
same gear constructed outside it (``dataclasses.replace`` included; the ratings' FZG reference gears are
other gears), :func:`femgear.case.operating_point` and every :class:`PathKinematics` (the path: radii and
velocities along the line of action) are counted from the loaded scene to the finished
:class:`femgear.results.RunResult`.
"""

from __future__ import annotations

import pytest

import femgear.case as case_module
from femgear.physics.geometry import GearPair, PathKinematics
from femgear.pipeline import run_case
from femgear.scene import load_scene


@pytest.fixture
def counts(monkeypatch):
    """Counters of the constructions, live while the test runs."""
    n = {"bindings": 0, "pairs_outside_binding": 0, "operating_points": 0, "paths": 0}
    depth, bound = [0], []
    bind, operating_point = case_module.pair_from_scene, case_module.operating_point
    pair_init, path_init = GearPair.__init__, PathKinematics.__init__

    def counting_bind(scene):
        n["bindings"] += 1
        depth[0] += 1
        try:
            bound.append(bind(scene))
            return bound[-1]
        finally:
            depth[0] -= 1

    def counting_pair(self, *args, **kwargs):
        pair_init(self, *args, **kwargs)
        n["pairs_outside_binding"] += depth[0] == 0 and any(self == pair for pair in bound)

    def counting_operating_point(*args, **kwargs):
        n["operating_points"] += 1
        return operating_point(*args, **kwargs)

    def counting_path(self, *args, **kwargs):
        n["paths"] += 1
        path_init(self, *args, **kwargs)

    monkeypatch.setattr(case_module, "pair_from_scene", counting_bind)
    monkeypatch.setattr(case_module, "operating_point", counting_operating_point)
    monkeypatch.setattr(GearPair, "__init__", counting_pair)
    monkeypatch.setattr(PathKinematics, "__init__", counting_path)
    return n


def _run(path, overrides=()):
    return run_case(case_module.build_case(load_scene(path, list(overrides))))


def test_the_counters_see_a_second_binding(baseline_path, counts):
    """The instrument itself: binding twice counts twice, and a pair or a path made by hand is seen."""
    case = case_module.build_case(load_scene(baseline_path))
    case_module.build_case(case.scene)
    from dataclasses import replace

    from femgear.physics.geometry import kinematics

    replace(case.pair)
    replace(case.pair, b=0.5 * case.pair.b)       # another gear: not counted

    kinematics(case.pair, case.path.u, 1.0)
    assert counts == {"bindings": 2, "pairs_outside_binding": 1, "operating_points": 2, "paths": 3}


def test_the_baseline_run_builds_the_pair_the_operating_point_and_the_path_once(baseline_path, counts):
    """Default levels (pem stiffness, formula lubrication, analytic thermal, archard wear, lumped dynamics,
    bidirectional coupling): one binding, no other pair, one operating point, one path."""
    result = _run(baseline_path)
    assert result.coupled is not None and result.tribology.wear is not None      # the run used them all
    assert counts == {"bindings": 1, "pairs_outside_binding": 0, "operating_points": 1, "paths": 1}


@pytest.mark.slow     # ~45 s on a shared machine (the LTCA model's body solve)
def test_a_quasi_static_ltca_run_builds_them_once(baseline_path, counts):
    """The ``ltca`` stiffness (coarse: body level 0, 16 phases) without dynamics: the LTCA cycle, the wear with
    its load sharing and the static tribology take the case's pair and path."""
    result = _run(baseline_path, ['physics.stiffness="ltca"', 'physics.dynamics="none"', 'physics.coupling="one-way"', "numerics.body_level=0",
                                  "stiffness.n_positions=16"])
    assert result.stiffness.level == "ltca" and result.tribology.wear is not None
    assert counts == {"bindings": 1, "pairs_outside_binding": 0, "operating_points": 1, "paths": 1}
