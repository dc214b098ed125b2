"""The frozen description of one run, bound from a validated scene in one place.

A :class:`Case` is built once per run by :func:`build_case` (the scene's edge): the gear
pair (:func:`femgear.case.pair.pair_from_scene`, with its feasibility checks), the operating
point with the normal force F_bn, the one path grid every sub-model shares, and the scene's
typed tables (materials, oil, members, errors, resolution knobs, physics levels).  The
checks that need the bound pair run here (:mod:`femgear.case.checks`), after the scene's
own validation (:func:`femgear.scene.load_scene`).  The levels (:mod:`femgear.levels`) and
the driver (:mod:`femgear.pipeline`, :mod:`femgear.system.coupling`, :mod:`femgear.system.dynamics`)
take a Case; physics functions below it take arrays, numbers and typed objects.

Lifetimes (ROSS habit): the pair, materials and oil stay fixed over a study; the
operating point changes per load case (:meth:`Case.at_speed` for speed sweeps).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from femgear.case.checks import check_bound_case
from femgear.case.oil import oil_at
from femgear.case.pair import pair_from_scene
from femgear.physics.geometry import GearPair, PathKinematics, kinematics, mesh_frequency, path_positions
from femgear.physics.housing.frf import FRFSet
from femgear.scene.roughness import FlankRoughness, flank_roughness
from femgear.scene.schema import (
    Errors,
    Friction,
    Housing,
    Material,
    Member,
    Modifications,
    Numerics,
    Oil,
    Physics,
    Scene,
    Stiffness,
    SurfaceRoughness,
    Thermal,
    Wear,
)


@dataclass(frozen=True)
class OperatingPoint:
    """Speeds, torques and loads of the load case, referred to the pinion (SI)."""

    driver: str                 #: "pinion" or "gear"
    pinion_rpm: float           #: pinion speed [rev/min]
    pinion_torque: float        #: torque on the pinion [N m] (losses neglected)
    gear_torque: float          #: T1 r_b2 / r_b1 [N m]
    normal_force: float         #: F_bn of the pair, both helices [N]
    ambient_temperature: float  #: oil supply and ambient temperature [K]
    loop_stiffness: float       #: closed power loop stiffness referred to the gear shaft [N m/rad]
    mesh_frequency: float       #: f_m [Hz]

    @property
    def pinion_speed(self) -> float:
        """ω1 [rad/s]."""
        return self.pinion_rpm * 2 * math.pi / 60


@dataclass(frozen=True)
class Case:
    """One run: the validated scene (kept as the input record) and what is bound from it."""

    scene: Scene
    pair: GearPair
    operating: OperatingPoint
    path: PathKinematics          #: the one path grid (``numerics.path_points`` + the pitch point)
    #: the ``[oil]`` table at the supply temperature ``operating.ambient_temperature`` (its reference_temperature)
    oil: Oil
    #: the flanks' roughness (the one ``[roughness]`` description, :func:`femgear.scene.roughness.flank_roughness`)
    flanks: FlankRoughness
    #: the plausibility warnings logged so far for this case (``key: message``), one per key
    warnings: tuple[str, ...] = ()
    #: the FRFs of ``housing.frf_file`` (:func:`femgear.scene.frf_file.read_frf`), read once; None without one
    frf: FRFSet | None = None

    # ---------- the scene's typed tables ----------
    @property
    def name(self) -> str:
        return self.scene.meta.name

    @property
    def levels(self) -> Physics:
        return self.scene.physics

    @property
    def members(self) -> tuple[Member, Member]:
        return self.scene.pinion, self.scene.gear

    @property
    def material(self) -> Material:
        return self.scene.material

    @property
    def oil_reference_temperature(self) -> float:
        """Temperature at which ``case.oil`` holds: the supply temperature [K]."""
        return self.oil.reference_temperature

    @property
    def roughness(self) -> SurfaceRoughness:
        """The scene's ``[roughness]`` table (its deterministic sub-tables; the resolved R_a, R_q, σ: ``flanks``)."""
        return self.scene.roughness

    @property
    def modifications(self) -> Modifications:
        return self.scene.modifications

    @property
    def errors(self) -> Errors:
        return self.scene.errors

    @property
    def friction(self) -> Friction:
        return self.scene.friction

    @property
    def stiffness(self) -> Stiffness:
        return self.scene.stiffness

    @property
    def wear(self) -> Wear:
        return self.scene.wear

    @property
    def thermal(self) -> Thermal:
        return self.scene.thermal

    @property
    def numerics(self) -> Numerics:
        return self.scene.numerics

    @property
    def stagger(self) -> float:
        return self.scene.pair.stagger

    @property
    def backlash(self) -> float:
        return self.scene.pair.backlash

    @property
    def groove_width(self) -> float:
        return self.scene.pair.groove_width

    @property
    def omega(self) -> tuple[float, float]:
        """Signed angular speeds of pinion and gear [rad/s] (pinion CCW when it drives)."""
        w1 = self.operating.pinion_speed
        sense = 1.0 if self.operating.driver == "pinion" else -1.0
        return sense * w1, -sense * w1 * self.pair.z1 / self.pair.z2

    @property
    def housing(self) -> Housing | None:
        """The ``[housing]`` table (None: the bearings stand on rigid ground)."""
        return self.scene.housing

    @property
    def bore_radii(self) -> tuple[float, float]:
        return self.scene.pinion.bore_radius, self.scene.gear.bore_radius

    # ---------- variants ----------
    def at_speed(self, driver_rpm: float) -> Case:
        """The same case with the driving member at ``driver_rpm``."""
        op = self.scene.operating.model_copy(update={"speed_rpm": float(driver_rpm)})
        return build_case(self.scene.model_copy(update={"operating": op}), pair=self.pair)


def operating_point(scene: Scene, pair: GearPair) -> OperatingPoint:
    """Speeds and torques referred to the pinion; F_bn = T1 / (r_b1 cos β_b)."""
    op = scene.operating
    ratio = scene.gear.teeth / scene.pinion.teeth
    rpm1 = op.speed_rpm if op.driver == "pinion" else op.speed_rpm * ratio
    T1 = op.torque if op.driver == "pinion" else op.torque / ratio
    return OperatingPoint(
        driver=op.driver, pinion_rpm=rpm1, pinion_torque=T1, gear_torque=T1 * pair.rb2 / pair.rb1,
        normal_force=T1 / (pair.rb1 * math.cos(pair.beta_b)), ambient_temperature=op.ambient_temperature,
        loop_stiffness=op.loop_stiffness, mesh_frequency=mesh_frequency(pair, rpm1),
    )


def path_grid(pair: GearPair, n: int, omega1: float) -> PathKinematics:
    """Kinematics at ``n`` equidistant positions from A to E plus the pitch point exactly."""
    u = np.unique(np.append(path_positions(pair, n), pair.u_pitch))
    return kinematics(pair, u, omega1)


def build_case(scene: Scene, pair: GearPair | None = None, warn: bool = True) -> Case:
    """Bind a validated scene into a :class:`Case`, once per run.

    The pair is bound and checked (:class:`femgear.errors.SceneError` naming the key for an impossible
    gear or operating point, :func:`femgear.case.checks.check_bound_case`); implausible inputs are
    logged as warnings (``warn=False`` skips them).  A given ``pair`` (the same gear at another
    operating point, :meth:`Case.at_speed`) is taken as bound and checked.
    """
    checks = pair is None
    pair = pair_from_scene(scene) if checks else pair
    op = operating_point(scene, pair)
    case = Case(scene=scene, pair=pair, operating=op, path=path_grid(pair, scene.numerics.path_points, op.pinion_speed),
                frf=_frf(scene), oil=oil_at(scene.oil, scene.oil_reference_temperature, op.ambient_temperature),
                flanks=flank_roughness(scene))
    return replace(case, warnings=check_bound_case(case, warn)) if checks else case


def _frf(scene: Scene) -> FRFSet | None:
    """The FRF set of ``housing.frf_file`` (None without one)."""
    h = scene.housing
    if h is None or h.frf_file is None:
        return None
    from femgear.scene.frf_file import read_frf

    return read_frf(h.frf_file, h.frf_kind, h.seat_nodes)
