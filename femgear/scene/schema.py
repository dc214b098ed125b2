"""The scene schema: frozen, validated models of a scene file (all units SI).

Every key is documented here, with its unit.  Angles are the one exception to SI in
the file (``*_deg`` keys, degrees, as engineers write them); they are converted to
radians once, by :mod:`femgear.geometry`.  Unknown keys are errors, so a typo never
goes unnoticed.

Models are grouped by lifetime (ROSS habit): the gear pair, material and oil stay
fixed for a study; the operating point and errors change per load case.
"""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import BaseModel, ConfigDict, Field, ValidationInfo, field_validator

from femgear.scene.levels import check_level

Pos = Annotated[float, Field(gt=0)]
NonNeg = Annotated[float, Field(ge=0)]


class _Frozen(BaseModel):
    model_config = ConfigDict(frozen=True, extra="forbid", strict=False)


class Meta(_Frozen):
    """``[meta]``: a name (used for output folders) and a free description."""

    name: str = "scene"
    description: str = ""


class Pair(_Frozen):
    """``[pair]``: the double-helical gear pair, data shared by both members.

    A double-helical pair is two helical pairs of opposite hand side by side
    ("left" and "right" helix).  ``face_width`` is the width of ONE helix.
    """

    normal_module: Pos = Field(description="normal module m_n [m]")
    normal_pressure_angle_deg: float = Field(20.0, gt=0, lt=45, description="normal pressure angle α_n [deg]")
    helix_angle_deg: float = Field(description="helix angle β at the reference circle [deg]", gt=0, lt=45)
    face_width: Pos = Field(description="face width of one helix b [m]")
    groove_width: NonNeg = Field(0.0, description="central groove between the helices [m]")
    addendum_coeff: float = Field(1.0, gt=0, le=1.5, description="basic-rack addendum h_aP/m_n [-]")
    dedendum_coeff: float = Field(1.25, gt=0, le=1.8, description="basic-rack dedendum h_fP/m_n [-]")
    root_radius_coeff: float = Field(0.38, ge=0, le=0.6, description="basic-rack root radius ρ_fP/m_n [-]")
    backlash: NonNeg = Field(0.0, description="normal backlash b0 of the pair (paper: 'half backlash') [m]")
    stagger: float = Field(
        0.0, ge=0, lt=1,
        description="offset of the right helix's mesh against the left one, as a fraction of the transverse base pitch [-]",
    )


class Member(_Frozen):
    """``[pinion]`` / ``[gear]``: one member (both its helices) and its supports."""

    teeth: int = Field(ge=5, le=1000, description="number of teeth z [-]")
    profile_shift: float = Field(0.0, ge=-1.5, le=1.5, description="profile shift coefficient x [-]")
    mass: Pos = Field(description="mass of the member, both helices [kg]")
    inertia: Pos = Field(description="polar moment of inertia, both helices [kg m^2]")
    bore_radius: NonNeg = Field(0.0, description="shaft bore radius (0 = solid) [m]")
    support_stiffness: Pos = Field(description="bearing stiffness per direction x, y, z [N/m]")
    support_damping: NonNeg = Field(0.0, description="bearing damping per direction [N s/m]")
    eccentricity: NonNeg = Field(0.0, description="geometric eccentricity e_r [m]")
    eccentricity_phase_deg: float = Field(0.0, description="phase θ of the eccentricity [deg]")
    unbalance: NonNeg = Field(0.0, description="mass unbalance m·e [kg m]")
    bearing_span: Pos = Field(0.10, description="distance between the member's two bearings [m]")
    shaft_diameter: Pos = Field(0.040, description="solid shaft diameter (timoshenko level) [m]")


class Material(_Frozen):
    """``[material]``: the gear steel (both members)."""

    youngs_modulus: Pos = Field(description="Young's modulus E [Pa]")
    poisson_ratio: float = Field(gt=0, lt=0.5, description="Poisson's ratio ν [-]")
    density: Pos = Field(description="density ρ [kg/m^3]")
    specific_heat: Pos = Field(description="specific heat c [J/(kg K)]")
    conductivity: Pos = Field(description="thermal conductivity k [W/(m K)]")
    thermal_expansion: Pos = Field(description="linear expansion coefficient λ [1/K]")
    hardness: Pos = Field(6.0e9, description="flank hardness H for Archard wear [Pa]")


class Oil(_Frozen):
    """``[oil]``: the lubricant.  Viscosity data refer to ``reference_temperature``."""

    viscosity: Pos = Field(description="dynamic viscosity η0 at the reference temperature [Pa s]")
    density: Pos = Field(description="density ρ0 [kg/m^3]")
    specific_heat: Pos = Field(description="specific heat c_f [J/(kg K)]")
    conductivity: Pos = Field(description="thermal conductivity k_f [W/(m K)]")
    pressure_viscosity: Pos = Field(description="Barus pressure-viscosity coefficient α [1/Pa]")
    temperature_viscosity: NonNeg = Field(description="temperature-viscosity coefficient β_T [1/K]")
    reference_temperature: Pos | None = Field(
        None, description="temperature of η0 [K]; defaults to operating.ambient_temperature"
    )
    thermal_expansion: NonNeg = Field(6.5e-4, description="density-temperature coefficient ε [1/K]")
    eyring_stress: Pos = Field(5.0e6, description="Eyring stress τ0 for non-Newtonian traction [Pa]")
    limiting_shear_coeff: NonNeg = Field(
        0.0, description="limiting shear stress τ_L = Λ p as the coefficient Λ; 0 switches it off [-]"
    )


class Operating(_Frozen):
    """``[operating]``: the load case."""

    driver: Literal["pinion", "gear"] = Field("pinion", description="the driving member")
    speed_rpm: Pos = Field(description="speed of the driving member [rev/min]")
    torque: Pos = Field(description="torque on the driving member [N m]")
    ambient_temperature: Pos = Field(313.0, description="ambient and oil supply temperature [K]")
    loop_stiffness: NonNeg = Field(
        0.0, description="torsional stiffness of a closed power loop (FZG rig), referred to the gear shaft; "
                         "0 = prescribed torques as in the paper [N m/rad]")


class Errors(_Frozen):
    """``[errors]``: transmission-error sources beside eccentricity (see ``[pinion]``)."""

    profile_error: NonNeg = Field(0.0, description="amplitude of the profile-error harmonics e_f [m]")
    profile_error_orders: int = Field(3, ge=1, le=10, description="number of mesh-frequency harmonics M [-]")
    profile_error_phase_deg: float = Field(0.0, description="phase φ of the profile error [deg]")
    random: NonNeg = Field(0.0, description="amplitude of the seeded random error component e_0 [m]")
    seed: int = Field(0, ge=0, description="seed of the random component")


class Friction(_Frozen):
    """``[friction]``: used when ``physics.lubrication = "constant"``."""

    coefficient: float = Field(0.05, ge=0, le=0.5, description="friction coefficient μ [-]")
    regularisation_speed: Pos = Field(0.01, description="v_reg of the sliding sign tanh(v_s/v_reg) [m/s]")


class Stiffness(_Frozen):
    """``[stiffness]``: used when ``physics.stiffness = "constant"``."""

    mesh_stiffness_per_width: Pos = Field(
        2.0e10, description="mean mesh stiffness per unit face width c_γ [N/m per m], ISO typical 20 N/(mm µm)"
    )
    damping_ratio: float = Field(0.07, ge=0, lt=1, description="mesh damping ratio ζ_m [-]")
    rayleigh_ratio: float = Field(0.03, ge=0, lt=1, description="Rayleigh damping ratio of the two lowest modes [-]")
    n_slices: int = Field(100, ge=1, le=2000, description="slices along the face width (pem, fe levels) [-]")
    n_positions: int = Field(200, ge=2, le=5000, description="mesh phases sampled per mesh period [-]")
    fe_mesh_size: Pos | None = Field(None, description="FE tooth mesh size (fe level) [m]; default m_n/2.5")


class Wear(_Frozen):
    """``[wear]``: Archard wear (``physics.wear = "archard"``)."""

    coefficient: NonNeg = Field(
        1.0e-6, description="dimensionless Archard coefficient K (dh = K p ds / H), the paper's 'wear rate' [-]"
    )
    cycles: NonNeg = Field(0.0, description="mesh cycles of accumulated wear [-]")


class Thermal(_Frozen):
    """``[thermal]``: bulk temperatures for thermal expansion of the teeth."""

    flank_temperature_rise: NonNeg = Field(
        0.0, description="flank temperature rise over ambient, if not from the lubrication model [K]"
    )
    shaft_temperature_rise: NonNeg = Field(0.0, description="shaft/bore temperature rise over ambient [K]")
    mesh_size: Pos | None = Field(None, description="FE gear-section mesh size (fe level) [m]; default m_n/5")


class Numerics(_Frozen):
    """``[numerics]``: resolution knobs shared by the pass along the path of contact."""

    path_points: int = Field(41, ge=3, le=10001, description="positions along the path of contact [-]")
    ehl_level: int = Field(5, ge=2, le=9, description="grid level of the FE line EHL (16·2^level cells) [-]")
    dynamics_method: Literal["expo", "rk4", "newmark"] | None = Field(
        None, description="integrator; default expo for lumped, rk4 for timoshenko")
    steps_per_mesh_period: int = Field(200, ge=10, le=100000, description="time steps per mesh period [-]")
    dynamics_cycles: Pos = Field(100.0, description="simulated mesh periods [-]")
    transient_cycles: NonNeg = Field(50.0, description="mesh periods dropped as transient (paper: 50) [-]")


class Physics(_Frozen):
    """``[physics]``: one fidelity level per sub-model (see :mod:`femgear.scene.levels`).

    ``preset`` ("fast", "balanced", "accurate"; :mod:`femgear.scene.presets`) fills in the
    levels and resolution knobs it names; keys given explicitly win.
    """

    preset: Literal["fast", "balanced", "accurate"] | None = None

    stiffness: str = "constant"
    lubrication: str = "formula"
    thermal: str = "none"
    wear: str = "none"
    dynamics: str = "none"
    coupling: str = "one-way"

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
        if level == "bidirectional" and info.data.get("dynamics") == "none":
            raise ValueError("bidirectional coupling needs a dynamics level (set physics.dynamics)")
        return level


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
    stiffness: Stiffness = Stiffness()
    wear: Wear = Wear()
    thermal: Thermal = Thermal()
    numerics: Numerics = Numerics()
    physics: Physics = Physics()

    @property
    def oil_reference_temperature(self) -> float:
        """Temperature at which ``oil.viscosity`` holds [K]."""
        t = self.oil.reference_temperature
        return self.operating.ambient_temperature if t is None else t
