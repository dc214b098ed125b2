"""The REXS attribute ids femgear reads and writes: a small table derived from the REXS 1.4 database.

Source: the REXS attribute database ``models/rexs_model_1.{0..4}_en.xml`` of the public repository
BearinxSimulationSuite/REXSapi (Apache-2.0, commit 1ea5832519a24e017acc78ca045b5db0a0a7fec1), as published
by FVA e.V. for REXS (https://www.rexs.info).  Only the component/attribute pairs that femgear maps are
listed, each with its unit and value type in REXS 1.4 and the first version whose database maps the
attribute to that component (under the component's name of that version, see
:data:`COMPONENT_RENAMES`).

Version differences that matter here (from comparing the five database files):

- REXS 1.0–1.2 call the flank component ``flank_geometry`` and the per-gear stage data
  ``stage_gear_data``; 1.3 and 1.4 call them ``cylindrical_gear_flank`` and
  ``cylindrical_stage_gear_data``.
- REXS 1.0–1.1 declare angles in the unit ``°``; 1.2–1.4 in ``deg``.
- None of the attribute ids femgear maps was renamed between 1.0 and 1.4 (attributes were
  added: the modifications in 1.2, ``mass_of_component`` and the lubricant's
  ``pressure_viscosity_coefficient_at_38_degrees_celsius`` in 1.3, the stage's ``operating_viscosity``
  in 1.4).

Attributes whose id starts with ``custom_`` are custom attributes (REXS convention); femgear's own
are listed in :data:`CUSTOM` (``custom_femgear_*``): what a femgear scene holds and REXS has no id for.
"""

from __future__ import annotations

#: version of the REXS database the table was taken from, and the versions femgear reads
DATABASE_VERSION = "1.4"
VERSIONS = ("1.0", "1.1", "1.2", "1.3", "1.4")

#: component types renamed after REXS 1.2 (old name -> 1.4 name)
COMPONENT_RENAMES = {"flank_geometry": "cylindrical_gear_flank", "stage_gear_data": "cylindrical_stage_gear_data"}
#: unit spellings of older versions (old -> 1.4)
UNIT_RENAMES = {"°": "deg"}

#: (component type, attribute id) -> (unit, value type, first version), REXS 1.4 spelling
ATTRIBUTES: dict[tuple[str, str], tuple[str, str, str]] = {
    # cylindrical_gear
    ("cylindrical_gear", "normal_module"): ("mm", "floating_point", "1.0"),
    ("cylindrical_gear", "number_of_teeth"): ("none", "integer", "1.0"),
    ("cylindrical_gear", "helix_angle_reference_diameter"): ("deg", "floating_point", "1.0"),  # older units ['°']
    ("cylindrical_gear", "face_width"): ("mm", "floating_point", "1.0"),
    ("cylindrical_gear", "tip_diameter"): ("mm", "floating_point", "1.0"),
    ("cylindrical_gear", "root_diameter"): ("mm", "floating_point", "1.2"),
    ("cylindrical_gear", "reference_circle_diameter"): ("mm", "floating_point", "1.1"),
    ("cylindrical_gear", "inner_diameter"): ("mm", "floating_point", "1.1"),
    ("cylindrical_gear", "mass_of_component"): ("kg", "floating_point", "1.3"),
    ("cylindrical_gear", "u_coordinate_on_shaft"): ("mm", "floating_point", "1.0"),
    ("cylindrical_gear", "rotational_speed"): ("1 / min", "floating_point", "1.0"),
    ("cylindrical_gear", "averaged_peak_to_valley_height_flank"): ("mum", "floating_point", "1.3"),
    # cylindrical_gear_flank
    ("cylindrical_gear_flank", "addendum_modification_coefficient"): ("none", "floating_point", "1.0"),
    ("cylindrical_gear_flank", "normal_pressure_angle"): ("deg", "floating_point", "1.0"),  # older units ['°']
    ("cylindrical_gear_flank", "addendum_coefficient_basic_profile"): ("none", "floating_point", "1.0"),
    # cylindrical_stage
    ("cylindrical_stage", "center_distance"): ("mm", "floating_point", "1.0"),
    ("cylindrical_stage", "gear_ratio"): ("none", "floating_point", "1.1"),
    ("cylindrical_stage", "common_face_width"): ("mm", "floating_point", "1.1"),
    ("cylindrical_stage", "minimum_normal_backlash"): ("mm", "floating_point", "1.2"),
    ("cylindrical_stage", "maximum_normal_backlash"): ("mm", "floating_point", "1.2"),
    ("cylindrical_stage", "operating_viscosity"): ("mm^2 / s", "floating_point", "1.4"),
    ("cylindrical_stage", "temperature_lubricant"): ("C", "floating_point", "1.3"),
    ("cylindrical_stage", "radial_contact_ratio"): ("none", "floating_point", "1.1"),
    ("cylindrical_stage", "overlap_contact_ratio"): ("none", "floating_point", "1.1"),
    ("cylindrical_stage", "total_contact_ratio"): ("none", "floating_point", "1.3"),
    # cylindrical_stage_gear_data
    ("cylindrical_stage_gear_data", "torque"): ("N m", "floating_point", "1.1"),
    ("cylindrical_stage_gear_data", "is_driving_gear"): ("none", "boolean", "1.0"),
    ("cylindrical_stage_gear_data", "power_for_rotational_speed"): ("W", "floating_point", "1.1"),
    # material
    ("material", "elastic_modulus"): ("N / mm^2", "floating_point", "1.0"),
    ("material", "poisson_ratio"): ("none", "floating_point", "1.0"),
    ("material", "density"): ("kg / dm^3", "floating_point", "1.0"),
    ("material", "thermal_capacity"): ("J / (kg K)", "floating_point", "1.0"),
    ("material", "thermal_conductivity"): ("W / (m K)", "floating_point", "1.0"),
    ("material", "thermal_expansion_coefficient_plus"): ("1e-6 / C", "floating_point", "1.0"),
    ("material", "surface_hardness_vickers"): ("HV", "floating_point", "1.0"),
    # lubricant
    ("lubricant", "density_at_15_degree_celsius"): ("kg / dm^3", "floating_point", "1.0"),
    ("lubricant", "viscosity_at_40_degree_celsius"): ("mm^2 / s", "floating_point", "1.0"),
    ("lubricant", "viscosity_at_100_degree_celsius"): ("mm^2 / s", "floating_point", "1.0"),
    ("lubricant", "pressure_viscosity_coefficient_at_38_degrees_celsius"): ("mm^2 / N", "floating_point", "1.3"),
    # rack_shaped_tool
    ("rack_shaped_tool", "normal_module"): ("mm", "floating_point", "1.0"),
    ("rack_shaped_tool", "normal_pressure_angle"): ("deg", "floating_point", "1.0"),  # older units ['°']
    ("rack_shaped_tool", "addendum_coefficient_reference_profile"): ("none", "floating_point", "1.0"),
    ("rack_shaped_tool", "tip_radius_factor"): ("none", "floating_point", "1.0"),
    # tip_relief
    ("tip_relief", "tip_relief_depth"): ("mm", "floating_point", "1.2"),
    ("tip_relief", "tip_relief_datum_length"): ("mm", "floating_point", "1.2"),
    ("tip_relief", "shape_of_relief"): ("none", "enum", "1.2"),
    # root_relief
    ("root_relief", "root_relief_depth"): ("mm", "floating_point", "1.2"),
    ("root_relief", "root_relief_datum_length"): ("mm", "floating_point", "1.2"),
    ("root_relief", "shape_of_relief"): ("none", "enum", "1.2"),
    # helix_crowning
    ("helix_crowning", "helix_crowning_amount_datum_face"): ("mm", "floating_point", "1.2"),
    ("helix_crowning", "helix_crowning_amount_non_datum_face"): ("mm", "floating_point", "1.2"),
    # helix_slope
    ("helix_slope", "helix_slope"): ("mm", "floating_point", "1.2"),
    # end_relief_datum_face
    ("end_relief_datum_face", "end_relief_depth_datum_face"): ("mm", "floating_point", "1.2"),
    ("end_relief_datum_face", "end_relief_length_datum_face"): ("mm", "floating_point", "1.2"),
    # end_relief_non_datum_face
    ("end_relief_non_datum_face", "end_relief_depth_non_datum_face"): ("mm", "floating_point", "1.2"),
    ("end_relief_non_datum_face", "end_relief_length_non_datum_face"): ("mm", "floating_point", "1.2"),
    # concept_bearing
    ("concept_bearing", "radial_stiffness"): ("N / m", "floating_point", "1.0"),
    ("concept_bearing", "axial_stiffness"): ("N / m", "floating_point", "1.0"),
    ("concept_bearing", "u_coordinate_on_shaft_inner_side"): ("mm", "floating_point", "1.0"),
    # shaft
    ("shaft", "rotational_speed"): ("1 / min", "floating_point", "1.0"),
    # gear_casing
    ("gear_casing", "temperature_lubricant"): ("C", "floating_point", "1.0"),
}

#: femgear's custom attributes: (component type, attribute id) -> (unit, value type)
CUSTOM: dict[tuple[str, str], tuple[str, str]] = {
    ("cylindrical_gear", "custom_femgear_moment_of_inertia"): ("kg m^2", "floating_point"),
    ("cylindrical_gear", "custom_femgear_support_stiffness"): ("N / m", "floating_point"),
    ("cylindrical_gear", "custom_femgear_support_damping"): ("N s / m", "floating_point"),
    ("cylindrical_gear", "custom_femgear_axial_stiffness"): ("N / m", "floating_point"),
    ("cylindrical_gear", "custom_femgear_axial_damping"): ("N s / m", "floating_point"),
    ("cylindrical_gear", "custom_femgear_bearing_span"): ("mm", "floating_point"),
    ("cylindrical_gear", "custom_femgear_shaft_diameter"): ("mm", "floating_point"),
    ("cylindrical_gear", "custom_femgear_eccentricity"): ("mum", "floating_point"),
    ("cylindrical_gear", "custom_femgear_eccentricity_phase"): ("deg", "floating_point"),
    ("cylindrical_gear", "custom_femgear_unbalance"): ("kg m", "floating_point"),
    ("cylindrical_stage", "custom_femgear_stagger"): ("none", "floating_point"),
    ("cylindrical_stage", "custom_femgear_groove_width"): ("mm", "floating_point"),
    ("cylindrical_stage", "custom_femgear_loop_stiffness"): ("N m / rad", "floating_point"),
    ("lubricant", "custom_femgear_specific_heat"): ("J / (kg K)", "floating_point"),
    ("lubricant", "custom_femgear_thermal_conductivity"): ("W / (m K)", "floating_point"),
    ("lubricant", "custom_femgear_temperature_viscosity_coefficient"): ("1 / K", "floating_point"),
    ("lubricant", "custom_femgear_thermal_expansion"): ("1 / K", "floating_point"),
    ("lubricant", "custom_femgear_eyring_stress"): ("N / mm^2", "floating_point"),
    ("lubricant", "custom_femgear_limiting_shear_coefficient"): ("none", "floating_point"),
    ("lubricant", "custom_femgear_viscosity_reference_temperature"): ("C", "floating_point"),
    ("lubricant", "custom_femgear_viscosity_at_reference_temperature"): ("mPa s", "floating_point"),
    ("lubricant", "custom_femgear_pressure_viscosity_at_reference_temperature"): ("mm^2 / N", "floating_point"),
    # the [rating] table (femgear.rexs.ratings) on each cylindrical_stage, its per-member lists on the gears
    **{("cylindrical_stage", f"custom_femgear_{key}"): spec_ for key, spec_ in {
        "application_factor": ("none", "floating_point"), "dynamic_factor": ("none", "floating_point"),
        "face_load_factor": ("none", "floating_point"), "transverse_load_factor": ("none", "floating_point"),
        "contact_stress_limit": ("N / mm^2", "floating_point"), "min_safety_factor": ("none", "floating_point"),
        "life_hours": ("h", "floating_point"), "rating_oil_viscosity_40": ("mm^2 / s", "floating_point"),
        "work_hardening_factor": ("none", "floating_point"), "size_factor": ("none", "floating_point"),
        "bending_stress_limit": ("N / mm^2", "floating_point"),
        "bending_min_safety_factor": ("none", "floating_point"), "finishing": ("none", "string"),
        "oil_type": ("none", "string"), "scuffing_load_stage": ("none", "floating_point"),
        "micropitting_load_stage": ("none", "floating_point"), "lubrication_method": ("none", "string"),
        "structural_factor": ("none", "floating_point"), "fillet_fe": ("none", "boolean"),
        "load_factors": ("none", "string"), "accuracy_grade": ("none", "integer"),
        # the [physics] levels
        **{f"physics_{level}": ("none", "string")
           for level in ("stiffness", "lubrication", "thermal", "wear", "dynamics", "coupling")},
    }.items()},
    ("cylindrical_gear", "custom_femgear_root_roughness_rz"): ("mum", "floating_point"),
    ("cylindrical_gear", "custom_femgear_roughness_ra"): ("mum", "floating_point"),
}


def spec(component: str, attribute: str) -> tuple[str, str]:
    """(unit, value type) of a mapped attribute in REXS 1.4 (femgear's custom ones included)."""
    if (component, attribute) in ATTRIBUTES:
        return ATTRIBUTES[component, attribute][:2]
    return CUSTOM[component, attribute]


#: REXS 1.4 component types femgear reads or writes
COMPONENT_TYPES = frozenset({
    "gear_unit", "gear_casing", "shaft", "concept_bearing", "cylindrical_stage", "cylindrical_gear",
    "cylindrical_gear_flank", "cylindrical_stage_gear_data", "cylindrical_gear_manufacturing_settings",
    "rack_shaped_tool", "material", "lubricant", "tip_relief", "root_relief", "helix_crowning", "helix_slope",
    "end_relief_datum_face", "end_relief_non_datum_face", "planetary_stage", "bevel_stage", "worm_stage"})
#: REXS 1.4 relation types femgear writes, with the roles each takes
RELATIONS = {"assembly": {"assembly", "part"}, "ordered_assembly": {"assembly", "part"},
             "reference": {"origin", "referenced"}, "stage": {"stage", "gear_1", "gear_2"},
             "stage_gear_data": {"stage", "gear", "stage_gear_data"}, "flank": {"gear", "left", "right"},
             "manufacturing_step": {"workpiece", "tool", "manufacturing_settings"}}


def id_problems(model) -> list[str]:
    """Where a model departs from the REXS 1.4 ids and units of this table (empty: none).

    Checks every component type, every attribute id and its declared unit (REXS attributes against
    :data:`ATTRIBUTES`, ``custom_`` ones against :data:`CUSTOM`), the value types of numbers and
    booleans, and every relation type and role against :data:`RELATIONS`.
    """
    out = []
    for comp in model.components.values():
        if comp.type not in COMPONENT_TYPES:
            out.append(f"component {comp.id}: type {comp.type!r} is not a REXS 1.4 type femgear knows")
        for attr in comp.attributes.values():
            key = (comp.type, attr.id)
            known = ATTRIBUTES.get(key, (None, None, None))[:2] if not attr.id.startswith("custom_") else \
                CUSTOM.get(key, (None, None))
            if known[0] is None:
                out.append(f"component {comp.id} ({comp.type}): attribute {attr.id!r} is not in the 1.4 table")
                continue
            unit, kind = known
            if (attr.unit or "none") != unit:
                out.append(f"component {comp.id} ({comp.type}) attribute {attr.id}: unit {attr.unit!r}, 1.4 has {unit!r}")
            expected = {"floating_point": float, "integer": int, "boolean": bool, "enum": str, "string": str}[kind]
            if type(attr.value) is not expected:
                out.append(f"component {comp.id} ({comp.type}) attribute {attr.id}: {attr.value!r} is not {kind}")
    for rel in model.relations:
        roles = RELATIONS.get(rel.type)
        if roles is None:
            out.append(f"relation {rel.id}: type {rel.type!r} is not one femgear writes")
        elif any(r.role not in roles for r in rel.refs):
            out.append(f"relation {rel.id} ({rel.type}): roles {[r.role for r in rel.refs]} not in {sorted(roles)}")
    return out
