"""The driver's last stages of a run: what the writers show, computed here so that the edge computes nothing.

:func:`derived_fields` completes a :class:`femgear.results.RunResult` of :func:`femgear.pipeline.run_case`
with

- ``figures``: the ISO 6336-2 pitting rating, the ISO 6336-1 stiffness, Blok's flash temperature and the
  mesh power loss, all with the run's own μ (:func:`femgear.rate.contact_figures`);
- ``body``: with ``thermal = "fe"``, the FE gear sections of both members at the run's flank and shaft
  temperature rises (:func:`body_sections`);
- ``ltca_maps``: with the ``ltca`` stiffness level, the pressure and load maps of its cycle on the loaded
  flanks of both members in mesh (:func:`ltca_maps`);
- ``housing``: with a ``[housing]`` table, the housing layer's outputs (:func:`housing_fields`).
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from femgear.case import Case
from femgear.physics.body.fields import BodySection
from femgear.physics.ltca.maps import LoadMaps
from femgear.rate import contact_figures
from femgear.results import RunResult


def derived_fields(result: RunResult) -> RunResult:
    """``result`` with its ``figures``, ``body`` and ``ltca_maps`` fields."""
    case, t = result.case, result.tribology
    figures = contact_figures(case, result.contact, t.friction_coefficient, case.path.u, case.levels.lubrication,
                              result.rating)
    return replace(result, figures=figures, body=body_sections(case, t.flank_temperature_rise),
                   ltca_maps=ltca_maps(result), housing=housing_fields(result),
                   static_bearing_loads=static_bearings(case, result.stiffness) if result.coupled is None else None)


def static_bearings(case: Case, stiffness) -> np.ndarray:
    """(4, 3) loads of the bearing stations at the static load [N]: the ``lumped`` rotor model of the scene's
    mounting (bearing stations, thrust bearing) with the run's mesh stiffness and no friction
    (:func:`femgear.system.dynamics.bearings.static_bearing_loads`; the loads are statically determinate)."""
    from femgear.system.dynamics import build_model
    from femgear.system.dynamics.bearings import static_bearing_loads

    return static_bearing_loads(build_model(case, "lumped", stiffness=stiffness, friction=0.0,
                                            rigid_housing=True))


def body_sections(case: Case, flank_rise: float) -> tuple[BodySection, BodySection] | None:
    """``thermal = "fe"``: the FE gear sections of pinion and gear at the bulk flank rise ``flank_rise`` [K] and the
    scene's shaft rise (the coupling keeps only the flank deviation, from unit responses: the fields are solved
    once more here); None for other thermal levels."""
    if not case.levels.spec("thermal").sections:
        return None
    from femgear.physics.body.fields import section_fields
    from femgear.physics.body.thermal import gear_thermo_elastic

    m = case.material
    sections = []
    for member, bore in ((1, case.bore_radii[0]), (2, case.bore_radii[1])):
        fe = gear_thermo_elastic(case.pair, member, flank_rise, case.thermal.shaft_temperature_rise,
                                 m.thermal_expansion, m.youngs_modulus, m.poisson_ratio, m.conductivity, bore,
                                 case.thermal.mesh_size)
        sections.append(section_fields(fe, member, m.youngs_modulus, m.poisson_ratio, m.thermal_expansion))
    return tuple(sections)


def ltca_maps(result: RunResult) -> LoadMaps | None:
    """The maps of the ``ltca`` stiffness level's cycle (new flanks with the scene's modifications, the operating point's
    pinion torque;
    ``w_worst`` at the phase of the largest pressure); None for other stiffness levels."""
    cycle = None if result.stiffness is None else result.stiffness.ltca
    ltca = None if cycle is None else cycle.result
    if ltca is None or not ltca.line_load:
        return None
    from femgear.physics.ltca.maps import load_maps
    from femgear.physics.ltca.te import pressure_peak

    case, te = result.case, result.transmission_error
    m = case.material
    worst = te.worst_phase if te is not None else pressure_peak(ltca, case.pair, m.youngs_modulus, m.poisson_ratio)[1]
    return load_maps(ltca, case.pair, m.youngs_modulus, m.poisson_ratio, case.operating.pinion_torque, worst,
                     case.groove_width, case.stagger)


def housing_fields(result: RunResult):
    """The :class:`femgear.system.dynamics.housing_result.HousingResult` of a case with ``[housing]`` (None
    without): the order sweep over ``housing.speed_range``, the operating point (from the dynamics run where the
    case has one, else from the linear response of the case's model) and the FE housing's deflection shape."""
    from femgear.levels import housing as housing_levels

    case = result.case
    layer = housing_levels.of(case)
    if layer is None:
        return None
    import numpy as np

    from femgear.system.dynamics import build_model
    from femgear.system.dynamics.housing_result import housing_result

    h, op = case.housing, case.scene.operating
    to_pinion = case.operating.pinion_rpm / op.speed_rpm
    lo, hi = (0.1 * op.speed_rpm, 1.5 * op.speed_rpm) if h.speed_range is None else h.speed_range
    run = None if result.coupled is None else result.coupled.state.dynamics
    model = build_model(case) if run is None else run.model
    ods = ((op.speed_rpm if h.ods_speed_rpm is None else h.ods_speed_rpm) * to_pinion, h.ods_order)
    return housing_result(model, layer, np.linspace(lo, hi, h.speed_points) * to_pinion, h.orders, run, ods,
                          h.air_impedance)


__all__ = ["body_sections", "derived_fields", "housing_fields", "ltca_maps"]
