"""Mesh stiffness levels (the ``[physics] stiffness`` key).

Each registered factory reads the Case's typed parts (the pair, the stagger, the material, the bores, the
``[stiffness]`` knobs and, for ``ltca``, the normal force of the operating point, the flank modifications and
the member bodies) and calls the physics: :func:`~femgear.physics.stiffness.tvms.uniform_mesh_stiffness`
(``constant``, ``iso6336``), :func:`~femgear.physics.stiffness.pem.pem_mesh_stiffness`, the FE level's 2-D
tooth solves (:mod:`femgear.physics.body.compliance`) and the LTCA cycle (:mod:`femgear.physics.ltca.level`),
so that the stiffness leaf imports neither.  The FE and LTCA levels' options are frozen records built from the
Case once (:class:`FEOptions`, :class:`LTCAOptions`): every default is the schema's.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from femgear.case import Case
from femgear.levels.registry import Registry
from femgear.physics.body.compliance import fe_pair_stiffness_per_width
from femgear.physics.ltca.level import check_body_memory, ltca_cycle
from femgear.physics.mesh.section import shaft_clamp_radius
from femgear.physics.stiffness import MeshStiffness, integrated_mesh_stiffness, uniform_mesh_stiffness
from femgear.physics.stiffness.pem import pem_mesh_stiffness
from femgear.physics.stiffness.tvms import FESamples, iso6336_helix_stiffness, path_samples, tabulated

REGISTRY = Registry("stiffness")
#: path positions of the ``fe`` level's 2-D tooth solves (tabulated between them) [-]
FE_POSITIONS = 9


@dataclass(frozen=True)
class FEOptions:
    """The ``fe`` level's 2-D FE tooth solves (:func:`femgear.physics.body.compliance.fe_pair_stiffness_per_width`)."""

    h: float | None               #: ``stiffness.fe_mesh_size`` [m] (None: the solver's default, m_n/2.5)
    level: int                    #: the sections' resolution, ``numerics.level_of("fe")`` [-]
    n_fe: int = FE_POSITIONS      #: path positions of the solves [-]
    refine_ratio: float | None = None   #: the contact refinement (None: the solver's default) [-]

    @classmethod
    def of(cls, case: Case) -> FEOptions:
        return cls(h=case.stiffness.fe_mesh_size, level=case.numerics.level_of("fe"))

    def keywords(self) -> dict[str, Any]:
        """The solver's keywords (the refinement only where given)."""
        out: dict[str, Any] = {"h": self.h, "level": self.level}
        if self.refine_ratio is not None:
            out["refine_ratio"] = self.refine_ratio
        return out


@dataclass(frozen=True)
class LTCAOptions:
    """The ``ltca`` level's cycle (:func:`femgear.physics.ltca.level.ltca_cycle`): the load, the flanks, the
    member bodies."""

    force: float                              #: F_bn of the operating point, both helices [N]
    modifications: Any                        #: the flank modifications (``[modifications]``)
    bore_radius: tuple[float, float]          #: the member bodies' bores (:func:`body_options`) [m]
    groove_width: float                       #: the double-helical groove [m]
    level: int                                #: the bodies' resolution, ``numerics.level_of("ltca")`` [-]
    order: int | str                          #: the bodies' elements (:func:`body_order`)

    @classmethod
    def of(cls, case: Case) -> LTCAOptions:
        body = body_options(case)
        return cls(force=case.operating.normal_force, modifications=case.modifications,
                   bore_radius=body["bore_radius"], groove_width=body["groove_width"],
                   level=case.numerics.level_of("ltca"), order=body_order(case.numerics.body_elements))

    @property
    def body(self) -> dict[str, Any]:
        """``bore_radius`` and ``groove_width`` of the member bodies."""
        return {"bore_radius": self.bore_radius, "groove_width": self.groove_width}


def body_options(case: Case) -> dict:
    """``bore_radius`` (each member's bore radius if > 0, else, a member cut on its shaft, its shaft radius but at
    least 1.2 h_t below the root, :func:`femgear.physics.mesh.section.shaft_clamp_radius`), ``groove_width`` and
    ``stagger`` of the member bodies (:func:`femgear.physics.ltca.analysis.build_model`)."""
    bores = tuple(m.bore_radius if m.bore_radius > 0 else shaft_clamp_radius(case.pair, j, 0.5 * m.shaft_diameter)
                  for j, m in zip((1, 2), case.members))
    return {"bore_radius": bores, "groove_width": case.groove_width, "stagger": case.stagger}


def body_order(elements: str) -> int | str:
    """The element ``order`` of :func:`femgear.physics.ltca.compliance.member_compliance` for the scene's
    ``numerics.body_elements`` ("p1" → 1; "p2-bending" as it is)."""
    return 1 if elements == "p1" else elements


def _options(record: Any, overrides: Any) -> Any:
    """``record`` with ``overrides`` (None, a record of the same kind, or a dict of its fields)."""
    if overrides is None:
        return record
    return overrides if isinstance(overrides, type(record)) else replace(record, **overrides)


@REGISTRY.register("constant")
def _constant(case: Case, n_positions: int | None = None, **_: Any) -> MeshStiffness:
    """``stiffness.mesh_stiffness_per_width`` × b per helix, constant in time."""
    pair = case.pair
    return uniform_mesh_stiffness(pair, case.stiffness.mesh_stiffness_per_width * pair.b, "constant",
                                  n_positions or case.stiffness.n_positions, case.stagger)


@REGISTRY.register("iso6336")
def _iso6336(case: Case, n_positions: int | None = None, **_: Any) -> MeshStiffness:
    """ISO 6336-1's c_γα b per helix (read as a transverse stiffness per unit face width, projected like ``pem``)."""
    t0 = time.perf_counter()
    k, iso = iso6336_helix_stiffness(case.pair, case.material.youngs_modulus)
    return uniform_mesh_stiffness(case.pair, k, "iso6336", n_positions or case.stiffness.n_positions, case.stagger,
                                  t0=t0, iso=iso)


@REGISTRY.register("pem")
def _pem(case: Case, n_positions: int | None = None, **_: Any) -> MeshStiffness:
    """The potential-energy tooth compliance integrated over every contact line."""
    m = case.material
    return pem_mesh_stiffness(case.pair, m.youngs_modulus, m.poisson_ratio, n_positions or case.stiffness.n_positions,
                              case.stagger, case.bore_radii)


@REGISTRY.register("fe")
def _fe(case: Case, n_positions: int | None = None, fe_options: FEOptions | dict | None = None,
        **_: Any) -> MeshStiffness:
    """Tooth compliance from the 2-D FE sections at ``n_fe`` path positions (:class:`FEOptions`), Hertz as in
    PEM, tabulated along the path and integrated over every contact line."""
    pair, m = case.pair, case.material
    opts = _options(FEOptions.of(case), fe_options)
    t0 = time.perf_counter()
    u_fe = np.linspace(pair.u_start, pair.u_end, opts.n_fe)
    k_fe, info = fe_pair_stiffness_per_width(pair, u_fe, m.youngs_modulus, m.poisson_ratio, bore_radius=case.bore_radii,
                                             **opts.keywords())
    u_grid = path_samples(pair)
    fe = FESamples(u=u_fe, k=k_fe, compliance=(info["c1"], info["c2"]), ndofs=tuple(info["ndofs"]), h=info["h"],
                   seconds=info["seconds"])
    return integrated_mesh_stiffness(pair, u_grid, tabulated(pair, u_fe, k_fe)(u_grid), "fe",
                                     n_positions or case.stiffness.n_positions, case.stagger, t0=t0, fe=fe)


def check_ltca(case: Case) -> None:
    """Refuse up front (:class:`femgear.errors.ResourceError` naming ``numerics.body_level`` and the level that
    fits) ``ltca`` member bodies that, not cached, need more memory than the budget; a thin rim below 0.5 h_t is
    refused naming its bore (:func:`femgear.physics.ltca.level.body_estimates`)."""
    opts, m = LTCAOptions.of(case), case.material
    check_body_memory(case.pair, m.youngs_modulus, m.poisson_ratio, opts.level, case.stagger, order=opts.order,
                      **opts.body)


@REGISTRY.register("ltca", check=check_ltca)
def _ltca(case: Case, n_positions: int | None = None, ltca_options: LTCAOptions | dict | None = None,
          **_: Any) -> MeshStiffness:
    """Secant stiffness per helix of the loaded tooth contact analysis at the operating point's F_bn (its TE
    tables and cycle in ``MeshStiffness.ltca``)."""
    opts, m = _options(LTCAOptions.of(case), ltca_options), case.material
    t0 = time.perf_counter()
    cycle = ltca_cycle(case.pair, opts.force, opts.modifications, n_positions=n_positions or case.stiffness.n_positions,
                       stagger=case.stagger, youngs_modulus=m.youngs_modulus, poisson_ratio=m.poisson_ratio,
                       level=opts.level, body=opts.body, order=opts.order)
    res = cycle.result
    return MeshStiffness("ltca", res.phase, res.k_secant_left, res.k_secant_right, case.stagger,
                         time.perf_counter() - t0, ltca=cycle)


def of(case: Case, level: str | None = None, **options: Any) -> MeshStiffness:
    """The mesh stiffness of ``case`` at its ``physics.stiffness`` level (or ``level``); ``options`` override what
    the level reads from the case: ``n_positions``, ``fe_options`` and ``ltca_options`` (a record, or a dict of
    the fields to replace)."""
    return REGISTRY.build(level or case.levels.stiffness, case, **options)
