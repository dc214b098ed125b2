"""Housing models (the ``[housing] model`` key): the path from the bearings to a sensor and to the air.

Each factory returns a :class:`HousingLayer`, whose attributes tell the driver what to do with it (never its name):
``reduced`` (an FE housing, Craig–Bampton-reduced: the dynamics model couples it, the bearings then join the shafts
to its seats) or ``frf`` (an FRF set, applied in the frequency domain), and ``coupling`` (how: ``craig-bampton``,
``lm-fbs`` or ``receiver``).  Absent ``[housing]``: :func:`of` is None and the bearings stand on rigid ground.
The FE housing is built once per geometry, material, elements, modes and sensors (:func:`fe_layer`).
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from typing import Any

import numpy as np

from femgear.errors import SceneError
from femgear.levels.registry import Registry
from femgear.physics.housing.fe import HousingMaterial, housing_structure
from femgear.physics.housing.reduction import lowest_frequencies
from femgear.physics.mesh.housing import HousingGeometry, housing_mesh

REGISTRY = Registry("housing")
#: the retained band of the reduction check: this fraction of the highest retained fixed-interface frequency (the
#: rule of thumb "fixed-interface modes to twice the band" left 3.1 % on a mode of the baseline housing; to 2.5 times
#: the band every mode measured was within 1 %: docs/models/housing.md)
RETAINED_BAND = 0.4


@dataclass(frozen=True)
class ReductionCheck:
    """The Craig–Bampton housing's natural frequencies against the unreduced FE housing's (seats free)."""

    band: float                 #: the retained band: RETAINED_BAND × the highest retained fixed-interface frequency [Hz]
    full: np.ndarray            #: the unreduced housing's natural frequencies in the band [Hz]
    reduced: np.ndarray         #: the reduced housing's, as many [Hz]
    max_error: float            #: max |f_red − f_full| / f_full in the band [-]


@dataclass(frozen=True)
class HousingLayer:
    """The product of a housing model (module docstring)."""

    name: str
    coupling: str                    #: "craig-bampton", "lm-fbs" or "receiver"
    sensors: tuple[str, ...]         #: sensor names, the order of every sensor axis
    reduced: Any = None              #: the :class:`~femgear.physics.housing.fe.ReducedHousing` (FE housing)
    frf: Any = None                  #: the :class:`~femgear.physics.housing.frf.FRFSet` (FRF housing)
    check: ReductionCheck | None = None  #: ``housing.check_reduction``: the reduction's error in its band
    full_dofs: int = 0               #: DOFs of the unreduced FE housing [-]


def of(case: Any) -> HousingLayer | None:
    """The housing of ``case`` (None without ``[housing]``)."""
    h = getattr(case, "housing", None)
    return None if h is None else REGISTRY.build(h.model, case)


@REGISTRY.register("fe")
def _fe(case: Any) -> HousingLayer:
    h = case.housing
    geometry = housing_geometry(case)
    material = HousingMaterial(h.youngs_modulus, h.poisson_ratio, h.density, h.damping_ratio)
    if h.sensors is None:
        sensors = default_sensors(geometry)
        dirs = ((0.0, 1.0, 0.0),) * len(sensors)
    else:
        sensors = tuple(tuple(p) for p in h.sensors)
        dirs = None if h.sensor_directions is None else tuple(tuple(d) for d in h.sensor_directions)
    return fe_layer(geometry, material, 2 if h.elements == "p2" else 1, h.modes, sensors, dirs,
                    bool(h.end_position or h.boss_length), h.check_reduction)


@functools.lru_cache(maxsize=4)
def fe_layer(geometry, material, order: int, modes: int, sensors, directions, user_walls: bool,
             check: bool) -> HousingLayer:
    """The FE housing's layer, built once per argument set (a run asks for it at its start, in the model and in
    its outputs)."""
    red, st = reduced_housing(geometry, material, order, modes, sensors, directions, user_walls)
    names = tuple(f"S{i + 1}" for i in range(len(sensors)))
    return HousingLayer("fe", "craig-bampton", names, reduced=red, check=reduction_check(red, st) if check else None,
                        full_dofs=st.n_dofs)


@REGISTRY.register("frf")
def _frf(case: Any) -> HousingLayer:
    h, frf = case.housing, case.frf
    if frf is None:
        raise SceneError("housing.frf_file", "model = 'frf' needs an FRF file")
    if h.coupling == "lm-fbs" and not frf.has_seat_block:
        raise SceneError("housing.coupling", f"lm-fbs needs the 12 × 12 seat-to-seat block; {frf.source} lacks "
                                             "some of it (use receiver)")
    if not frf.sensors:
        raise SceneError(str(h.frf_file), "holds no sensor output (every response is at a bearing seat)")
    coupling = "lm-fbs" if h.coupling == "lm-fbs" or (h.coupling == "auto" and frf.has_seat_block) else "receiver"
    return HousingLayer("frf", coupling, frf.sensors, frf=frf)


def housing_geometry(case: Any):
    """The :class:`~femgear.physics.mesh.housing.HousingGeometry` of ``case``'s pair, bearings and ``[housing]``."""
    h, pair, (p, g) = case.housing, case.pair, case.members
    bore = (p.shaft_diameter, g.shaft_diameter) if h.bore_diameter is None else tuple(0.5 * d for d in h.bore_diameter)
    width = (0.5 * p.shaft_diameter, 0.5 * g.shaft_diameter) if h.bearing_width is None else tuple(h.bearing_width)
    return HousingGeometry(
        centre_distance=pair.a_w, tip_radius=(pair.ra1, pair.ra2),
        station_z=(-0.5 * p.bearing_span, 0.5 * p.bearing_span, -0.5 * g.bearing_span, 0.5 * g.bearing_span),
        bore_radius=bore, bearing_width=width, wall=h.wall_thickness, end_wall=h.end_wall_thickness,
        end_position=h.end_position, clearance=h.clearance, boss=h.boss_thickness, boss_length=h.boss_length,
        foot=h.foot_size, foot_height=h.foot_height, size=h.mesh_size)


def default_sensors(geometry) -> tuple[tuple[float, float, float], ...]:
    """One point on the outer top wall (y max) above each bearing station, over the end wall's inner face (off the
    box's edge), read along +y [m]."""
    top = float(geometry.cavity()[1][1] + geometry.wall)
    inner = geometry.walls_at - 0.5 * geometry.end_wall
    return tuple((float(geometry.axis(j)[0]), top, float(np.clip(z, -inner, inner)))
                 for j, z in enumerate(geometry.station_z))


def _structure(geometry, material, order: int, user_walls: bool):
    try:
        return housing_structure(housing_mesh(geometry), material, order)
    except ValueError as exc:
        key = "housing.end_position" if "seat" in str(exc) and user_walls else "housing"
        raise SceneError(key, str(exc)) from None


def reduced_housing(geometry, material, order: int, modes: int, sensors, directions, user_walls: bool = False):
    """(:class:`~femgear.physics.housing.fe.ReducedHousing`, its unreduced structure) of the FE housing;
    :class:`SceneError` naming the key for a mesh that misses a seat, too many modes or a sensor off the surface."""
    st = _structure(geometry, material, order, user_walls)
    try:
        red = st.reduce(modes, np.array(sensors), None if directions is None else np.array(directions))
    except ValueError as exc:
        key = "housing.modes" if "fixed-interface" in str(exc) else "housing.sensors"
        raise SceneError(key, f"{exc} (the housing mesh has {st.n_dofs} DOFs)") from None
    return red, st


def reduction_check(red, st) -> ReductionCheck:
    """The reduced housing ``red``'s natural frequencies (seats free) against those of its unreduced structure
    ``st`` in the retained band (:data:`RETAINED_BAND` × the highest retained fixed-interface frequency)."""
    band = RETAINED_BAND * float(red.fixed_interface_hz.max()) if red.fixed_interface_hz.size else 0.0
    reduced = red.frequencies()
    reduced = reduced[reduced <= band]
    if reduced.size == 0:
        return ReductionCheck(band, np.zeros(0), np.zeros(0), 0.0)
    full = lowest_frequencies(st.K, st.M, reduced.size)
    return ReductionCheck(band, full, reduced, float(np.max(np.abs(reduced - full) / full)))
