"""The pure functions of one pass of the coupling loop (:mod:`femgear.system.coupling.loop`): the reference
loads of the pass's LTCA cycle, the contact response (load sharing, then lubrication), the thermal growth, the
wear, the pass's dynamic model on its deviated flanks and the phase average of its mesh force.  Each reads the
:class:`~femgear.system.coupling.setup.CouplingSetup` and the previous :class:`~femgear.system.coupling.state.
CouplingState` and returns new arrays (or the pass's :class:`~femgear.system.coupling.state.DeviatedCycle`):
none keeps state.
"""

from __future__ import annotations

import logging
from dataclasses import replace

import numpy as np

from femgear.errors import ConvergenceError, SceneError
from femgear.levels import wear as wear_levels
from femgear.levels.lubrication import bulk_temperature
from femgear.physics.ltca import level as ltca_level
from femgear.physics.ltca.cycle import LTCACycle
from femgear.physics.ltca.separation import face_deviation, path_deviation
from femgear.physics.wear import run_wear
from femgear.physics.wear.face import run_face_wear
from femgear.physics.wear.load_sharing import ReferenceLoad, load_map, reference_load_map
from femgear.system.coupling.profile import mesh_deviation
from femgear.system.coupling.setup import CouplingSetup, ltca_reference
from femgear.system.coupling.state import CouplingState, DeviatedCycle
from femgear.system.coupling.thermal import bulk_temperature_rise, roll_distances
from femgear.system.dynamics.build import with_deviated_tooth_contact, with_deviation, with_friction
from femgear.system.dynamics.model import GearRotorModel, MeshDeviation
from femgear.system.dynamics.run import DynamicsRun, run_dynamics

log = logging.getLogger(__name__)

#: the load per contact-line length of never-loaded path ends, as a fraction of the static mean [-]
UNLOADED_FLOOR = 1e-3
#: the fewest mesh-phase bins the phase average needs per recorded mesh period [-]
MIN_PHASE_BINS = 8


def removed_deviation(setup: CouplingSetup, wear: np.ndarray, zeta: np.ndarray, wear_face: np.ndarray | None = None,
                      thermal_face: np.ndarray | None = None):
    """The drive flanks' deviation the LTCA is re-run on: wear − ζ_T of each member, face-uniform
    (:func:`~femgear.physics.ltca.separation.path_deviation`) or, with a face-resolved wear field, per helix and face
    position (:func:`~femgear.physics.ltca.separation.face_deviation`; the thermal growth ``thermal_face`` (member,
    helix, u, ζ) of ``fe3d``, else ζ_T uniform over the face)."""
    if wear_face is None:
        return path_deviation(setup.pair, setup.kin.u, wear - zeta)
    thermal = zeta[:, None, :, None] if thermal_face is None else thermal_face
    return face_deviation(setup.pair, setup.kin.u, setup.face.grid, wear_face - thermal)


def reference_loads(setup: CouplingSetup, cycle: LTCACycle | None, wear: np.ndarray, zeta: np.ndarray,
                    wear_face: np.ndarray | None = None, thermal_face: np.ndarray | None = None):
    """(wear, contact) reference load maps for the pass whose LTCA cycle ``cycle`` ran on the deviation
    wear − ζ_T (None, None without ``ltca``).

    The contact response sees h1 + h2 − ζ_T = that deviation: the cycle's own loads.  The wear
    integration runs h = h1 + h2 from 0 to the pass's wear, from the unworn cycle (run without wear
    and thermal growth, i.e. at h = Σζ_T in h), which the Winkler layer moves by the wear grown
    (``wear_anchor = "unworn"``); with ``"pass"`` the reference ends at the pass's cycle (at h =
    Σ wear), blended along the way by the wear's progress towards Σ wear (see :class:`CouplingSetup`).
    """
    if cycle is None or setup.pair.beta_b == 0:
        # spur: a contact line is the whole face at one u, and the pairs in contact share the load by the
        # Winkler layer of the level's pair stiffness (the spur load map); the LTCA's per-line reference
        # reads helical lines
        return None, None
    h, z = wear.sum(axis=0), zeta.sum(axis=0)
    extra = None
    if cycle is not setup.ltca:
        extra = removed_deviation(setup, wear, zeta, wear_face, thermal_face)
    ref = ltca_reference(setup.pair, setup.kin.u, cycle, h, extra, setup.n_phase)
    if cycle is setup.ltca:
        return ref, replace(ref, deviation=h - z)
    unworn = ltca_reference(setup.pair, setup.kin.u, setup.ltca, z, n_phase=setup.n_phase)
    if setup.wear_anchor == "unworn":
        return unworn, replace(ref, deviation=h - z)
    return replace(unworn, end=ref, start=np.zeros_like(h)), replace(ref, deviation=h - z)


def contact_response(setup: CouplingSetup, force: np.ndarray, removed: np.ndarray,
                     reference: ReferenceLoad | None = None, flank_rise: float = 0.0):
    """w̄'(u) for per-helix forces over the mesh phases, then μ, ΔT from the lubrication at the flanks' bulk
    temperature (the supply temperature plus ``flank_rise`` [K], the previous pass's bulk rise)."""
    pair, kin = setup.pair, setup.kin
    if reference is None:
        maps = [load_map(pair, kin.u, force[s], removed, setup.c_l, offset=off)
                for s, off in enumerate((0.0, setup.case.stagger)[:pair.n_helices])]
        w = np.mean([m.mean_load for m in maps], axis=0)
    else:
        w = reference_load_map(pair, kin.u, force, removed, setup.c_l, reference).mean_load
    w = np.maximum(w, UNLOADED_FLOOR * setup.static_force / pair.mean_contact_length)   # never-loaded ends
    T0 = bulk_temperature(setup.case, flank_rise)
    mu, dT = setup.lubrication(w=w, R=kin.R, ue=kin.ue, srr=np.abs(kin.srr), T=np.full(w.shape, T0))
    return w, np.asarray(mu, dtype=float), np.asarray(dT, dtype=float)


def pass_thermal(setup: CouplingSetup, dT: np.ndarray) -> tuple[float, np.ndarray, np.ndarray | None]:
    """(bulk rise, ζ_T (2, n), face-resolved ζ_T (member, helix, u, ζ) or None): the face field only with a
    face-resolved wear field (``setup.face``) and 3-D units (``fe3d``), on the wear's face grid."""
    if setup.thermal is None:
        return 0.0, np.zeros((2, setup.kin.u.size)), None
    rise, shaft = bulk_temperature_rise(setup.case, dT), setup.case.thermal.shaft_temperature_rise
    face = None if setup.face is None else \
        setup.thermal.face(roll_distances(setup.pair, setup.kin.u), setup.face.grid, rise, shaft)
    return rise, setup.thermal.deviation(rise, shaft), face


def pass_wear(setup: CouplingSetup, force: np.ndarray,
              reference: ReferenceLoad | None = None) -> tuple[np.ndarray, np.ndarray | None]:
    """(2, n) wear of pinion and gear along the path and, with ``setup.face``, the face-resolved field
    (member, helix, u, ζ) whose face mean it is (else None)."""
    case = setup.case
    n = setup.kin.u.size
    face = None if setup.face is None else np.zeros((2, 2, n, setup.face.grid.size))
    wear = setup.wear if setup.wear is not None else wear_levels.of(case)
    if wear is None or wear.cycles == 0:
        return np.zeros((2, n)), face
    helices = force[:setup.pair.n_helices]
    ws = wear.setup(setup.pair, setup.kin, helices.mean(axis=0) if reference is None else helices, setup.c_l,
                    n_phase=setup.n_phase, reference=reference)
    if face is not None:
        state = run_face_wear(ws, replace(setup.face, ref=reference), wear.cycles)
        return state.path_mean(setup.face.grid), np.array([state.h1, state.h2])
    state = run_wear(ws, wear.cycles)
    return np.array([state.h1, state.h2]), None


def deviated_model(setup: CouplingSetup, state: CouplingState):
    """(model, the deviation tables it still needs, the ``ltca`` cycle of the deviated flanks or None without, the
    :class:`DeviatedCycle` the pass ran or reused, None where it ran none): the cycles of ``state.deviated`` (the
    pass before) are reused where they ran on this very deviation (to :data:`~femgear.system.coupling.state.AGREEMENT`)."""
    u, wear, zeta = setup.kin.u, state.wear, state.thermal_deviation
    deviation = mesh_deviation(setup.pair, u, wear.sum(axis=0), zeta.sum(axis=0), setup.case.stagger, setup.n_phase)
    if setup.ltca is None:
        return setup.model, deviation, None, None
    if deviation is None:
        return setup.model, None, setup.ltca, None
    face = state.wear_face
    inputs = (wear, zeta, face, state.thermal_face)
    deviated = state.deviated
    if deviated is None or not deviated.reusable(setup.ltca, inputs):
        extra = removed_deviation(setup, wear, zeta, face, state.thermal_face)
        worn = setup.ltca.deviated(extra)
        unworn = setup.ltca
        if face is not None:
            unworn, worn = worn_orders(setup.ltca, worn, extra)
        deviated = DeviatedCycle(setup.ltca, tuple(None if a is None else np.array(a) for a in inputs), worn, unworn)
    coast_only = MeshDeviation(drive=np.zeros_like(deviation.coast), coast=deviation.coast)
    return with_deviated_tooth_contact(setup.model, deviated.unworn, deviated.worn), coast_only, deviated.worn, deviated


def worn_orders(unworn: LTCACycle, worn: LTCACycle, extra) -> tuple[LTCACycle, LTCACycle]:
    """(``unworn``, ``worn``) with the mesh orders that the contact discretisation resolves on the worn flanks too
    (:func:`femgear.physics.ltca.level.resolved_orders` with the deviation ``extra``; the fewer of the two), in
    both: the dynamics keeps only those (face-resolved wear).

    A face-resolved worn field moves load along the lines point by point, and the LTCA re-run on it resolves
    fewer orders than on the unworn flanks (measured in docs/validation/coupling.md).  Where the refined cycle of
    the check does not converge, the resolution is unknown: only the mesh order 1 is kept, with a warning, and
    ``worn.orders_check`` holds the solver's message."""
    check = None
    try:
        orders, change = ltca_level.resolved_orders(unworn.model, unworn.force, unworn.modifications, unworn.stagger,
                                         unworn.n_line, extra)
    except ConvergenceError as exc:
        log.warning("worn-flank resolution check failed (%s): keeping mesh order 1", exc)
        orders, change, check = 1, None, str(exc)
    orders = min(orders, unworn.resolved_orders)
    return (replace(unworn, resolved_orders=orders),
            worn.with_orders(orders, change, check))


def pass_model(setup: CouplingSetup, state: CouplingState) -> tuple[GearRotorModel, LTCACycle | None,
                                                                     DeviatedCycle | None]:
    """The dynamic model of the pass after ``state``: its friction μ(u) and flank deviations (wear opens the drive
    flanks' dead zone, thermal growth closes both; :class:`femgear.system.dynamics.model.MeshDeviation`), the
    pass's LTCA cycle (None without ``ltca``) and the :class:`DeviatedCycle` it ran on (None: none).  A dead zone
    closed below zero is refused naming what closes it."""
    u_tab, mu_tab = setup.kin.u, state.mu
    mu = (lambda u: np.interp(u, u_tab, mu_tab)) if np.any(mu_tab > 0) else 0.0
    base, deviation, cycle, deviated = deviated_model(setup, state)
    try:
        return with_deviation(with_friction(base, mu), deviation), cycle, deviated
    except SceneError as exc:
        raise SceneError(exc.key, f"{exc.message}. {dead_zone_parts(setup, state)}") from None


def dead_zone_parts(setup: CouplingSetup, state: CouplingState) -> str:
    """What opens and what closes the dead zone in ``state``, separately (the refusal's second sentence)."""
    pair, u, stagger = setup.pair, setup.kin.u, setup.case.stagger
    zero = np.zeros(u.size)
    parts = []
    for name, wear, zeta in (("the thermal growth", zero, state.thermal_deviation.sum(axis=0)),
                             ("the wear", state.wear.sum(axis=0), zero)):
        d = mesh_deviation(pair, u, wear, zeta, stagger, setup.n_phase)
        if d is not None:
            parts.append((name, float(np.min(d.opening)), float(np.max(d.opening))))
    text = []
    for name, lo, hi in parts:
        if lo < 0:
            text.append(f"{name} closes it by up to {-lo * 1e6:.3g} µm")
        elif hi > 0:
            text.append(f"{name} opens it by {lo * 1e6:.3g}–{hi * 1e6:.3g} µm (material removed)")
    rise = state.flank_temperature_rise
    return (f"Of these, {' and '.join(text) or 'no part alone closes it'} (bulk flank temperature rise "
            f"{rise:.3g} K over the oil)")


def pass_dynamics(setup: CouplingSetup, state: CouplingState) -> tuple[np.ndarray, DynamicsRun, LTCACycle | None,
                                                                       DeviatedCycle | None]:
    """Dynamic mesh force per helix over one mesh period for the inputs in ``state``, the run, the pass's LTCA
    cycle and the deviated cycles it ran on (:func:`pass_model`)."""
    model, cycle, deviated = pass_model(setup, state)
    num = setup.case.numerics
    run = run_dynamics(model, method=setup.method or num.dynamics_method, cycles=num.dynamics_cycles,
                       transient_cycles=num.transient_cycles, steps_per_period=num.steps_per_mesh_period,
                       modal=setup.modal)
    return phase_average(run.response, setup.n_phase), run, cycle, deviated


def phase_average(res, n_phase: int) -> np.ndarray:
    """Mesh force per helix averaged over the recorded mesh periods, at phases i/n_phase.

    Samples are binned by mesh phase (at most as many bins as samples per period, so
    no bin is empty) and the bin means interpolated periodically onto the n_phase grid.
    """
    phase = np.mod(res.t * res.mesh_frequency, 1.0)
    per_period = res.t.size / max(res.mesh_frequency * (res.t[-1] - res.t[0]), 1.0)
    n_bins = int(min(n_phase, np.floor(per_period)))
    if n_bins < MIN_PHASE_BINS:
        raise ValueError(f"too few recorded samples per mesh period ({per_period:.1f}) for the phase average")
    bins = np.minimum((phase * n_bins).astype(int), n_bins - 1)
    count = np.bincount(bins, minlength=n_bins)
    centres = (np.arange(n_bins) + 0.5) / n_bins
    grid = np.arange(n_phase) / n_phase
    out = []
    for s in range(2):
        mean = np.bincount(bins, res.mesh_force[:, s], n_bins) / np.maximum(count, 1)
        ok = count > 0
        out.append(np.interp(grid, centres[ok], mean[ok], period=1.0))
    return np.array(out)
