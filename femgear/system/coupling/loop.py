"""The bidirectional tribo-dynamic loop (the paper's Fig. 9) as a generator of states.

One iteration:

1. flank deviations → the drive- and coast-flank deviation tables of each helix over
   one mesh period (:mod:`femgear.system.coupling.profile`): wear h1 + h2 acts on the loaded
   (drive) flanks only, thermal expansion ζ_T1 + ζ_T2 on both; each enters the
   dynamics once (:class:`femgear.system.dynamics.model.MeshDeviation`).  With the ``ltca``
   stiffness level the drive flanks' deviations instead re-run the loaded tooth contact
   analysis on the worn and expanded topography (the compliance is reused), whose loaded
   TE excites the dynamics (:func:`femgear.system.dynamics.build.with_deviated_tooth_contact`);
   the coast flanks keep the contact-line mean of −ζ_T;
2. dynamics with the mesh stiffness, μ(u) and those deviations → the dynamic mesh
   force of each helix over one mesh period (phase average of the steady state);
3. load sharing along the contact lines → passage-mean load intensity w̄'(u): a Winkler
   layer c_l(u) on the flank deviations, or with ``ltca`` the load distribution of the
   pass's (deviated) LTCA cycle scaled to the dynamic force (:func:`ltca_reference`);
4. lubrication at every path position (load, radius, entrainment, slide-to-roll,
   bulk temperature: the supply temperature plus the previous pass's bulk flank rise of step 5,
   :func:`femgear.levels.lubrication.bulk_temperature`) → μ(u) and the contact temperature rise ΔT(u);
5. thermal expansion of both flanks for the bulk (body) temperature rise
   (:func:`femgear.system.coupling.thermal.bulk_temperature_rise`: the scene's ``thermal.flank_temperature_rise``, or,
   when that is 0, ``thermal.bulk_fraction`` × the mean contact temperature rise along
   the path, the ISO/TS 6336-21 integral-temperature estimate) → ζ_T1, ζ_T2;
6. Archard wear after ``wear.cycles`` under the dynamic load → h1, h2 (with ``ltca``: the
   load shared like the unworn LTCA cycle, modifications included, moved by the wear grown
   by the Winkler layer, :func:`femgear.physics.wear.load_sharing.reference_loads`; or blended
   towards the pass's cycle, ``CouplingSetup.wear_anchor``);
7. relaxation of the inputs of the next iteration (μ, ζ_T, h) by ``relax``.

Build once, apply many: the dynamic model, its modes, the thermal unit responses and
the lubrication solver are built once per case (:class:`CouplingSetup`); each pass
replaces only friction and deviations.  The states are immutable; stopping, relaxation
policy and logging stay with the caller (:func:`run_coupled` is the standard one: it
stops when the dynamic mesh force and μ change by less than their tolerances and
raises with the history otherwise).
"""

from __future__ import annotations

import logging
import math
import time
from collections.abc import Callable, Iterator, Mapping
from dataclasses import dataclass, field, replace

import numpy as np

from femgear.case import Case
from femgear.docfields import document_fields
from femgear.errors import ConvergenceError, SceneError
from femgear.levels import wear as wear_levels
from femgear.levels.lubrication import Lubrication, bulk_temperature, lubrication_solver
from femgear.perf import Progress
from femgear.physics.ltca.cycle import LTCACycle
from femgear.physics.stiffness.tvms import MeshStiffness
from femgear.physics.wear.face import FaceReference
from femgear.physics.wear.load_sharing import ReferenceLoad, load_map, reference_load_map
from femgear.system.coupling.profile import mesh_deviation
from femgear.system.coupling.thermal import ThermalUnits, bulk_temperature_rise, roll_distances, thermal_units
from femgear.system.dynamics.build import (
    build_model,
    stiffness_source,
    with_deviated_tooth_contact,
    with_deviation,
    with_friction,
)
from femgear.system.dynamics.modal import ModalResult, modal_analysis
from femgear.system.dynamics.model import GearRotorModel, MeshDeviation
from femgear.system.dynamics.run import DynamicsRun, run_dynamics

log = logging.getLogger(__name__)


def line_stiffness(case: Case, mean_helix_stiffness: float, stiffness: MeshStiffness | None = None):
    """Stiffness per unit contact-line length c_l(u) at the case's path positions [N/m²].

    Its mean is the helix's mean mesh stiffness over the mean contact-line length; its
    shape along the path is that of the tooth-pair stiffness per unit face width of the
    stiffness level when the level has one (``pem``, ``fe``: ≈ 25 % lower at the path
    ends than at the pitch point), else uniform (a number).
    """
    c_bar = mean_helix_stiffness / case.pair.mean_contact_length
    if stiffness is None or stiffness.k_pair_per_width is None:
        return c_bar
    k = np.interp(case.path.u, stiffness.u, stiffness.k_pair_per_width)
    return c_bar * k / k.mean()


@dataclass(frozen=True)
class CouplingSetup:
    """What stays fixed over the iterations of one load case (built once)."""

    case: Case
    model: GearRotorModel          #: the dynamic model without friction and deviations
    modal: ModalResult             #: its modes (mean system; independent of friction and deviations)
    lubrication: Lubrication
    thermal: ThermalUnits | None
    c_l: float | np.ndarray        #: stiffness per unit contact-line length along the path [N/m²]
    static_force: float            #: normal force per helix [N]
    n_phase: int = 128
    method: str | None = None      #: integrator; None: the dynamics' default for the model
    ltca: LTCACycle | None = None  #: the unworn LTCA cycle of an ``ltca`` stiffness (re-run on deviated flanks)
    #: ``ltca``: the LTCA cycles the wear integration of a pass shares the load like: ``"unworn"`` (the
    #: unworn cycle, moved by the wear grown through the Winkler layer c_l) or ``"pass"`` (blended from
    #: the unworn cycle to the pass's deviated one).  ``"pass"`` reproduces the deviated LTCA at the
    #: pass's wear, but the LTCA unloads worn ends faster than the local update restores them, so the
    #: wear then depends on the previous pass's wear with a gain below −1: the loop oscillates with
    #: ``relax = 1`` (measured, baseline wear 1e6: largest wear 6.5 ↔ 7.1 µm, Δμ 0.02–0.03 over 12
    #: passes) and needs under-relaxation; ``"unworn"`` converges like the other levels (5 passes).
    wear_anchor: str = "unworn"
    #: ``wear.field = "face"``: the unworn LTCA cycle's face reference (its ζ samples and face grid): the wear
    #: is then integrated face-resolved per member and helix (:mod:`femgear.physics.wear.face`) and the deviated
    #: cycle of each pass runs on that (ρ, ζ) field; None: the face-uniform path wear
    face: FaceReference | None = None
    #: the case's wear model (``physics.wear``; its asperity share is solved once, on first use); None: no wear
    wear: wear_levels.ArchardWear | None = None
    #: ``ltca``: the latest deviated cycle, kept for the next pass (:func:`_deviated_model`): the unworn cycle it
    #: ran from, its deviation inputs and (worn, unworn)
    deviated: dict = field(default_factory=dict, compare=False, repr=False)

    def __post_init__(self):
        if self.wear_anchor not in ("unworn", "pass"):
            raise ValueError(f"wear_anchor must be 'unworn' or 'pass' (got {self.wear_anchor!r})")
        if self.face is not None and self.wear_anchor != "unworn":
            raise ValueError("wear_anchor 'pass' blends path deviations; the face-resolved wear (wear.field = "
                             "\"face\") needs wear_anchor = 'unworn'")

    @property
    def pair(self):
        return self.case.pair

    @property
    def kin(self):
        return self.case.path

    @property
    def stiffness(self):
        return self.model.stiffness

    @classmethod
    def from_case(cls, case: Case, n_phase: int = 128, lubrication: Lubrication | None = None,
                  method: str | None = None, stiffness: MeshStiffness | None = None,
                  wear_anchor: str = "unworn") -> CouplingSetup:
        source = stiffness_source(case, stiffness)
        model = build_model(case, stiffness=source, friction=0.0)
        c_l = line_stiffness(case, float(np.mean(model.stiffness.k_left)), stiffness)
        ltca = getattr(source, "ltca", None)
        return cls(case=case, model=model, modal=modal_analysis(model),
                   lubrication=lubrication or lubrication_solver(case, repeated=True), thermal=thermal_units(case),
                   c_l=c_l, static_force=case.operating.normal_force / case.pair.n_helices, n_phase=n_phase, method=method,
                   ltca=ltca, wear_anchor=wear_anchor, face=_face_reference(case, ltca, n_phase),
                   wear=wear_levels.of(case))


def _face_reference(case: Case, ltca: LTCACycle | None, n_phase: int) -> FaceReference | None:
    """The unworn cycle's :class:`FaceReference` for ``wear.field = "face"`` (None for ``"path"``)."""
    if case.wear.field != "face":
        return None
    if ltca is None:
        raise SceneError("wear.field", '"face" needs physics.stiffness = "ltca" (the LTCA\'s contact-line loads)')
    return ltca_face_reference(case.pair, case.path.u, ltca, np.zeros(case.path.u.size), n_phase=n_phase,
                               n_zeta=case.wear.face_points)


@document_fields
@dataclass(frozen=True)
class CouplingState:
    """The loop after ``iteration`` passes; arrays over the path positions unless noted."""

    iteration: int
    """passes of the loop so far (0: the quasi-static start) [-]"""
    mesh_force: np.ndarray
    """(2, n_phase) dynamic mesh force of the left (row 0) and right (row 1) helix over one mesh period, along the
    normal line of action, at phases i / n_phase [N]"""
    load_per_length: np.ndarray
    """passage-mean load per unit contact-line length w̄' at the path positions (measured from T1) [N/m]"""
    mu: np.ndarray
    """friction coefficient μ at the path positions (relaxed) [-]"""
    temperature_rise: np.ndarray
    """contact (flash) temperature rise at the path positions [K]"""
    flank_temperature_rise: float
    """bulk temperature rise used for the thermal expansion [K]"""
    thermal_deviation: np.ndarray
    """(2, n) thermal growth ζ_T of the pinion (row 0) and gear (row 1) flank along the path (relaxed) [m]"""
    wear: np.ndarray
    """(2, n) wear depth of the pinion (row 0) and gear (row 1) flank along the path (relaxed) [m]"""
    mesh_force_change: float = math.nan
    """largest change of the mesh force against the previous pass, relative to its largest value (NaN at the start) [-]"""
    mu_change: float = math.nan
    """largest absolute change of μ against the previous pass (NaN at the start) [-]"""
    dynamics: DynamicsRun | None = field(default=None, repr=False, compare=False)
    """the pass's dynamics run: settings, simulation, response, modes (None at the start) [-]"""
    lte_peak_to_peak: float = math.nan
    """peak-to-peak loaded TE (normal approach) of the pass's deviated LTCA cycle (``ltca`` only, else NaN) [m]"""
    seconds: float = 0.0
    """wall time of the pass [s]"""
    timings: Mapping[str, float] = field(default_factory=dict, compare=False)
    """wall time of the pass's parts: ``ltca`` (the deviated cycle), ``dynamics`` (with it), ``wear``, ``contact`` [s]"""
    wear_face: np.ndarray | None = field(default=None, repr=False, compare=False)
    """``wear.field = "face"``: (member, helix, u, ζ) wear depth on the setup's face grid; ``wear`` is then its face
    mean over both helices (else None) [m]"""
    thermal_face: np.ndarray | None = field(default=None, repr=False, compare=False)
    """``wear.field = "face"`` with ``thermal = "fe3d"``: (member, helix, u, ζ) ζ_T on the face grid
    (:meth:`ThermalUnits.face`); ``thermal_deviation`` is its face mean (else None) [m]"""

    @property
    def removed(self) -> np.ndarray:
        """Drive-flank material removed at each position, h1 + h2 − ζ_T1 − ζ_T2 [m]."""
        return self.wear.sum(axis=0) - self.thermal_deviation.sum(axis=0)

    @property
    def amplitudes(self) -> Mapping[str, float]:
        return {} if self.dynamics is None else self.dynamics.amplitudes


def ltca_reference(pair, u: np.ndarray, cycle: LTCACycle, deviation: np.ndarray, extra=None,
                   n_phase: int | None = None) -> ReferenceLoad:
    """The load map of the ``ltca`` cycle (:func:`femgear.physics.ltca.level.ltca_cycle` or
    :meth:`~femgear.physics.ltca.cycle.LTCACycle.deviated`, run with the extra deviation ``extra``) at the path
    positions ``u``, computed under the flank deviation ``deviation`` (h1 + h2, or h1 + h2 − ζ_T1 −
    ζ_T2: what its user passes as deviation), with its elastic approach δ − ε (the secant stiffness
    by which a deviation change moves its loads, :meth:`ReferenceLoad.stiffness`).

    ``n_phase``: keep every k-th phase of the cycle, k = ⌈phases / n_phase⌉ (the wear integration
    solves each kept phase of both helices at every step; None keeps all)."""
    res = cycle.result
    k = _phase_stride(res, n_phase)
    return ReferenceLoad(phases=res.phase[::k], load=res.path_load(pair, u, scaled=True)[:, ::k],
                         deviation=np.asarray(deviation, dtype=float), offsets=(0.0, float(cycle.stagger)),
                         approach=res.path_approach(pair, u, cycle.modifications, extra)[:, ::k])


def _phase_stride(res, n_phase: int | None) -> int:
    """Every k-th phase of the LTCA cycle ``res`` is kept, k = ⌈phases / n_phase⌉ (1 for None)."""
    return 1 if n_phase is None else max(1, math.ceil(res.phase.size / n_phase))


def ltca_face_reference(pair, u: np.ndarray, cycle: LTCACycle, deviation, extra=None, n_phase: int | None = None,
                        n_zeta: int = 21):
    """:func:`ltca_reference` with the face coordinate of each sample and a uniform face grid of ``n_zeta``
    points: the input of the face-resolved wear (:class:`femgear.physics.wear.face.FaceReference`), the load averaged
    over the cycle's point spacing b / n_line in ζ (its face resolution, :func:`femgear.physics.wear.face.face_load`)."""
    ref = ltca_reference(pair, u, cycle, deviation, extra, n_phase)
    k = _phase_stride(cycle.result, n_phase)
    return FaceReference(ref=ref, zeta=cycle.result.path_zeta(pair, u)[:, ::k], grid=np.linspace(0.0, pair.b, n_zeta),
                         window=pair.b / cycle.n_line)


def _removed_deviation(setup: CouplingSetup, wear: np.ndarray, zeta: np.ndarray, wear_face: np.ndarray | None = None,
                       thermal_face: np.ndarray | None = None):
    """The drive flanks' deviation the LTCA is re-run on: wear − ζ_T of each member, face-uniform
    (:func:`~femgear.physics.ltca.separation.path_deviation`) or, with a face-resolved wear field, per helix and face
    position (:func:`~femgear.physics.ltca.separation.face_deviation`; the thermal growth ``thermal_face`` (member,
    helix, u, ζ) of ``fe3d``, else ζ_T uniform over the face)."""
    from femgear.physics.ltca.separation import face_deviation, path_deviation

    if wear_face is None:
        return path_deviation(setup.pair, setup.kin.u, wear - zeta)
    thermal = zeta[:, None, :, None] if thermal_face is None else thermal_face
    return face_deviation(setup.pair, setup.kin.u, setup.face.grid, wear_face - thermal)


def _references(setup: CouplingSetup, cycle: LTCACycle | None, wear: np.ndarray, zeta: np.ndarray,
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
        extra = _removed_deviation(setup, wear, zeta, wear_face, thermal_face)
    ref = ltca_reference(setup.pair, setup.kin.u, cycle, h, extra, setup.n_phase)
    if cycle is setup.ltca:
        return ref, replace(ref, deviation=h - z)
    unworn = ltca_reference(setup.pair, setup.kin.u, setup.ltca, z, n_phase=setup.n_phase)
    if setup.wear_anchor == "unworn":
        return unworn, replace(ref, deviation=h - z)
    return replace(unworn, end=ref, start=np.zeros_like(h)), replace(ref, deviation=h - z)


def _contact_response(setup: CouplingSetup, force: np.ndarray, removed: np.ndarray,
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
    w = np.maximum(w, 1e-3 * setup.static_force / pair.mean_contact_length)   # never-loaded ends
    T0 = bulk_temperature(setup.case, flank_rise)
    mu, dT = setup.lubrication(w=w, R=kin.R, ue=kin.ue, srr=np.abs(kin.srr), T=np.full(w.shape, T0))
    return w, np.asarray(mu, dtype=float), np.asarray(dT, dtype=float)


def _thermal(setup: CouplingSetup, dT: np.ndarray) -> tuple[float, np.ndarray, np.ndarray | None]:
    """(bulk rise, ζ_T (2, n), face-resolved ζ_T (member, helix, u, ζ) or None): the face field only with a
    face-resolved wear field (``setup.face``) and 3-D units (``fe3d``), on the wear's face grid."""
    if setup.thermal is None:
        return 0.0, np.zeros((2, setup.kin.u.size)), None
    rise, shaft = bulk_temperature_rise(setup.case, dT), setup.case.thermal.shaft_temperature_rise
    face = None if setup.face is None else \
        setup.thermal.face(roll_distances(setup.pair, setup.kin.u), setup.face.grid, rise, shaft)
    return rise, setup.thermal.deviation(rise, shaft), face


def _wear(setup: CouplingSetup, force: np.ndarray,
          reference: ReferenceLoad | None = None) -> tuple[np.ndarray, np.ndarray | None]:
    """(2, n) wear of pinion and gear along the path and, with ``setup.face``, the face-resolved field
    (member, helix, u, ζ) whose face mean it is (else None)."""
    case = setup.case
    n = setup.kin.u.size
    face = None if setup.face is None else np.zeros((2, 2, n, setup.face.grid.size))
    wear = setup.wear if setup.wear is not None else wear_levels.of(case)
    if wear is None or wear.cycles == 0:
        return np.zeros((2, n)), face
    from femgear.physics.wear import run_wear

    helices = force[:setup.pair.n_helices]
    ws = wear.setup(setup.pair, setup.kin, helices.mean(axis=0) if reference is None else helices, setup.c_l,
                    n_phase=setup.n_phase, reference=reference)
    if face is not None:
        from femgear.physics.wear.face import run_face_wear

        state = run_face_wear(ws, replace(setup.face, ref=reference), wear.cycles)
        return state.path_mean(setup.face.grid), np.array([state.h1, state.h2])
    state = run_wear(ws, wear.cycles)
    return np.array([state.h1, state.h2]), None


def _agree(a: tuple, b: tuple) -> bool:
    """The deviation inputs (wear, ζ_T, face fields) agree to 1e-12 of their largest value: the coupling's
    relaxed update old + (new − old) may move an unchanged field by an ulp, which no LTCA cycle can see."""
    for x, y in zip(a, b):
        if (x is None) != (y is None):
            return False
        if x is None:
            continue
        if x.shape != np.shape(y) or np.max(np.abs(x - y), initial=0.0) > 1e-12 * np.max(np.abs(x), initial=1e-300):
            return False
    return True


def _deviated_model(setup: CouplingSetup, state: CouplingState):
    """The model, the deviation tables it still needs, and the ``ltca`` cycle of the deviated flanks (None without)."""
    u, wear, zeta = setup.kin.u, state.wear, state.thermal_deviation
    deviation = mesh_deviation(setup.pair, u, wear.sum(axis=0), zeta.sum(axis=0), setup.case.stagger, setup.n_phase)
    if setup.ltca is None:
        return setup.model, deviation, None
    if deviation is None:
        return setup.model, None, setup.ltca
    face = state.wear_face
    inputs = (wear, zeta, face, state.thermal_face)
    last = setup.deviated.get("last")
    if last is not None and last[0] is setup.ltca and _agree(last[1], inputs):
        worn, unworn = last[2]          # the pass before ran the LTCA on this very deviation (to 1e-12)
    else:
        extra = _removed_deviation(setup, wear, zeta, face, state.thermal_face)
        worn = setup.ltca.deviated(extra)
        unworn = setup.ltca
        if face is not None:
            unworn, worn = _worn_orders(setup.ltca, worn, extra)
        setup.deviated["last"] = (setup.ltca, tuple(None if a is None else np.array(a) for a in inputs), (worn, unworn))
    coast_only = MeshDeviation(drive=np.zeros_like(deviation.coast), coast=deviation.coast)
    return with_deviated_tooth_contact(setup.model, unworn, worn), coast_only, worn


def _worn_orders(unworn: LTCACycle, worn: LTCACycle, extra) -> tuple[LTCACycle, LTCACycle]:
    """(``unworn``, ``worn``) with the mesh orders that the contact discretisation resolves on the worn flanks too
    (:func:`femgear.physics.ltca.level.resolved_orders` with the deviation ``extra``; the fewer of the two), in
    both: the dynamics keeps only those (face-resolved wear).

    A face-resolved worn field moves load along the lines point by point, and the LTCA re-run on it
    resolves fewer orders than on the unworn flanks: on the rig's test gear after 1e6 cycles 4 (face
    field) against 10 (unworn) and 8 (face-uniform wear) by the level's 25 % criterion; the face field's
    loaded TE (field and re-run both at 16 and at 32 points per line) kept order 1 within 0.5 % but
    orders 2, 3, 6, 9, 10 changed by 64–530 %.  ≈ 1.5 s a pass (two cycles of 64 phases without line
    loads).  Where the refined cycle of the check does not converge (its Hertz-width fixed point on the
    crowned baseline's face-worn flanks, 32 points per line), the resolution is unknown: only the mesh
    order 1 is kept, with a warning, and ``worn.orders_check`` holds the solver's message."""
    import logging

    from femgear.physics.ltca.level import resolved_orders

    check = None
    try:
        orders, change = resolved_orders(unworn.model, unworn.force, unworn.modifications, unworn.stagger,
                                         unworn.n_line, extra)
    except ConvergenceError as exc:
        logging.getLogger(__name__).warning("worn-flank resolution check failed (%s): keeping mesh order 1", exc)
        orders, change, check = 1, None, str(exc)
    orders = min(orders, unworn.resolved_orders)
    return (replace(unworn, resolved_orders=orders),
            worn.with_orders(orders, change, check))


def pass_model(setup: CouplingSetup, state: CouplingState) -> tuple[GearRotorModel, LTCACycle | None]:
    """The dynamic model of the pass after ``state``: its friction μ(u) and flank deviations (wear opens the drive
    flanks' dead zone, thermal growth closes both; :class:`femgear.system.dynamics.model.MeshDeviation`), and the
    pass's LTCA cycle (None without ``ltca``).  A dead zone closed below zero is refused naming what closes it."""
    u_tab, mu_tab = setup.kin.u, state.mu
    mu = (lambda u: np.interp(u, u_tab, mu_tab)) if np.any(mu_tab > 0) else 0.0
    base, deviation, cycle = _deviated_model(setup, state)
    try:
        return with_deviation(with_friction(base, mu), deviation), cycle
    except SceneError as exc:
        raise SceneError(exc.key, f"{exc.message}. {_dead_zone_parts(setup, state)}") from None


def _dead_zone_parts(setup: CouplingSetup, state: CouplingState) -> str:
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


def _dynamics(setup: CouplingSetup, state: CouplingState) -> tuple[np.ndarray, DynamicsRun, LTCACycle | None]:
    """Dynamic mesh force per helix over one mesh period for the inputs in ``state`` (and the pass's LTCA cycle)."""
    model, cycle = pass_model(setup, state)
    num = setup.case.numerics
    run = run_dynamics(model, method=setup.method or num.dynamics_method, cycles=num.dynamics_cycles,
                       transient_cycles=num.transient_cycles, steps_per_period=num.steps_per_mesh_period,
                       modal=setup.modal)
    return phase_average(run.response, setup.n_phase), run, cycle


def phase_average(res, n_phase: int) -> np.ndarray:
    """Mesh force per helix averaged over the recorded mesh periods, at phases i/n_phase.

    Samples are binned by mesh phase (at most as many bins as samples per period, so
    no bin is empty) and the bin means interpolated periodically onto the n_phase grid.
    """
    phase = np.mod(res.t * res.mesh_frequency, 1.0)
    per_period = res.t.size / max(res.mesh_frequency * (res.t[-1] - res.t[0]), 1.0)
    n_bins = int(min(n_phase, np.floor(per_period)))
    if n_bins < 8:
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


def coupling_iterations(setup: CouplingSetup, relax: float = 1.0) -> Iterator[CouplingState]:
    """Yield the quasi-static start (iteration 0) and then one state per pass of the loop."""
    if not 0 < relax <= 1:
        raise ValueError(f"relax must be in (0, 1] (got {relax!r})")
    t0 = time.perf_counter()
    force = np.full((2, setup.n_phase), setup.static_force)
    zero = np.zeros((2, setup.kin.u.size))
    ref_wear, ref_contact = _references(setup, setup.ltca, zero, zero)
    wear, face = _wear(setup, force, ref_wear)
    w, mu, dT = _contact_response(setup, force, wear.sum(axis=0), ref_contact, setup.case.thermal.flank_temperature_rise)
    rise, zeta, zeta_face = _thermal(setup, dT)
    state = CouplingState(iteration=0, mesh_force=force, load_per_length=w, mu=mu, temperature_rise=dT,
                          flank_temperature_rise=rise, thermal_deviation=zeta, wear=wear,
                          seconds=time.perf_counter() - t0, wear_face=face, thermal_face=zeta_face)
    yield state
    while True:
        t0 = time.perf_counter()
        force, run, cycle = _dynamics(setup, state)
        t1 = time.perf_counter()
        ref_wear, ref_contact = _references(setup, cycle, state.wear, state.thermal_deviation, state.wear_face,
                                            state.thermal_face)
        wear_new, face_new = _wear(setup, force, ref_wear)
        t2 = time.perf_counter()
        w, mu_new, dT = _contact_response(setup, force, state.removed, ref_contact, state.flank_temperature_rise)
        rise, zeta_new, zeta_face = _thermal(setup, dT)
        mix = lambda old, new: old + relax * (new - old)  # noqa: E731
        lte = math.nan if cycle is None else cycle.lte_peak_to_peak
        rerun = 0.0 if cycle is None or cycle is setup.ltca else cycle.seconds
        timings = {"ltca": rerun, "dynamics": t1 - t0, "wear": t2 - t1, "contact": time.perf_counter() - t2}
        state = replace(
            state, iteration=state.iteration + 1, mesh_force=force, load_per_length=w, mu=mix(state.mu, mu_new),
            temperature_rise=dT, flank_temperature_rise=rise, thermal_deviation=mix(state.thermal_deviation, zeta_new),
            wear=mix(state.wear, wear_new),
            mesh_force_change=_force_change(force, state.mesh_force),
            mu_change=float(np.max(np.abs(mu_new - state.mu))), dynamics=run, lte_peak_to_peak=lte,
            seconds=time.perf_counter() - t0, timings=timings,
            wear_face=None if face_new is None else mix(state.wear_face, face_new),
            thermal_face=None if zeta_face is None else mix(state.thermal_face, zeta_face))
        for name, value in (("mesh_force", force), ("mu", state.mu), ("wear", state.wear)):
            if not np.all(np.isfinite(value)):
                raise ConvergenceError("coupling", f"non-finite {name} in iteration {state.iteration}")
        yield state


def _force_change(new: np.ndarray, old: np.ndarray) -> float:
    """The loop's mesh-force change: max |new − old| relative to max |new|."""
    return float(np.max(np.abs(new - old)) / np.max(np.abs(new)))


def _same(a: CouplingState, b: CouplingState, tol_force: float, tol_mu: float) -> bool:
    """Whether two passes agree to the loop's tolerances (mesh force relative, μ absolute)."""
    return _force_change(a.mesh_force, b.mesh_force) < tol_force and float(np.max(np.abs(a.mu - b.mu))) < tol_mu


@document_fields
@dataclass(frozen=True)
class CouplingHistory:
    """Per-pass convergence measures (iteration 0 is the quasi-static start)."""

    iteration: tuple[int, ...]
    """pass number of each entry (0: the quasi-static start) [-]"""
    mesh_force_change: tuple[float, ...]
    """relative mesh-force change of each pass (None/NaN at the start) [-]"""
    mu_change: tuple[float, ...]
    """absolute μ change of each pass (None/NaN at the start) [-]"""
    seconds: tuple[float, ...]
    """wall time of each pass [s]"""


@document_fields
@dataclass(frozen=True)
class CoupledResult:
    state: CouplingState
    """the last state of the loop (the converged one, or the first dynamic pass of a one-way run) [-]"""
    history: CouplingHistory
    """the per-pass convergence measures [-]"""
    converged: bool
    """whether the loop met its tolerances (a one-way run counts as converged) [-]"""
    seconds: float
    """wall time of the whole loop [s]"""
    alternation: tuple[float, float] | None = None
    """where the loop settled into a two-pass cycle instead (each pass equal to the one before the last, to the
    tolerances, the passes between differing): the (relative mesh-force, absolute μ) change between its two
    states, the answer's uncertainty (a contact switch of the discrete LTCA at a relief edge, flipped by a
    sub-nanometre flank deviation, :func:`run_coupled`); None where it converged [-]"""


def run_coupled(setup: CouplingSetup, tol_force: float = 1e-6, tol_mu: float = 1e-6, max_iter: int = 30,
                relax: float = 1.0, one_way: bool = False,
                progress: Callable[[CouplingState], None] | None = None) -> CoupledResult:
    """Iterate to convergence; ``one_way`` stops after the first dynamic pass.

    ``progress``: called with every state (logging, progress display) as it arrives.

    Converged when the dynamic mesh force changes by less than ``tol_force`` (relative,
    paper: 1e-6) and μ by less than ``tol_mu`` between two passes.  A loop that instead alternates
    between two states (each of two successive passes within the tolerances of the pass before the
    last) stops there with a warning and the difference of the two states in
    :attr:`CoupledResult.alternation`: a map with a jump cannot converge below it (measured: the paper's
    rig condition 100 rpm / 150 N·m with the test gear's tip relief and ``ltca``, where ζ_T moving by
    0.24 nm switches the load at the path end by 2 %, μ there by 3.8e-4, and the mesh force by 1e-5;
    relaxation moves the inputs towards the jump but not the residual below it).  Raises
    :class:`ConvergenceError` carrying the history after ``max_iter`` passes.
    """
    history: dict[str, list] = {"iteration": [], "mesh_force_change": [], "mu_change": [], "seconds": []}
    start = time.perf_counter()
    passes: list[CouplingState] = []
    lines = Progress(f"coupling of scene {setup.case.name!r}", None)     # shown once the loop has run 10 s

    def done(state: CouplingState, alternation: tuple[float, float] | None = None) -> CoupledResult:
        return CoupledResult(state, CouplingHistory(**{k: tuple(v) for k, v in history.items()}), True,
                             time.perf_counter() - start, alternation)

    for state in coupling_iterations(setup, relax):
        history["iteration"].append(state.iteration)
        history["mesh_force_change"].append(state.mesh_force_change)
        history["mu_change"].append(state.mu_change)
        history["seconds"].append(state.seconds)
        if progress is not None:
            progress(state)
        lines(state.iteration, f"pass {state.iteration} done in {state.seconds:.1f} s, mesh-force change "
                               f"{state.mesh_force_change:.3g}, μ change {state.mu_change:.3g}" if state.iteration else
                               f"quasi-static start done in {state.seconds:.1f} s")
        if state.iteration == 0:
            continue
        if one_way or (state.mesh_force_change < tol_force and state.mu_change < tol_mu):
            return done(state)
        passes = [*passes[-3:], state]
        if len(passes) == 4 and all(_same(passes[k], passes[k - 2], tol_force, tol_mu) for k in (2, 3)):
            log.warning(f"coupling of scene {setup.case.name!r}: passes {state.iteration - 3}-{state.iteration} "
                        f"alternate between two states (mesh force {state.mesh_force_change:.2g} relative, μ "
                        f"{state.mu_change:.2g} apart; a contact switch of the discrete LTCA): the last is the "
                        "result, their difference its uncertainty (summary.coupling.alternation)")
            return done(state, (state.mesh_force_change, state.mu_change))
        if state.iteration >= max_iter:
            raise ConvergenceError(
                f"coupling of scene {setup.case.name!r}",
                f"no convergence in {max_iter} iterations (tolerances {tol_force:g}, {tol_mu:g})", history)
    raise AssertionError("unreachable")  # pragma: no cover

