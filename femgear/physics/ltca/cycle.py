"""The LTCA mesh cycle of the ``ltca`` stiffness level as a typed, frozen product.

:func:`femgear.physics.ltca.level.ltca_cycle` returns an :class:`LTCACycle`: the cycle's
:class:`~femgear.physics.ltca.analysis.LTCAResult` together with what re-running it needs (the member
bodies' compliance model, the force, the modifications, the phases, the stagger and the points per
contact line) and the mesh orders its contact discretisation resolves.  :meth:`LTCACycle.deviated`
re-runs it on flanks moved by a deviation (wear, thermal growth) with the same compliance (no FE
solve); :meth:`LTCACycle.with_orders` records a smaller resolved band.  The dynamics
(:mod:`femgear.system.dynamics.build`) and the coupling loop (:mod:`femgear.system.coupling.loop`) read it;
nothing mutates it.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from femgear.docfields import document_fields
from femgear.physics.ltca.analysis import LTCAModel, LTCAResult


@document_fields
@dataclass(frozen=True)
class LTCACycle:
    """One LTCA mesh cycle at the operating normal force, with its model and the mesh orders it resolves.

    All stiffnesses and approaches are along the normal line of action; phases in transverse
    base pitches over one mesh period [0, 1)."""

    result: LTCAResult
    """the cycle: loaded/unloaded TE, loads, secant/tangent stiffness and pressures per phase [-]"""
    model: LTCAModel | None
    """the pair, material and bulk flank kernels of both member bodies the cycle was solved on (needed to re-run
    it) [-]"""
    force: float
    """total normal force of both helices the cycle carries (operating torque / r_b / cos β_b) [N]"""
    modifications: Any
    """the flank modifications the cycle was run with (the scene's ``[modifications]``; None: none) [-]"""
    n_phases: int
    """phases of the cycle over one mesh period [-]"""
    stagger: float
    """offset of the right helix against the left one [base pitches]"""
    n_line: int
    """points per contact line actually used (after the refinement for resolved orders) [-]"""
    resolved_orders: int | None
    """mesh orders 1…H of the total secant stiffness that the contact discretisation resolves; the dynamics keeps
    only those (:func:`femgear.physics.ltca.level.resolved_orders`; None: all the cycle's phases carry) [-]"""
    harmonic_change: np.ndarray | None = None
    """relative change of each mesh harmonic of the total secant stiffness when the points per line are doubled,
    orders 1… (None where the check did not converge) [-]"""
    orders_check: str | None = None
    """the solver's message where the resolved-orders check of a deviated cycle did not converge (only mesh order 1
    is then kept), else None [-]"""

    @classmethod
    def from_result(cls, result: LTCAResult, model: LTCAModel | None = None, modifications=None,
                    resolved_orders: int | None = None, harmonic_change: np.ndarray | None = None) -> LTCACycle:
        """The cycle of ``result`` (force, phases, stagger and points per line read from it) on ``model``
        (needed by :meth:`deviated` only) with its ``modifications`` (those it was run with)."""
        return cls(result=result, model=model, force=float(result.force), modifications=modifications,
                   n_phases=int(result.phase.size), stagger=float(result.stagger), n_line=int(result.n_line),
                   resolved_orders=resolved_orders, harmonic_change=harmonic_change)

    @functools.cached_property
    def excitation(self) -> dict[str, np.ndarray]:
        """Per helix: secant/tangent stiffness, loaded and unloaded TE, e_s, force, peak pressure
        (:meth:`LTCAResult.excitation`, computed once)."""
        return self.result.excitation()

    @property
    def lte_peak_to_peak(self) -> float:
        """Peak-to-peak of the loaded TE (normal approach δ) over the cycle [m]."""
        return self.result.lte_peak_to_peak()

    @property
    def model_seconds(self) -> float:
        """Wall time to build (or read from the cache) the member bodies' compliance [s]."""
        return self.model.seconds

    @property
    def seconds(self) -> float:
        """Wall time of the cycle's contact solves [s]."""
        return self.result.seconds

    def deviated(self, extra) -> LTCACycle:
        """This cycle re-run with the flank deviation ``extra`` (wear, thermal growth) added to the
        modifications' separation (a :data:`femgear.physics.ltca.separation.Deviation`).

        The same model (its compliance is reused: no FE solve), force, modifications, phases and
        contact points; the resolved mesh orders are kept from this cycle (the contact discretisation,
        which sets them, does not change)."""
        from femgear.physics.ltca.analysis import mesh_cycle

        res = mesh_cycle(self.model, self.force, self.modifications, n_phases=self.n_phases, stagger=self.stagger,
                         n_line=self.n_line, extra=extra, start=self.result)    # warm start: the unique fixed point
        return replace(self, result=res, orders_check=None)

    def with_orders(self, orders: int, change: np.ndarray | None, check: str | None = None) -> LTCACycle:
        """This cycle with ``orders`` resolved mesh orders, their ``change`` and the check's failure message."""
        return replace(self, resolved_orders=int(orders), harmonic_change=change, orders_check=check)
