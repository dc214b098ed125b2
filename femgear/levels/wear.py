"""Wear levels (the ``[physics] wear`` key).

The factory of ``archard`` returns an :class:`ArchardWear` (the ``[wear]`` coefficient, the
material's hardness and the number of cycles, and :meth:`ArchardWear.setup` for a load case);
``none`` returns None: a case "has wear" when its product is not None (:func:`has_wear`).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from femgear.levels.registry import Registry

if TYPE_CHECKING:
    from femgear.case import Case
    from femgear.physics.geometry import GearPair, PathKinematics
    from femgear.physics.wear import WearSetup
    from femgear.physics.wear.load_sharing import ReferenceLoad

REGISTRY = Registry("wear")


@dataclass(frozen=True)
class ArchardWear:
    """Archard wear of the case: what stays fixed over the runs of one case."""

    coefficient: float   #: dimensionless Archard K [-]
    hardness: float      #: flank hardness H [Pa]
    cycles: float        #: pinion revolutions to wear over [-]
    face: bool           #: True: face-resolved (``wear.field = "face"``); False: along the path
    face_points: int     #: points over the face of each helix (face-resolved) [-]

    def setup(self, pair: GearPair, kin: PathKinematics, force: float | np.ndarray, c_l: float | np.ndarray,
              n_phase: int = 64, reference: ReferenceLoad | None = None) -> WearSetup:
        """The :class:`femgear.physics.wear.WearSetup` of one load case (force per helix, stiffness c_l)."""
        from femgear.physics.wear import WearSetup

        return WearSetup(pair=pair, kin=kin, force=force, c_l=c_l, coefficient=self.coefficient,
                         hardness=self.hardness, n_phase=n_phase, reference=reference)


REGISTRY.register("none", "no wear")(lambda case, **_: None)


@REGISTRY.register("archard", "Archard wear along the path (or over the face) with the load updated as the "
                              "profile wears")
def _archard(case: Case, **_: Any) -> ArchardWear:
    w = case.wear
    return ArchardWear(coefficient=w.coefficient, hardness=case.material.hardness, cycles=w.cycles,
                       face=w.field == "face", face_points=w.face_points)


def of(case: Case) -> ArchardWear | None:
    """The wear model of the case's ``physics.wear`` level (None for ``none``)."""
    return REGISTRY.build(case.levels.wear, case)


def has_wear(case: Case) -> bool:
    """Whether the case's wear level wears the flanks."""
    return of(case) is not None


def static_setup(case: Case, kin: PathKinematics | None = None, n_phase: int = 64) -> WearSetup:
    """The static load sharing of the case (any wear level's numbers): each helix carries F_bn/2, c_l from
    ``stiffness.mesh_stiffness_per_width`` over the mean contact length; ``kin`` defaults to the case's path."""
    from femgear.physics.wear import WearSetup

    pair = case.pair
    c_l = case.stiffness.mesh_stiffness_per_width * pair.b / pair.mean_contact_length
    return WearSetup(pair=pair, kin=case.path if kin is None else kin, force=case.operating.normal_force / 2,
                     c_l=c_l, coefficient=case.wear.coefficient, hardness=case.material.hardness, n_phase=n_phase)
