"""The scene schema: frozen, validated models of a scene file (all units SI).

Every key is documented here, with its unit.  Angles are the one exception to SI in
the file (``*_deg`` keys, degrees, as engineers write them); they are converted to
radians once, by :mod:`femgear.physics.geometry`.  Unknown keys are errors, so a typo never
goes unnoticed.

Models are grouped by lifetime (ROSS habit): the gear pair, material and oil stay
fixed for a study; the operating point and errors change per load case.
"""

from __future__ import annotations

from typing import Annotated, Any, ClassVar, Literal

from pydantic import BaseModel, ConfigDict, Field, ValidationInfo, field_validator, model_validator

from femgear.errors import SceneError
from femgear.scene.levels import CATALOGUE, LEVELS, LevelSpec, check_level

Pos = Annotated[float, Field(gt=0)]
NonNeg = Annotated[float, Field(ge=0)]


class _Frozen(BaseModel):
    """Strict: no str -> number, no bool -> number, no float -> int; finite numbers only."""

    model_config = ConfigDict(frozen=True, extra="forbid", strict=True, allow_inf_nan=False)


class Meta(_Frozen):
    """``[meta]``: a name (used for output folders) and a free description."""

    name: str = Field(
        "scene", min_length=1, max_length=100, pattern=r"^[A-Za-z0-9_][A-Za-z0-9_ .+-]*$",
        description="name of the load case and of its output folder: letters, digits, space, _ . + - "
                    "(no path separators, no leading dot)")
    description: str = Field("", description="free text describing the load case (copied into results.json)")


class Pair(_Frozen):
    """``[pair]``: the gear pair, data shared by both members.

    ``kind``: a double-helical pair (the default) is two helical pairs of opposite hand
    side by side ("left" and "right" helix), ``face_width`` the width of ONE helix; a
    single-helical pair is one helix of width ``face_width``; a spur pair has
    ``helix_angle_deg = 0``.  Consistency (kind vs helix angle, thrust bearings of a
    single helix, basic rack vs coefficients, tip diameters and centre distance vs
    profile shifts) is checked by :mod:`femgear.case.pair`.
    """

    kind: Literal["double-helical", "single-helical", "spur"] = Field(
        "double-helical",
        description="double-helical (two opposite-hand helices of width face_width each), single-helical "
                    "(one helix; the unbalanced axial force needs pinion/gear.axial_stiffness) or spur "
                    "(helix_angle_deg = 0)")
    normal_module: Pos = Field(description="normal module m_n [m]")
    normal_pressure_angle_deg: float = Field(20.0, gt=0, lt=45, description="normal pressure angle α_n [deg]")
    helix_angle_deg: float = Field(
        description="helix angle β at the reference circle [deg]; 0 only for kind = 'spur'", ge=0, lt=45)
    face_width: Pos = Field(description="face width b of ONE helix [m]: a double-helical member of total width B with a groove g has "
                    "face_width = (B − g)/2; the contact width of a member pair is the smaller of the two members' widths")
    groove_width: NonNeg = Field(0.0, description="axial width of the central groove between the two helices of a double-helical member (0 for "
                    "single-helical and spur pairs) [m]")
    addendum_coeff: float = Field(1.0, gt=0, le=1.5, description="basic-rack addendum h_aP/m_n [-]")
    dedendum_coeff: float = Field(1.25, gt=0, le=1.8, description="basic-rack dedendum h_fP/m_n [-]")
    root_radius_coeff: float = Field(0.38, ge=0, le=0.6, description="basic-rack root radius ρ_fP/m_n [-]")
    basic_rack: Literal["A", "B", "C", "D"] | None = Field(
        None, description="ISO 53 basic-rack profile (A: h_fP 1.25, ρ_fP 0.38; B: 1.25, 0.30; C: 1.25, 0.25; "
                          "D: 1.40, 0.39; h_aP 1, α_n 20°); sets the three coefficients, which may then be omitted")
    centre_distance: Pos | None = Field(
        None, description="working centre distance a_w [m]; checked against the profile shifts (or, with "
                          "tip diameters, used to derive them)")
    tip_diameter_tolerance: NonNeg = Field(
        1.0e-4, description="how far a given pinion/gear.tip_diameter may lie outside what its profile shift gives, "
                            "d + 2 m_n (h_aP + x + k) with ISO 21771's tip shortening k m_n to d + 2 m_n (h_aP + x) "
                            "without it (a drawing's tolerance; the given diameter is the tip as made) [m]")
    backlash: NonNeg = Field(0.0, description="HALF the normal backlash, b0 = j_bn/2 [m]: the dead zone of the mesh deflection "
                    "along the normal line of action is |δ| ≤ b0, so the total free play between the drive and "
                    "the coast flanks is 2 b0 (the paper's 'half backlash' b; Kahraman & Singh 1990)")
    stagger: float = Field(
        0.0, ge=0, lt=1,
        description="offset of the right helix's mesh phase against the left one, as a fraction of the transverse "
                    "base pitch (0: teeth of both helices in line, apex; 0.5: half-pitch stagger) [-]",
    )


class Member(_Frozen):
    """``[pinion]`` / ``[gear]``: one member (both its helices) and its supports."""

    teeth: int = Field(ge=5, le=1000, description="number of teeth z [-]")
    profile_shift: float = Field(0.0, ge=-1.5, le=1.5, description="profile shift coefficient x [-]")
    tip_diameter: Pos | None = Field(
        None, description="tip diameter d_a as made [m]: the tip circle of the member; derives profile_shift if that "
                          "is not given, else lies within pair.tip_diameter_tolerance of what the shift gives")
    face_width: Pos | None = Field(
        None, description="this member's face width [m]; default pair.face_width; the contact width is the smaller")
    axial_stiffness: Pos | None = Field(
        None, description="axial (thrust) bearing stiffness of the member, total [N/m]; required for pair.kind = 'single-helical' "
                          "(its axial mesh force is not balanced), default support_stiffness otherwise")
    axial_damping: NonNeg | None = Field(None, description="axial (thrust) bearing damping of the member, total [N s/m]; default support_damping")
    mass: Pos = Field(description="mass of the gear body (both helices, rim, web, hub) WITHOUT the shaft [kg]: "
                                  "the timoshenko dynamics level adds the shaft's own mass from shaft_diameter and "
                                  "material.density between the bearings; the lumped level has a rigid massless "
                                  "shaft, so add the shaft's mass here for that level if it matters")
    inertia: Pos = Field(description="polar moment of inertia J of the gear body about its axis (both helices; "
                                     "without the shaft, as mass) [kg m^2]")
    bore_radius: NonNeg = Field(
        0.0, description="inner radius of the gear body, where it sits on the shaft (usually shaft_diameter/2) [m]: "
                         "the thermal models hold the bore at shaft_temperature_rise there, the FE bodies are "
                         "clamped there; the rim below the root circle must be at least 0.5 h_t (ISO 6336-3's limit, "
                         "h_t the tooth depth). 0 = no bore, the member is cut on its shaft (a pinion shaft, a solid "
                         "pinion): the analytic and FE thermal levels take half the root radius, the LTCA body is "
                         "clamped at half the shaft_diameter but at least 1.2 h_t below the root, the rating takes "
                         "no rim factor")
    support_stiffness: Pos = Field(
        description="bearing stiffness of the WHOLE member (the sum of its two bearings) in each direction x, y "
                    "and, without axial_stiffness, z [N/m]; each of the two bearings gets half")
    support_damping: NonNeg = Field(
        0.0, description="bearing damping of the WHOLE member (the sum of its two bearings) per direction, split "
                         "like support_stiffness [N s/m]")
    eccentricity: NonNeg = Field(0.0, description="geometric eccentricity e_r of the member: distance of its pitch-circle centre from its axis of "
                    "rotation [m]")
    eccentricity_phase_deg: float = Field(0.0, description="phase θ of the eccentricity at t = 0 [deg]")
    unbalance: NonNeg = Field(0.0, description="mass unbalance U = m·e (rotating force U Ω²) [kg m]")
    cumulative_pitch_error: NonNeg = Field(
        0.0, description="amplitude A of a once-per-revolution cumulative pitch deviation along the line of action: "
                         "tooth n sits A sin(2π n/z + φ) ahead (a sinusoidal pattern of ISO 1328's F_p = 2 A), seen "
                         "tooth by tooth in the mesh [m]")
    cumulative_pitch_phase_deg: float = Field(0.0, description="phase φ of the cumulative pitch deviation, at the tooth "
                                                               "in mesh at t = 0 [deg]")
    bearing_span: Pos = Field(0.10, description="axial distance between the member's two radial bearings (the shaft "
                                                "between them must be longer than the toothed face) [m]")
    face_offset: float = Field(
        0.0, description="axial position of the toothed face's centre (the mesh station; a double-helical pair's "
                         "groove centre) from the midpoint of the two bearings, towards the right bearing (+z) [m]: "
                         "0 = symmetric straddle; |face_offset| < (bearing_span − face)/2 straddle, "
                         "> (bearing_span + face)/2 overhung (both bearings on one side); a bearing under the "
                         "toothed face is refused")
    thrust_bearing: Literal["both", "left", "right"] = Field(
        "both", description="which radial bearing also carries the axial load (axial_stiffness, axial_damping): "
                            "'both' split equally (as a pair of angular-contact or tapered bearings), 'left' "
                            "(the bearing at −z, station <member>_L) or 'right' (+z) alone, the other floating "
                            "axially [-]")
    shaft_diameter: Pos = Field(0.040, description="diameter of the member's solid shaft [m]: the Timoshenko shaft elements between the bearings "
                    "(timoshenko dynamics level) and the LTCA body's bore when bore_radius = 0")


class Material(_Frozen):
    """``[material]``: the gear steel (both members)."""

    youngs_modulus: Pos = Field(description="Young's modulus E [Pa]")
    poisson_ratio: float = Field(gt=0, lt=0.5, description="Poisson's ratio ν [-]")
    density: Pos = Field(description="density ρ [kg/m^3]")
    specific_heat: Pos = Field(description="specific heat c [J/(kg K)]")
    conductivity: Pos = Field(description="thermal conductivity k [W/(m K)]")
    thermal_expansion: Pos = Field(description="linear expansion coefficient λ [1/K]")
    hardness: Pos = Field(6.0e9, description="flank hardness H of Archard's law (Vickers hardness as a pressure: HV 600 ≈ 6e9 Pa) [Pa]")


class Oil(_Frozen):
    """``[oil]``: the lubricant.  Viscosity data refer to ``reference_temperature``.  ``name`` picks an oil of
    femgear's library (``femgear oils``), which fills every key the table does not give."""

    name: str | None = Field(
        None, description="a named oil of femgear's library (femgear oils lists them with their sources: "
                          "mineral-vg32 … mineral-vg460, min100-fzg, fva3a, pao-vg100, pag-eo-po); it fills every oil key "
                          "not given here, at reference_temperature (default: operating.ambient_temperature); "
                          "None: the table's own values")
    viscosity: Pos = Field(description="dynamic viscosity η0 at ambient pressure and the reference temperature [Pa s] (kinematic "
                    "viscosity [mm²/s] × density [kg/m³] × 1e-6)")
    density: Pos = Field(description="density ρ0 at ambient pressure and the reference temperature [kg/m^3]")
    specific_heat: Pos = Field(description="specific heat c_f [J/(kg K)]")
    conductivity: Pos = Field(description="thermal conductivity k_f [W/(m K)]")
    pressure_viscosity: Pos = Field(description="pressure-viscosity coefficient α = ∂ln η/∂p at p = 0 and the REFERENCE temperature [1/Pa] "
                    "(typical mineral oils 1e-8 … 3e-8; 20 GPa⁻¹ = 2e-8): Barus' slope, from which the Roelands "
                    "pressure index z0 is taken")
    temperature_viscosity: NonNeg = Field(description="temperature-viscosity coefficient β_T = −∂ln η/∂T at p = 0 and the REFERENCE temperature "
                    "[1/K]: the local slope there, from which the Roelands temperature index S0 is taken (so the "
                    "law is exact at the reference and follows Roelands' shape away from it). From two datasheet "
                    "viscosities, ln(η(T1)/η(T2))/(T2 − T1) with T1 < T0 < T2 close to T0 is a fair estimate; the "
                    "40–100 °C secant underestimates the slope at 40 °C")
    reference_temperature: Pos | None = Field(
        None, description="temperature at which viscosity, density, pressure_viscosity and temperature_viscosity hold "
                    "[K]; default operating.ambient_temperature"
    )
    thermal_expansion: NonNeg = Field(6.5e-4, description="density-temperature coefficient ε: ρ = ρ0 (1 − ε (T − T0)) [1/K]")
    eyring_stress: Pos = Field(5.0e6, description="Eyring stress τ0 of the Ree–Eyring shear law of the traction [Pa]")
    limiting_shear_coeff: NonNeg = Field(
        0.0, description="limiting shear stress τ_L = Λ p as the coefficient Λ; 0 switches it off [-]"
    )


class Operating(_Frozen):
    """``[operating]``: the load case."""

    driver: Literal["pinion", "gear"] = Field("pinion", description="the driving member: speed_rpm and torque are given on it")
    speed_rpm: Pos = Field(description="rotational speed of the driving member [rev/min]")
    torque: Pos = Field(description="torque on the driving member, both helices together [N m]")
    ambient_temperature: Pos = Field(313.0, description="ambient and oil supply temperature [K] (313 K = 40 °C)")
    loop_stiffness: NonNeg = Field(
        0.0, description="torsional stiffness of a closed power loop (FZG rig), referred to the gear shaft; "
                         "0 = prescribed torques as in the paper [N m/rad]")


class Errors(_Frozen):
    """``[errors]``: transmission-error sources beside eccentricity (see ``[pinion]``)."""

    profile_error: NonNeg = Field(0.0, description="amplitude e_f of each mesh-frequency harmonic of the profile error, along the line of action [m]")
    profile_error_orders: int = Field(3, ge=1, le=10, description="number of mesh-frequency harmonics M [-]")
    profile_error_phase_deg: float = Field(0.0, description="phase φ of the profile error [deg]")
    random: NonNeg = Field(0.0, description="amplitude e_0 of the seeded random tooth-to-tooth error component, along the line of action [m]")
    seed: int = Field(0, ge=0, description="seed of the random component (same seed, same errors) [-]")


class Friction(_Frozen):
    """``[friction]``: the constant μ of ``physics.lubrication = "constant"``, the sliding-sign regularisation of
    the dynamics and the boundary friction of mixed lubrication."""

    coefficient: float = Field(0.05, ge=0, le=0.5, description="constant friction coefficient μ of the constant lubrication level [-]")
    regularisation_speed: Pos = Field(0.01, description="v_reg of the sliding sign tanh(v_s/v_reg) [m/s]")
    boundary_coefficient: float = Field(
        0.1, ge=0, le=0.5, description="boundary friction coefficient μ_b of asperity contacts (mixed lubrication, "
                                       "roughness.model = \"greenwood-tripp\") [-]")


class RoughnessPeak(_Frozen):
    """``[roughness.peak]``: the seed paper's single roughness peak (its sec. 3.1.2, eq. 22), a
    transverse ridge R = (A_b/2)[1 + cos(π(x − x0)/l_b)] for |x − x0| ≤ l_b, 0 elsewhere, on one flank.

    Heights count towards the other flank (a peak thins the film: h = h0 + g + v − R; the paper's
    eq. 23 writes + R_r, which with its eq. 22 would be a dent).  Film term of the EHL solvers
    (:mod:`femgear.physics.ehl.core.surface`, :mod:`femgear.physics.ehl.transient`).
    """

    amplitude: Pos = Field(description="peak height A_b [m]")
    wavelength: Pos = Field(description="the paper's wavelength l_b: half the base width of the peak [m]")
    x0: float = Field(0.0, description="position of the peak along the rolling direction, from the contact "
                                       "centre (at t = 0 when moving; negative = inlet side) [m]")
    member: Literal["pinion", "gear"] = Field("pinion", description="flank that carries the peak (the paper: pinion)")
    moving: bool = Field(False, description="true: the peak moves with its flank through the contact (transient "
                                            "Reynolds); false (the paper's model): fixed at x0 in the contact frame, "
                                            "steady")


class SyntheticSurface(_Frozen):
    """``[roughness.synthetic]``: a seeded Gaussian random surface on one flank (FFT filtering,
    :func:`femgear.physics.ehl.core.surface.random_surface`) for deterministic rough EHL.  Independent of
    ``roughness.ra``/``rq``, which feed the statistical (Greenwood–Tripp) mixed-lubrication model.
    """

    rq: Pos = Field(description="RMS height Rq of the synthetic surface [m]")
    correlation_length: Pos = Field(description="correlation length β: the ACF falls to 1/e at β [m]")
    acf: Literal["exponential", "gaussian"] = Field(
        "exponential", description="autocorrelation exp(−r/β) or exp(−(r/β)²)")
    seed: int = Field(0, ge=0, description="seed of the random generator (same seed, same surface) [-]")
    member: Literal["pinion", "gear"] = Field("pinion", description="flank that carries the surface")
    moving: bool = Field(True, description="the surface moves with its flank through the contact")


#: R_a of a flank by its finishing process [m] (typical values, docs/roughness.md)
FINISHING_RA = {"ground": 0.4e-6, "honed": 0.3e-6, "shaved": 0.8e-6, "hobbed": 1.6e-6}
Finishing = Literal["ground", "honed", "shaved", "hobbed"]
MemberPair = Annotated[list[Pos], Field(min_length=2, max_length=2)]


class SurfaceRoughness(_Frozen):
    """``[roughness]``: the one description of the flanks' roughness, read by the ratings (λ_GF, μ_mC) and the
    tribology (the Greenwood–Tripp asperity share of the mixed lubrication, λ).

    Per member R_a (``ra``) or R_q (``rq``), or both (then R_q/R_a must lie in 1…1.6; Gaussian heights:
    √(π/2) = 1.25); neither: R_a from ``finishing`` (default ground, R_a 0.4 µm).  The missing one of R_a, R_q
    follows the Gaussian ratio; the tribology takes the composite σ = √(R_q1² + R_q2²).  ``model = "smooth"``
    keeps the tribology's flanks smooth (full film; the seed paper's model) while the ratings still read the
    roughness.  The sub-tables ``[roughness.peak]`` (the paper's single peak) and ``[roughness.synthetic]`` (a
    seeded random surface) describe deterministic roughness for the EHL solvers; absent = none.  Until the next
    release the old keys keep working, each with a log line naming its new key: ``rating.roughness_ra`` (now
    ``roughness.ra``), ``rating.finishing`` (``roughness.finishing``) and one number ``roughness.rq`` (the
    composite σ; 0: smooth, now ``roughness.model = "smooth"``).
    """

    ra: MemberPair | None = Field(
        None, description="arithmetic mean roughness R_a of the pinion and gear flanks, [R_a1, R_a2] [m]")
    rq: MemberPair | NonNeg | None = Field(
        None, description="RMS roughness R_q of the pinion and gear flanks, [R_q1, R_q2] [m]; one number is the old "
                          "composite σ = √(R_q1² + R_q2²) (deprecated: give the pair; 0 = smooth flanks)")
    finishing: Finishing | None = Field(
        None, description="flank finishing, which sets R_a of both flanks when neither ra nor rq is given (ground 0.4, "
                          "honed 0.3, shaved 0.8, hobbed 1.6 µm); default ground")
    state: Literal["new", "run-in"] = Field(
        "new", description="running-in state of the flanks: new (R_a/R_q as given, or as the finishing sets them) or "
                           "run-in (those as-manufactured values times the running-in factor of the finishing, "
                           "femgear.physics.lubrication.running_in: ground 0.70, honed 0.77, shaved 0.70, hobbed 0.59; "
                           "GearCalc manual §14.12); the ratings and the tribology both read the result")
    run_in_factor: float | None = Field(
        None, gt=0, le=1, description="roughness after running-in over as manufactured, with state = \"run-in\" "
                                      "(default: the finishing's typical factor; the finishing is ground when none "
                                      "is given) [-]")
    model: Literal["greenwood-tripp", "smooth"] = Field(
        "greenwood-tripp", description="the tribology's flanks: greenwood-tripp (rough: the asperities carry a share "
                                       "of the load at low λ by the load sharing, their law roughness.contact, μ "
                                       "rising towards friction.boundary_coefficient) or smooth (full film "
                                       "everywhere; the ratings still read the roughness)")
    contact: Literal["greenwood-tripp", "greenwood-williamson", "zhou-hoeprich"] = Field(
        "greenwood-tripp", description="the asperity contact law of the load sharing: greenwood-tripp (two rough "
                                       "surfaces, p_C = K E* F_5/2; Akbarzadeh & Khonsari's gear model), "
                                       "greenwood-williamson (a rough surface on a flat, p_C = 4/3 E* ηβσ √(σ/β) "
                                       "F_3/2; Gelinck & Schipper's Stribeck curves) or zhou-hoeprich (the share "
                                       "W_C/W = exp(−B λ^C) of λ = h_c/σ alone, Zhou & Hoeprich 1991; B, C: "
                                       "roughness.share_b, share_c)")
    fluid_film: Literal["mean-gap", "separation"] = Field(
        "mean-gap", description="the fluid's film at a nominal separation h of the flanks' mean planes: mean-gap "
                                "(Patir & Cheng's mean gap σ(tΦ(t) + φ(t)), t = h/σ: the flanks may close below the "
                                "mean planes, so the asperities take the whole load as the film vanishes) or "
                                "separation (the film is h ≥ 0: the asperity pressure never exceeds its value at "
                                "h = 0; femgear's split before this option)")
    share_b: Pos = Field(1.90, le=20.0, description="B of the Zhou–Hoeprich share exp(−B λ^C) (roughness.contact = "
                                                  "\"zhou-hoeprich\"; default the rib contact of Wingertszahn et al., "
                                                  "Lubricants 11:369, 2023, σ 0.24 µm) [-]")
    share_c: Pos = Field(0.99, le=5.0, description="C of the Zhou–Hoeprich share exp(−B λ^C) (default: Wingertszahn et "
                                                 "al.'s rib contact) [-]")
    eta_beta_sigma: Pos = Field(0.04, le=1.0, description="Greenwood–Tripp ηβσ (asperity density × radius × σ) [-]")
    sigma_over_beta: Pos = Field(
        3e-3, le=1.0, description="σ/β, roughness over the asperity tip radius (typical 1e-3…1e-2) [-]")
    peak: RoughnessPeak | None = Field(None, description="the paper's single roughness peak (eq. 22); none if absent")
    synthetic: SyntheticSurface | None = Field(None, description="a seeded Gaussian random surface; none if absent")


class Stiffness(_Frozen):
    """``[stiffness]``: the mesh stiffness of the ``constant`` level, mesh and Rayleigh damping (every dynamics
    level) and the resolution of the ``pem`` / ``fe`` levels."""

    mesh_stiffness_per_width: Pos = Field(
        2.0e10, description="mean mesh stiffness per unit face width c_γ [N/m per m], ISO typical 20 N/(mm µm)"
    )
    damping_ratio: float = Field(0.07, ge=0, lt=1, description="mesh damping ratio ζ_m [-]")
    rayleigh_ratio: float = Field(0.03, ge=0, lt=1, description="Rayleigh damping ratio of the two lowest modes [-]")
    n_positions: int = Field(200, ge=2, le=5000, description="mesh phases sampled per mesh period [-]")
    fe_mesh_size: Pos | None = Field(None, description="FE tooth mesh size (fe level) [m]; default m_n/2.5")


class Wear(_Frozen):
    """``[wear]``: Archard wear (``physics.wear = "archard"``)."""

    coefficient: NonNeg = Field(
        1.0e-6, description="dimensionless Archard coefficient K (dh = K p ds / H) [-]: with wear.load = \"total\" the "
                            "paper's 'wear rate' on the whole load, with \"asperity\" that of the asperity contacts"
    )
    cycles: NonNeg = Field(0.0, description="pinion revolutions of accumulated wear (load cycles of one pinion tooth) [-]")
    field: Literal["path", "face"] = Field(
        "path", description="wear depth field with physics.stiffness = \"ltca\": \"path\" (face-uniform h(u), the same "
                            "on both helices) or \"face\" (h(ρ, ζ) per member and helix from the LTCA's contact-line "
                            "loads, femgear.physics.wear.face; needs the ltca stiffness and an overlap ratio ε_β ≤ 1)")
    face_points: int = Field(21, ge=3, le=201, description="face positions ζ of the face-resolved wear grid [-]")
    load: Literal["asperity", "total"] = Field(
        "asperity", description="the load that wears in Archard's law: \"asperity\" the part the asperities carry "
                                "through the film (the Greenwood–Tripp/JGP split of the formula level's film at each "
                                "path position, roughness.rq or else the flanks' rating.roughness_ra / finishing; "
                                "Akbarzadeh & Khonsari 2009), negligible in full film; \"total\" the paper's "
                                "constant-coefficient form, K on the whole load whatever the film (its studies use "
                                "it; a pair whose film carries the load is warned)")


class Thermal(_Frozen):
    """``[thermal]``: bulk temperatures for thermal expansion of the teeth."""

    flank_temperature_rise: NonNeg = Field(
        0.0, description="bulk temperature rise of the flanks (tooth body) over ambient that drives the thermal "
                         "expansion [K]. > 0: used as given. 0 in a COUPLED run (a dynamics level): estimated each "
                         "pass as bulk_fraction × the mean contact temperature rise along the path (ISO/TS 6336-21). "
                         "0 in an UNCOUPLED run (dynamics = none): taken as 0, so the flanks do not grow (only "
                         "shaft_temperature_rise acts): give a value to see thermal expansion there"
    )
    shaft_temperature_rise: NonNeg = Field(0.0, description="temperature rise of the bore (where the body sits on the shaft) over ambient [K]")
    bulk_fraction: float = Field(
        0.7, ge=0, le=1,
        description="bulk temperature rise over the oil as a fraction C_1 of the mean contact temperature rise "
                    "along the path (ISO/TS 6336-21 integral-temperature method: 0.7), used in a coupled run when "
                    "flank_temperature_rise = 0 [-]")
    mesh_size: Pos | None = Field(None, description="FE gear-section mesh size (fe level; fe3d uses the LTCA body level 1) [m]; default m_n/5")


class Numerics(_Frozen):
    """``[numerics]``: resolution knobs shared by the pass along the path of contact."""

    path_points: int = Field(
        41, ge=3, le=10001,
        description="equidistant positions from the start A to the end E of the path of contact; the pitch point is "
                    "added to them [-]")
    ehl_level: int | None = Field(
        None, ge=2, le=9, description="the coarsest grid level the line EHL and TEHL results of the path end on "
                                      "(16·2^level cells of the graded grid, a floor); unset: the solvers pick the "
                                      "level that meets numerics.ehl_tol [-]")
    ehl_tol: float = Field(
        0.01, gt=0.0, lt=0.2, description="relative accuracy of the line EHL and TEHL films (central and minimum), "
                                          "by the two-level Richardson estimate each result carries [-]")
    dynamics_method: Literal["expo", "rk4", "newmark"] | None = Field(
        None, description="integrator; default expo for lumped, rk4 for timoshenko")
    steps_per_mesh_period: int = Field(200, ge=10, le=100000, description="time steps per mesh period [-]")
    dynamics_cycles: Pos = Field(100.0, description="simulated mesh periods in all, the transient_cycles included; must exceed them [-]")
    transient_cycles: NonNeg = Field(50.0, description="mesh periods dropped as transient before the response is analysed (paper: 50) [-]")
    body_level: int | None = Field(
        None, ge=0, le=6, description="resolution of the 3-D member bodies (ltca stiffness, fe3d thermal) and of the "
                                      "2-D sections (fe stiffness): element size m_n/(2 + level) on the loaded teeth, "
                                      "in module units so that similar gears get the same mesh; unset: each body's "
                                      "default, the coarsest within 2 % mesh error where measured: 0 for the ltca "
                                      "bodies with p2-bending elements (1 with p1), 1 for fe3d and fe (docs/cost.md) [-]")
    body_elements: Literal["p1", "p2-bending"] = Field(
        "p2-bending", description="elements of the ltca stiffness's 3-D member bodies: p2-bending quadratic ones in "
                                  "the loaded tooth (to 1 m_n below its root) and the rim (below 3 m_n under the "
                                  "root), linear elsewhere (< 2 % mesh error at level 0); p1 linear tetrahedra "
                                  "everywhere, stiff in bending (≈ 5 % on the mean stiffness at level 1, docs/cost.md) [-]")

    @model_validator(mode="after")
    def _records_a_period(self):
        if not self.dynamics_cycles >= self.transient_cycles + 1:
            raise SceneError("numerics.transient_cycles",
                             f"{self.transient_cycles:g} mesh periods dropped as transient leave fewer than one "
                             f"recorded period of numerics.dynamics_cycles = {self.dynamics_cycles:g} (the periods "
                             "simulated in all, the transient included): raise numerics.dynamics_cycles to at least "
                             f"{self.transient_cycles + 1:g} or lower numerics.transient_cycles")
        return self

    def level_of(self, body: str) -> int:
        """Resolution level of ``body`` (``"ltca"``, ``"fe3d"`` or ``"fe"``): ``body_level`` when the scene gives
        it, else that body's default (:data:`DEFAULT_BODY_LEVELS`; with ``body_elements = "p1"``
        :data:`P1_BODY_LEVELS`)."""
        if self.body_level is not None:
            return self.body_level
        return (P1_BODY_LEVELS if self.body_elements == "p1" else DEFAULT_BODY_LEVELS)[body]


#: the default resolution of each FE body (``numerics.body_level`` unset; docs/cost.md): the ltca bodies at level 0
#: with p2-bending elements (< 2 % on the mean stiffness and the LTE peak-to-peak), the fe3d thermal bodies and
#: the fe stiffness sections at level 1
DEFAULT_BODY_LEVELS = {"ltca": 0, "fe3d": 1, "fe": 1}
#: the default resolution of each FE body with ``numerics.body_elements = "p1"`` (linear tetrahedra, which only the
#: ltca bodies take from that key): level 1 throughout
P1_BODY_LEVELS = {"ltca": 1, "fe3d": 1, "fe": 1}


class Rating(_Frozen):
    """``[rating]``: ISO 6336-2 pitting, ISO 6336-3 bending, ISO/TS 6336-20/21 scuffing and ISO/TS 6336-22
    micropitting ratings (``femgear info``, ``femgear run``; docs/rating.md).

    Defaults: K_A 1 (give the application's); K_v, K_Hβ, K_Hα from femgear's own dynamics and LTCA where
    the scene's physics computes them, else by ISO 6336-1's methods (``load_factors``; a value given wins),
    accuracy grade 6; σ_Hlim 1500 MPa (case-carburised steel, ISO 6336-5 quality MQ), S_Hmin 1;
    life, lubricant and roughness factors are 1 (reference conditions) unless their
    inputs are given; Z_W = Z_X = 1.  The keys left unset (None) whose default the rating logs as used are
    :data:`Rating.DEFAULTS` (:meth:`value`).
    """

    #: the value of each key left unset (None) that the ratings use, named in their "defaults used" line
    DEFAULTS: ClassVar[dict[str, Any]] = {
        "bending_stress_limit": 5.0e8, "root_roughness_rz": [1.0e-5, 1.0e-5], "oil_type": "mineral",
        "scuffing_load_stage": 12.0, "micropitting_load_stage": 8.0, "accuracy_grade": 6}

    def value(self, key: str) -> Any:
        """``key``'s value, or its default (:data:`DEFAULTS`) where the scene leaves it unset."""
        given = getattr(self, key)
        return self.DEFAULTS[key] if given is None else given

    def defaulted(self, keys: tuple[str, ...]) -> list[str]:
        """``rating.<key>=<default>`` for each of ``keys`` the scene leaves unset (the "defaults used" line)."""
        return [f"rating.{k}={self.DEFAULTS[k]}" for k in keys if getattr(self, k) is None]

    application_factor: float = Field(1.0, ge=1, description="application factor K_A (ISO 6336-1) [-]")
    dynamic_factor: float | None = Field(
        None, ge=1, description="dynamic factor K_v (ISO 6336-1) [-]; unset: from the run's dynamics (the largest "
                                "dynamic over static mesh force of a helix) where a dynamics level runs, else "
                                "ISO 6336-1 method B (rating.load_factors)")
    face_load_factor: float | None = Field(
        None, ge=1, description="face load factor K_Hβ (contact, ISO 6336-1) [-]; unset: from the LTCA's face load "
                                "distribution with stiffness = 'ltca', else ISO 6336-1 method C (rating.load_factors)")
    transverse_load_factor: float | None = Field(
        None, ge=1, description="transverse load factor K_Hα (contact, ISO 6336-1) [-]; unset: from the LTCA's "
                                "sharing between the tooth pairs with stiffness = 'ltca', else ISO 6336-1 method B")
    load_factors: Literal["femgear", "iso"] = Field(
        "femgear", description="source of K_v, K_Hβ, K_Hα not given above: femgear (the run's dynamics and LTCA where "
                               "the physics levels compute them, ISO's methods otherwise) or iso (ISO 6336-1 "
                               "methods B / C / B throughout); results.json lists each with its source and ISO's value")
    accuracy_grade: int | None = Field(
        None, ge=1, le=12, description="ISO 1328-1 accuracy grade Q of both members (f_pb, f_fα of ISO's K_v and K_Hα; "
                                       "f_Hβ of its K_Hβ without a given helix slope deviation) [-]; default 6")
    contact_stress_limit: Pos = Field(1.5e9, description="σ_Hlim, allowable stress number (contact) [Pa]")
    min_safety_factor: Pos = Field(1.0, description="minimum required safety factor for pitting S_Hmin [-]")
    life_hours: Pos | None = Field(None, description="required life L_h [h]; sets N_L and Z_NT (None: Z_NT = 1)")
    oil_viscosity_40: Pos | None = Field(
        None, description="kinematic viscosity of the oil at 40 °C ν40 [mm^2/s]; sets Z_L and Z_v (None: 1)")
    roughness_rz: Annotated[list[Pos], Field(min_length=2, max_length=2)] | None = Field(
        None, description="mean peak-to-valley roughness R_z of the pinion and gear flanks, [R_z1, R_z2] [m]; "
                          "sets Z_R (None: 1)")
    work_hardening_factor: Pos = Field(1.0, description="work hardening factor Z_W (ISO 6336-2) [-]")
    size_factor: Pos = Field(1.0, description="size factor Z_X (ISO 6336-2) [-]")
    # ---- bending, scuffing, micropitting (docs/rating.md; None: the documented default, logged) ----
    bending_stress_limit: Pos | None = Field(
        None, description="σ_Flim, nominal stress number (bending) [Pa]; default 5e8 (case-carburised, ISO 6336-5 MQ)")
    bending_min_safety_factor: Pos = Field(1.0, description="minimum required safety factor for bending S_Fmin [-]")
    root_roughness_rz: Annotated[list[Pos], Field(min_length=2, max_length=2)] | None = Field(
        None, description="root fillet roughness R_z of pinion and gear [m] (Y_RrelT); default 1e-5 each")
    finishing: Finishing | None = Field(
        None, description="deprecated (read for one release): use roughness.finishing [-]")
    roughness_ra: MemberPair | None = Field(
        None, description="deprecated (read for one release): use roughness.ra; R_a of pinion and gear [m]")
    oil_type: Literal["mineral", "pao", "pag", "pag-water", "traction", "phosphate-ester"] | None = Field(
        None, description="base oil, sets the lubricant factor X_L of ISO/TS 6336-20/21; default mineral")
    scuffing_load_stage: float | None = Field(
        None, ge=1, le=14, description="FZG A/8.3/90 scuffing failure load stage of the oil (ISO 14635-1) [-]; "
                                       "default 12 (the DIN 51517-3 CLP minimum)")
    micropitting_load_stage: float | None = Field(
        None, ge=1, le=14, description="FZG GF-C/8.3/90 micropitting failure load stage of the oil (FVA 54) [-]; "
                                       "default 8 (GFT medium)")
    lubrication_method: Literal["dip", "spray"] = Field("dip", description="X_S of the bulk temperature: dip 1, spray 1.2")
    structural_factor: Pos = Field(1.0, description="X_W of the scuffing temperature (case-carburised 1) [-]")
    fillet_fe: bool = Field(
        False, description="also solve the 2-D FE section for the max principal fillet stress beside σ_F0 "
                           "(about 10 s per member)")


class FlankModification(_Frozen):
    """Flank modifications of one member (ISO 21771:2007 §§8–9 terms), amounts normal to the flank [m].

    Profile: tip relief C_a over the roll length L_Ca below the tip, root relief C_f over
    L_Cf above the start of the active profile (``*_shape``: linear or parabolic).  Face:
    lead crowning C_β (circular arc ≈ parabola, amount at each end of a helix), end relief
    C_I over L_I at both ends of each helix.  ``topography``: a measured deviation grid
    (rows root → tip over the active profile, columns groove end → outer end of a helix),
    bilinearly interpolated, added to both helices.  Used by the ``ltca`` stiffness level.
    """

    tip_relief: float = Field(0.0, ge=0, le=1e-3, description="tip relief C_a [m]")
    tip_relief_length: NonNeg = Field(0.0, description="roll length L_Ca of the tip relief along the path [m]")
    tip_relief_shape: Literal["linear", "parabolic"] = Field("linear", description="tip relief shape")
    root_relief: float = Field(0.0, ge=0, le=1e-3, description="root relief C_f [m]")
    root_relief_length: NonNeg = Field(0.0, description="roll length L_Cf of the root relief [m]")
    root_relief_shape: Literal["linear", "parabolic"] = Field("linear", description="root relief shape")
    crowning: float = Field(0.0, ge=0, le=1e-3, description="lead crowning C_β, amount at each helix end [m]")
    end_relief: float = Field(0.0, ge=0, le=1e-3, description="end relief C_I at each helix end [m]")
    end_relief_length: NonNeg = Field(0.0, description="axial length L_I of the end relief [m]")
    topography: list[list[float]] | None = Field(
        None, description="measured flank deviation grid [m], rows root→tip, columns groove end→outer end")

    @model_validator(mode="after")
    def _length_with_amount(self):
        for amount in ("tip_relief", "root_relief", "end_relief"):
            if getattr(self, amount) > 0 and getattr(self, f"{amount}_length") <= 0:
                raise ValueError(f"{amount} > 0 needs a positive {amount}_length")
        return self

    @field_validator("topography")
    @classmethod
    def _grid(cls, grid):
        if grid is None:
            return grid
        if len(grid) < 2 or any(len(row) != len(grid[0]) for row in grid) or len(grid[0]) < 2:
            raise ValueError("topography must be a rectangular grid of at least 2 × 2 values")
        if any(abs(v) > 1e-3 for row in grid for v in row):
            raise ValueError("topography values are in metres and must stay below 1 mm")
        return grid


class Modifications(FlankModification):
    """``[modifications]``: flank modifications shared by both members, or per member.

    The keys of :class:`FlankModification` at the top level apply to both members unless a
    ``[modifications.pinion]`` or ``[modifications.gear]`` table is given (it then replaces
    them for that member).  ``helix_slope_deviation_left/right`` is f_Hβ of each helix of the
    pair (misalignment): the gap opens linearly from 0 at the groove end to f_Hβ at the
    outer end (negative: closes).
    """

    pinion: FlankModification | None = Field(
        None, description="[modifications.pinion]: the pinion's own modifications (replace the shared keys for it)")
    gear: FlankModification | None = Field(
        None, description="[modifications.gear]: the gear's own modifications (replace the shared keys for it)")
    helix_slope_deviation_left: float = Field(0.0, ge=-1e-3, le=1e-3, description="f_Hβ of the left helix [m]")
    helix_slope_deviation_right: float = Field(0.0, ge=-1e-3, le=1e-3, description="f_Hβ of the right helix [m]")

    def member(self, member: int) -> FlankModification:
        """The modification of member 1 (pinion) or 2 (gear)."""
        own = self.pinion if member == 1 else self.gear
        if own is not None:
            return own
        return FlankModification(**{k: getattr(self, k) for k in FlankModification.model_fields})


Point = Annotated[list[float], Field(min_length=3, max_length=3)]
PerMember = Annotated[list[Pos], Field(min_length=2, max_length=2)]


def _housing_doc() -> str:
    return "the housing model: " + "; ".join(f"{s.name} ({s.summary})" for s in CATALOGUE["housing"].levels)


class Housing(_Frozen):
    """``[housing]``: the path from the bearings to a sensor and to the surroundings (docs/models/housing.md).

    Absent: the bearings stand on rigid ground, as before.  ``model = "fe"``: a parametric gearbox housing
    (gmsh, quadratic tetrahedra) around the pair, Craig–Bampton-reduced at the four bearing seats and coupled
    into the dynamics (the bearings join the shafts to the seats; the ``lumped`` dynamics level).
    ``model = "frf"``: receptances, mobilities or accelerances from the bearing-seat DOFs to sensors (and to the
    seats), read from ``frf_file`` (UFF dataset 58 or CSV); a receiver (sensor = H · bearing forces of the model on
    a rigid housing) or, with the whole seat-to-seat block, coupled by LM-FBS in the frequency domain.  Outputs per
    mesh order over ``speed_range`` (the linear response of the coupled model) and at the operating speed.
    """

    model: str = Field(description=_housing_doc())
    # ---- the FE housing: geometry in the dynamics' frame (shafts along z, pinion axis at (0, 0), gear at (a_w, 0))
    wall_thickness: Pos = Field(0.010, description="side wall thickness of the FE housing [m]")
    end_wall_thickness: Pos = Field(0.012, description="thickness of the two end walls that carry the bearings [m]")
    end_position: Pos | None = Field(
        None, description="z of the end walls' mid-planes, ± this [m]; default the outer bearing stations "
                          "(± the larger bearing_span/2)")
    clearance: Pos = Field(0.020, description="cavity beyond each gear's tip circle, radially [m]")
    bore_diameter: PerMember | None = Field(
        None, description="diameter of the bearing seats (the bearings' outer diameter) of the pinion and the gear "
                          "shaft [m]; default 2 × shaft_diameter")
    bearing_width: PerMember | None = Field(
        None, description="axial width of the bearing seats of the pinion and the gear shaft [m]; default "
                          "shaft_diameter/2")
    boss_thickness: Pos = Field(0.010, description="radial thickness of the bosses around the bores [m]")
    boss_length: Pos | None = Field(
        None, description="axial length of the bosses, centred on the end walls [m]; default: with the default "
                          "end_position the shortest (at least the end wall's thickness) that holds every bearing "
                          "seat, with a given end_position the end wall's thickness")
    foot_size: Pos = Field(0.040, description="edge length of the four square feet, clamped on their soles [m]")
    foot_height: Pos = Field(0.020, description="height of the feet below the floor [m]")
    mesh_size: Pos = Field(0.015, description="target element size of the housing mesh [m]")
    elements: Literal["p2", "p1"] = Field(
        "p2", description="quadratic (p2, bends a wall right with one element through its thickness) or linear "
                          "tetrahedra (p1, stiff in bending: for quick looks only)")
    youngs_modulus: Pos = Field(1.1e11, description="Young's modulus of the housing [Pa] (grey cast iron EN-GJL-250, "
                                                    "EN 1561: 103-118 GPa)")
    poisson_ratio: float = Field(0.26, gt=0, lt=0.5, description="Poisson's ratio of the housing [-]")
    density: Pos = Field(7200.0, description="density of the housing [kg/m^3]")
    damping_ratio: float = Field(0.02, ge=0, lt=1, description="modal damping ratio of every housing mode [-]")
    modes: int = Field(60, ge=0, description="fixed-interface modes kept by the Craig–Bampton reduction [-]")
    check_reduction: bool = Field(
        False, description="also solve the unreduced FE housing's modes and report the Craig–Bampton error in the "
                           "retained band (0.4 × the highest retained fixed-interface frequency); costs "
                           "one more factorisation and eigen-solve")
    sensors: list[Point] | None = Field(
        None, description="FE housing: sensor points [m] (x, y, z), each read at the nearest vertex of the outer "
                          "surface; default one on the top wall above each bearing station")
    sensor_directions: list[Point] | None = Field(
        None, description="FE housing: the sensors' directions (x, y, z), one per sensor; default the outward "
                          "surface normal [-]")
    # ---- measured or supplied FRFs
    frf_file: str | None = Field(
        None, description="FRF file (model = 'frf'): UFF/UNV dataset 58 (.uff, .unv) or CSV (.csv, columns "
                          "frequency, output, input, real, imag); a relative path is read from the scene's folder")
    frf_kind: Literal["receptance", "mobility", "accelerance"] | None = Field(
        None, description="what the FRF file holds (m/N, m/s per N, m/s^2 per N); required for CSV, read from "
                          "the UFF's ordinate type (and checked against this when given)")
    seat_nodes: Annotated[list[int], Field(min_length=4, max_length=4)] | None = Field(
        None, description="UFF: the node numbers of the bearing seats pinion_L, pinion_R, gear_L, gear_R [-] (their "
                          "directions 1/2/3 = x/y/z of the dynamics' frame; every other response node is a sensor)")
    coupling: Literal["auto", "receiver", "lm-fbs"] = Field(
        "auto", description="FRF housing: receiver (sensor = H · bearing forces on a rigid housing), lm-fbs "
                            "(coupled by substructuring: needs the 12 × 12 seat-to-seat block) or auto (lm-fbs "
                            "when the file has that block)")
    # ---- outputs
    speed_range: Annotated[list[Pos], Field(min_length=2, max_length=2)] | None = Field(
        None, description="driving-member speeds of the order sweep, [from, to] [rev/min]; default 10 % to 150 % "
                          "of operating.speed_rpm")
    speed_points: int = Field(41, ge=2, le=2000, description="speeds of the order sweep [-]")
    orders: int = Field(6, ge=1, le=50, description="mesh orders 1 … orders of the sweep and of the operating "
                                                    "point [-]")
    ods_speed_rpm: Pos | None = Field(None, description="driving-member speed of the operating deflection shape "
                                                        "[rev/min]; default operating.speed_rpm")
    ods_order: int = Field(1, ge=1, le=50, description="mesh order of the operating deflection shape [-]")
    air_impedance: Pos = Field(411.0, description="characteristic impedance ρc of the air the housing radiates into "
                                                  "[N s/m^3] (ISO/TS 7849: 411)")

    @field_validator("model")
    @classmethod
    def _model_exists(cls, name: str) -> str:
        problem = CATALOGUE["housing"].problem(name)
        if problem:
            raise ValueError(problem)
        return name

    @model_validator(mode="after")
    def _consistent(self):
        if self.sensor_directions is not None and (self.sensors is None or
                                                   len(self.sensor_directions) != len(self.sensors)):
            raise ValueError("sensor_directions needs one direction per point of sensors")
        if self.speed_range is not None and not self.speed_range[1] > self.speed_range[0]:
            raise ValueError("speed_range must be [from, to] with to > from")
        if self.ods_order > self.orders:
            raise ValueError(f"ods_order {self.ods_order} is above orders = {self.orders}")
        return self


def _levels_doc(submodel: str, what: str) -> str:
    """The description of a ``[physics]`` key, listing its levels from the catalogue (cheapest first)."""
    return f"level of the {what} sub-model, cheapest first: " + ", ".join(LEVELS[submodel])


class Physics(_Frozen):
    """``[physics]``: one fidelity level per sub-model (see :mod:`femgear.scene.levels`).

    ``preset`` ("fast", "balanced", "accurate"; :mod:`femgear.scene.presets`) fills in the
    levels and resolution knobs it names; keys given explicitly win.
    """

    preset: Literal["fast", "balanced", "accurate"] | None = Field(
        None, description="a point on the measured speed–accuracy fronts that fills in the levels and resolution "
                          "knobs it names (fast, balanced, accurate; femgear.scene.presets); keys given explicitly win")

    stiffness: str = Field("constant", description=_levels_doc("stiffness", "mesh stiffness"))
    lubrication: str = Field("formula", description=_levels_doc("lubrication", "friction, film and contact temperature"))
    thermal: str = Field("none", description=_levels_doc("thermal", "thermal expansion of the flanks"))
    wear: str = Field("none", description=_levels_doc("wear", "flank wear"))
    dynamics: str = Field("none", description=_levels_doc("dynamics", "gear-rotor dynamics"))
    coupling: str = Field("one-way", description=_levels_doc("coupling", "coupling of dynamics and tribology"))

    @field_validator("stiffness", "lubrication", "thermal", "wear", "dynamics", "coupling")
    @classmethod
    def _level_exists(cls, level: str, info: ValidationInfo) -> str:
        message = check_level(info.field_name, level)
        if message:
            raise ValueError(message)
        return level

    @field_validator("coupling")
    @classmethod
    def _coupling_needs_dynamics(cls, level: str, info: ValidationInfo) -> str:
        dynamics = info.data.get("dynamics")
        if CATALOGUE["coupling"].spec(level).iterates and dynamics is not None and \
                not CATALOGUE["dynamics"].spec(dynamics).is_dynamic:
            raise ValueError("bidirectional coupling needs a dynamics level (set physics.dynamics)")
        return level

    def spec(self, submodel: str) -> LevelSpec:
        """The catalogue's spec of this table's ``submodel`` level (:mod:`femgear.scene.levels`): what callers
        branch on instead of the level's name."""
        return CATALOGUE[submodel].spec(getattr(self, submodel))


class Scene(_Frozen):
    """A whole scene file."""

    meta: Meta = Meta()
    pair: Pair
    pinion: Member
    gear: Member
    material: Material
    oil: Oil
    operating: Operating
    errors: Errors = Errors()
    friction: Friction = Friction()
    roughness: SurfaceRoughness = SurfaceRoughness()
    stiffness: Stiffness = Stiffness()
    wear: Wear = Wear()
    thermal: Thermal = Thermal()
    numerics: Numerics = Numerics()
    modifications: Modifications = Modifications()
    physics: Physics = Physics()
    rating: Rating = Rating()
    housing: Housing | None = None

    @property
    def pinion_rpm(self) -> float:
        """Speed of the pinion [rev/min], from the driving member's speed."""
        op = self.operating
        return op.speed_rpm if op.driver == "pinion" else op.speed_rpm * self.gear.teeth / self.pinion.teeth

    @property
    def oil_reference_temperature(self) -> float:
        """Temperature at which ``oil.viscosity`` holds [K]."""
        t = self.oil.reference_temperature
        return self.operating.ambient_temperature if t is None else t
