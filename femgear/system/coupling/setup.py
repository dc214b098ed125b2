"""What stays fixed over the passes of the coupling loop (:class:`CouplingSetup`, built once per case) and the
LTCA reference loads the passes share the load like (:func:`ltca_reference`, :func:`ltca_face_reference`).

Build once, apply many: the dynamic model, its modes, the thermal unit responses and the lubrication solver
are built here once per case; each pass (:mod:`femgear.system.coupling.passes`) replaces only friction and
deviations.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from femgear.case import Case
from femgear.levels import wear as wear_levels
from femgear.levels.lubrication import Lubrication, lubrication_solver
from femgear.physics.ltca.cycle import LTCACycle
from femgear.physics.stiffness.tvms import MeshStiffness
from femgear.physics.wear.face import FaceReference
from femgear.physics.wear.load_sharing import ReferenceLoad
from femgear.system.coupling.thermal import ThermalUnits, thermal_units
from femgear.system.dynamics.build import build_model, stiffness_source
from femgear.system.dynamics.modal import ModalResult, modal_analysis
from femgear.system.dynamics.model import GearRotorModel

#: mesh phases of one period on which the loop's mesh force, deviation tables and reference loads live [-]
N_PHASE = 128


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
    n_phase: int = N_PHASE
    method: str | None = None      #: integrator; None: the dynamics' default for the model
    ltca: LTCACycle | None = None  #: the unworn LTCA cycle of an ``ltca`` stiffness (re-run on deviated flanks)
    #: ``ltca``: the LTCA cycles the wear integration of a pass shares the load like: ``"unworn"`` (the
    #: unworn cycle, moved by the wear grown through the Winkler layer c_l) or ``"pass"`` (blended from
    #: the unworn cycle to the pass's deviated one).  ``"pass"`` reproduces the deviated LTCA at the
    #: pass's wear, but the LTCA unloads worn ends faster than the local update restores them, so the
    #: wear then depends on the previous pass's wear with a gain below −1: the loop oscillates with
    #: ``relax = 1`` and needs under-relaxation; ``"unworn"`` converges like the other levels
    #: (docs/validation/coupling.md).
    wear_anchor: str = "unworn"
    #: ``wear.field = "face"``: the unworn LTCA cycle's face reference (its ζ samples and face grid): the wear
    #: is then integrated face-resolved per member and helix (:mod:`femgear.physics.wear.face`) and the deviated
    #: cycle of each pass runs on that (ρ, ζ) field; None: the face-uniform path wear
    face: FaceReference | None = None
    #: the case's wear model (``physics.wear``; its asperity share is solved once, on first use); None: no wear
    wear: wear_levels.ArchardWear | None = None

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
    def from_case(cls, case: Case, n_phase: int = N_PHASE, lubrication: Lubrication | None = None,
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
    """The unworn cycle's :class:`FaceReference` for ``wear.field = "face"`` (None for ``"path"``, or without a
    cycle: the case's checks refuse ``"face"`` without the ``ltca`` stiffness, :func:`femgear.case.checks.check_wear_field`)."""
    if case.wear.field != "face" or ltca is None:
        return None
    return ltca_face_reference(case.pair, case.path.u, ltca, np.zeros(case.path.u.size), n_phase=n_phase,
                               n_zeta=case.wear.face_points)


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
