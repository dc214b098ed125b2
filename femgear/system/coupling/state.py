"""The immutable records of the coupling loop: one :class:`CouplingState` per pass, the run's
:class:`CouplingHistory` and :class:`CoupledResult`, and the deviated LTCA cycles a pass hands to the next
(:class:`DeviatedCycle`)."""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field

import numpy as np

from femgear.docfields import document_fields
from femgear.physics.ltca.cycle import LTCACycle
from femgear.system.dynamics.run import DynamicsRun

#: relative agreement (of the largest value) below which two deviations are the same to any LTCA cycle: the
#: coupling's relaxed update old + (new − old) may move an unchanged field by an ulp [-]
AGREEMENT = 1e-12


def agree(a: tuple, b: tuple) -> bool:
    """The deviation inputs (wear, ζ_T, face fields) agree to :data:`AGREEMENT` of their largest value."""
    for x, y in zip(a, b):
        if (x is None) != (y is None):
            return False
        if x is None:
            continue
        if x.shape != np.shape(y) or np.max(np.abs(x - y), initial=0.0) > AGREEMENT * np.max(np.abs(x), initial=1e-300):
            return False
    return True


@document_fields
@dataclass(frozen=True)
class DeviatedCycle:
    """The ``ltca`` cycles one pass ran on its deviated flanks, with what they ran from: the next pass reuses them
    where it runs from the same unworn cycle on a deviation that :func:`agree` s with theirs."""

    source: LTCACycle
    """the unworn cycle they ran from (the setup's) [-]"""
    inputs: tuple
    """(wear [m], ζ_T [m], wear face field [m], thermal face field [m]) they ran on, copies [-]"""
    worn: LTCACycle
    """the cycle of the deviated flanks [-]"""
    unworn: LTCACycle
    """the unworn cycle, with the mesh orders resolved on both [-]"""

    def reusable(self, source: LTCACycle, inputs: tuple) -> bool:
        return self.source is source and agree(self.inputs, inputs)


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
    (:meth:`femgear.physics.body.thermal_units.ThermalUnits.face`); ``thermal_deviation`` is its face mean (else None) [m]"""
    deviated: DeviatedCycle | None = field(default=None, repr=False, compare=False)
    """``ltca``: the cycles the pass ran on its deviated flanks, which the next pass reuses where its deviation
    agrees (None: no deviated cycle ran) [-]"""

    @property
    def removed(self) -> np.ndarray:
        """Drive-flank material removed at each position, h1 + h2 − ζ_T1 − ζ_T2 [m]."""
        return self.wear.sum(axis=0) - self.thermal_deviation.sum(axis=0)

    @property
    def amplitudes(self) -> Mapping[str, float]:
        return {} if self.dynamics is None else self.dynamics.amplitudes


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
