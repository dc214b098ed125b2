"""The ``transmission_error`` section of a run's summary (an ``ltca`` stiffness) is in the result schema
(femgear.edge.io.summary_schema; the other sections: tests/io/test_summary_schema.py)."""

from __future__ import annotations

import dataclasses

from femgear.physics.ltca.cycle import LTCACycle


def test_the_transmission_error_section_is_in_the_schema(coarse_model, baseline_force, baseline_scene):
    from femgear.case import build_case
    from femgear.edge.io.run import run_summary
    from femgear.physics.ltca.analysis import mesh_cycle
    from femgear.pipeline import run_case, transmission_error
    from tests.io.test_summary_schema import conforms

    scene = baseline_scene.model_copy(update={"physics": baseline_scene.physics.model_copy(update={
        "dynamics": "none", "coupling": "one-way", "lubrication": "constant", "thermal": "none", "wear": "none",
        "stiffness": "iso6336"})})
    case = build_case(scene)
    result = run_case(case)
    r = mesh_cycle(coarse_model, baseline_force, None, n_phases=16, n_line=8)
    ms = dataclasses.replace(result.stiffness, level="ltca", ltca=LTCACycle.from_result(r, resolved_orders=7))
    result = dataclasses.replace(result, stiffness=ms, transmission_error=transmission_error(case, ms))
    seen = conforms(run_summary(result))
    assert "transmission_error.lte_peak_to_peak" in seen and "transmission_error.units" in seen
