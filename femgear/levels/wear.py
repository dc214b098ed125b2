"""Wear levels (the ``[physics] wear`` key).

The factory of ``archard`` returns an :class:`ArchardWear` (the ``[wear]`` coefficient, the
material's hardness and the number of cycles, and :meth:`ArchardWear.setup` for a load case);
``none`` returns None: a case "has wear" when its product is not None (:func:`has_wear`).

``wear.load`` says which load wears: ``"asperity"`` (default) the part the asperities carry through the
film, from the JGP split of the ``formula`` level's thermal film at every path position
(:mod:`femgear.physics.wear.regime`; the table is solved once per product, on first use:
:attr:`ArchardWear.share_table`); ``"total"`` the paper's constant coefficient on the whole load.  Either
way :meth:`ArchardWear.regime` says how much of the load the film carries, and :meth:`ArchardWear.warnings`
warns where the constant-coefficient form wears a pair whose film carries it.

Roughness of the split: the tribology's composite σ of the flanks' one description (``[roughness]``: R_a or R_q
per member, or the finishing, ground by default: R_a 0.4 µm, σ 0.71 µm; :attr:`femgear.case.Case.flanks`), also
where the tribology takes the flanks as smooth (``roughness.model = "smooth"``: σ = √(Rq1² + Rq2²) then).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property
from typing import Any

import numpy as np

from femgear.case import Case
from femgear.levels.lubrication import flank_asperities, line_friction
from femgear.levels.registry import Registry
from femgear.physics.geometry import GearPair, PathKinematics
from femgear.physics.lubrication.mixed import Roughness, split_table
from femgear.physics.wear import WearSetup
from femgear.physics.wear.load_sharing import ReferenceLoad
from femgear.physics.wear.regime import AsperityShare, Regime, regime

REGISTRY = Registry("wear")

#: loads of the asperity-share table, relative to the nominal load per unit line length of one helix, and their
#: number (log-spaced: 1.33 apart; the LTCA's path ends carry up to 6×, a dynamic load swings about the mean)
LOAD_SPAN = (0.01, 30.0)
LOAD_POINTS = 29


@dataclass(frozen=True)
class FilmInputs:
    """What the asperity share of the case's path is solved from (typed parts of the case)."""

    R: np.ndarray            #: reduced radius at the path positions [m]
    ue: np.ndarray           #: entrainment speed [m/s]
    srr: np.ndarray          #: slide-to-roll ratio [-]
    temperature: float       #: bulk oil temperature [K]
    oil: Any                 #: the oil law (:class:`femgear.physics.lubrication.oil.OilLaw`)
    E_red: float             #: reduced modulus E' [Pa]
    solids: Any              #: effusivities and oil conductivity (:class:`femgear.physics.lubrication.traction.Solids`)
    roughness: Roughness     #: composite roughness and asperity statistics
    nominal_load: float      #: F_bn / (helices × mean contact length) [N/m]


@dataclass(frozen=True)
class ArchardWear:
    """Archard wear of the case: what stays fixed over the runs of one case."""

    coefficient: float   #: dimensionless Archard K [-]
    hardness: float      #: flank hardness H [Pa]
    cycles: float        #: pinion revolutions to wear over [-]
    face: bool           #: True: face-resolved (``wear.field = "face"``); False: along the path
    face_points: int     #: points over the face of each helix (face-resolved) [-]
    load: str = "total"  #: ``wear.load``: "asperity" (the asperity-borne part wears) or "total" (the whole load)
    film: FilmInputs | None = None   #: what the asperity share is solved from (None: no film known)

    @cached_property
    def share_table(self) -> AsperityShare:
        """The asperity share over the case's path and a range of loads (solved once, about 1 s)."""
        f = self.film
        loads = f.nominal_load * np.geomspace(*LOAD_SPAN, LOAD_POINTS)
        fraction, lam = split_table(loads, f.R, f.ue, f.srr, f.temperature, f.oil, f.E_red, f.solids, f.roughness)
        return AsperityShare(loads=loads, fraction=fraction, film_parameter=lam, sigma=f.roughness.sigma)

    @property
    def share(self) -> AsperityShare | None:
        """The share that wears (``load = "asperity"``), None where the whole load does."""
        return self.share_table if self.load == "asperity" and self.film is not None else None

    def regime(self, load_per_length) -> Regime | None:
        """How the film shares the load ``load_per_length`` at the case's path positions [N/m] (None: no film)."""
        return None if self.film is None else regime(self.share_table, load_per_length)

    def warnings(self, load_per_length) -> tuple[str, ...]:
        """``wear.load: ...`` where the constant-coefficient form wears a pair whose film carries the load."""
        r = self.regime(load_per_length)
        if self.load != "total" or r is None or not r.full_film or self.cycles == 0:
            return ()
        regime_text = "full film (λ > 3)" if r.film_parameter_min > 3 else "a film that carries the load"
        return (f'wear.load: the paper\'s constant-coefficient Archard form ("total") wears the whole load, but '
                f"this pair runs in {regime_text}: λ = h/σ ≥ {r.film_parameter_min:.3g} along the path (σ = "
                f"{self.share_table.sigma * 1e6:.3g} µm) and the asperities carry at most {r.share_max:.2%} of the "
                f'load; the wear of the asperity-borne load (wear.load = "asperity") is about '
                f"{1 / max(r.share_max, 1e-300):.3g} times smaller",)

    def setup(self, pair: GearPair, kin: PathKinematics, force: float | np.ndarray, c_l: float | np.ndarray,
              n_phase: int = 64, reference: ReferenceLoad | None = None) -> WearSetup:
        """The :class:`femgear.physics.wear.WearSetup` of one load case (force per helix, stiffness c_l) on the
        case's path kinematics ``kin`` (the share's positions)."""
        share = self.share
        if share is not None and share.fraction.shape[0] != kin.u.size:
            raise ValueError(f"the asperity share holds {share.fraction.shape[0]} path positions, kin {kin.u.size}")
        return WearSetup(pair=pair, kin=kin, force=force, c_l=c_l, coefficient=self.coefficient,
                         hardness=self.hardness, n_phase=n_phase, reference=reference, share=share)


REGISTRY.register("none")(lambda case, **_: None)


@REGISTRY.register("archard")
def _archard(case: Case, **_: Any) -> ArchardWear:
    w = case.wear
    return ArchardWear(coefficient=w.coefficient, hardness=case.material.hardness, cycles=w.cycles,
                       face=w.field == "face", face_points=w.face_points, load=w.load, film=film_inputs(case))


def wear_roughness(case: Case) -> Roughness:
    """The composite roughness σ of the wear's split, from the flanks' one roughness description
    (:attr:`femgear.case.Case.flanks`; also where the tribology takes the flanks as smooth, ``roughness.model =
    "smooth"``: the wear needs the asperities), with the scene's Greenwood–Tripp statistics."""
    rough, flanks = case.roughness, case.flanks
    sigma = flanks.sigma if flanks.sigma > 0 else math.hypot(*flanks.rq)
    return flank_asperities(rough, sigma)


def film_inputs(case: Case) -> FilmInputs:
    """The :class:`FilmInputs` of the case: its path, the ``formula`` level's oil, steel and traction solids."""
    lf, k, pair = line_friction(case), case.path, case.pair
    return FilmInputs(R=k.R, ue=k.ue, srr=np.abs(k.srr), temperature=case.operating.ambient_temperature, oil=lf.oil,
                      E_red=lf.E_red, solids=lf.solids, roughness=wear_roughness(case),
                      nominal_load=case.operating.normal_force / pair.n_helices / pair.mean_contact_length)


def of(case: Case) -> ArchardWear | None:
    """The wear model of the case's ``physics.wear`` level (None for ``none``)."""
    return REGISTRY.build(case.levels.wear, case)


def has_wear(case: Case) -> bool:
    """Whether the case's wear level wears the flanks."""
    return of(case) is not None


def static_setup(case: Case, kin: PathKinematics | None = None, n_phase: int = 64) -> WearSetup:
    """The static load sharing of the case (any wear level's numbers) with the whole load wearing (the
    constant-coefficient form: the tests' and studies' reference): each helix carries F_bn/2, c_l from
    ``stiffness.mesh_stiffness_per_width`` over the mean contact length; ``kin`` defaults to the case's path."""
    pair = case.pair
    c_l = case.stiffness.mesh_stiffness_per_width * pair.b / pair.mean_contact_length
    return WearSetup(pair=pair, kin=case.path if kin is None else kin, force=case.operating.normal_force / 2,
                     c_l=c_l, coefficient=case.wear.coefficient, hardness=case.material.hardness, n_phase=n_phase)
