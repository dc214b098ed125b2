"""Mesh stiffness levels (the ``[physics] stiffness`` key).

Each level is a function of the pair and its numbers (:func:`mesh_stiffness` dispatches
them for a bare pair); its registered factory reads the Case's typed parts: the pair, the
stagger, the material, the bores, the ``[stiffness]`` knobs and, for ``ltca``, the normal
force of the operating point, the flank modifications and the member bodies.  The FE
level's 2-D tooth solves (:mod:`femgear.physics.body.compliance`) and the LTCA cycle
(:mod:`femgear.physics.ltca.level`) are called from here, so that the stiffness leaf
imports neither.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from femgear.levels.registry import Registry

if TYPE_CHECKING:
    from femgear.case import Case
    from femgear.physics.geometry import GearPair
    from femgear.physics.stiffness import MeshStiffness

REGISTRY = Registry("stiffness")


def _constant(pair: GearPair, n_positions: int = 200, stagger: float = 0.0, constant_per_width: float = 2.0e10,
              **_: Any) -> MeshStiffness:
    from femgear.physics.stiffness import uniform_mesh_stiffness

    return uniform_mesh_stiffness(pair, constant_per_width * pair.b, "constant", n_positions, stagger)


def _iso6336(pair: GearPair, n_positions: int = 200, stagger: float = 0.0, youngs_modulus: float = 210e9,
             **_: Any) -> MeshStiffness:
    from femgear.physics.stiffness import uniform_mesh_stiffness
    from femgear.physics.stiffness.tvms import iso6336_helix_stiffness

    t0 = time.perf_counter()
    k, iso = iso6336_helix_stiffness(pair, youngs_modulus)
    return uniform_mesh_stiffness(pair, k, "iso6336", n_positions, stagger, t0=t0, iso=iso)


def _pem(pair: GearPair, n_positions: int = 200, stagger: float = 0.0,
         youngs_modulus: float = 210e9, poisson_ratio: float = 0.3, bore_radius: tuple[float, float] = (0.0, 0.0),
         plane: str = "strain", **_: Any) -> MeshStiffness:
    from femgear.physics.stiffness import integrated_mesh_stiffness
    from femgear.physics.stiffness.pem import pair_stiffness_per_width
    from femgear.physics.stiffness.tvms import path_samples

    t0 = time.perf_counter()
    u_grid = path_samples(pair)
    k_grid = pair_stiffness_per_width(pair, u_grid, youngs_modulus, poisson_ratio, bore_radius, plane)
    return integrated_mesh_stiffness(pair, u_grid, k_grid, "pem", n_positions, stagger, t0=t0)


def _fe(pair: GearPair, n_positions: int = 200, stagger: float = 0.0,
        youngs_modulus: float = 210e9, poisson_ratio: float = 0.3, bore_radius: tuple[float, float] = (0.0, 0.0),
        fe_options: dict | None = None, **_: Any) -> MeshStiffness:
    """Tooth compliance from the 2-D FE sections at ``fe_options['n_fe']`` (default 9) path positions, Hertz as
    in PEM, tabulated along the path and integrated over every contact line."""
    import numpy as np

    from femgear.physics.body.compliance import fe_pair_stiffness_per_width
    from femgear.physics.stiffness import integrated_mesh_stiffness
    from femgear.physics.stiffness.tvms import FESamples, path_samples, tabulated

    t0 = time.perf_counter()
    opts = dict(fe_options or {})
    n_fe = opts.pop("n_fe", 9)
    u_fe = np.linspace(pair.u_start, pair.u_end, n_fe)
    k_fe, fe_info = fe_pair_stiffness_per_width(pair, u_fe, youngs_modulus, poisson_ratio, bore_radius=bore_radius,
                                                **opts)
    u_grid = path_samples(pair)
    fe = FESamples(u=u_fe, k=k_fe, compliance=(fe_info["c1"], fe_info["c2"]), ndofs=tuple(fe_info["ndofs"]),
                   h=fe_info["h"], seconds=fe_info["seconds"])
    return integrated_mesh_stiffness(pair, u_grid, tabulated(pair, u_fe, k_fe)(u_grid), "fe", n_positions, stagger,
                                     t0=t0, fe=fe)


def _ltca(pair: GearPair, n_positions: int = 200, stagger: float = 0.0, youngs_modulus: float = 210e9,
          poisson_ratio: float = 0.3, ltca_options: dict | None = None, **_: Any) -> MeshStiffness:
    """Secant stiffness per helix of the loaded tooth contact analysis at ``ltca_options['force']`` (its TE
    tables and cycle in ``MeshStiffness.ltca``)."""
    from femgear.physics.ltca.level import ltca_cycle
    from femgear.physics.stiffness import MeshStiffness

    if not ltca_options or "force" not in ltca_options:
        raise ValueError("level 'ltca' needs ltca_options={'force': normal force [N], ...}")
    t0 = time.perf_counter()
    cycle = ltca_cycle(pair, n_positions=n_positions, stagger=stagger, youngs_modulus=youngs_modulus,
                       poisson_ratio=poisson_ratio, **ltca_options)
    res = cycle.result
    return MeshStiffness("ltca", res.phase, res.k_secant_left, res.k_secant_right, stagger,
                         time.perf_counter() - t0, ltca=cycle)


#: level name -> the level's function of a bare pair (the keywords of :func:`mesh_stiffness`)
PAIR_LEVELS: dict[str, Callable[..., MeshStiffness]] = {
    "constant": _constant, "iso6336": _iso6336, "pem": _pem, "fe": _fe, "ltca": _ltca,
}
_SUMMARIES = {
    "constant": "one mesh stiffness per unit face width, constant in time (stiffness.mesh_stiffness_per_width)",
    "iso6336": "ISO 6336-1 single-pair stiffness c' and mesh stiffness c_gamma, shared along the contact lines",
    "pem": "potential-energy tooth compliance (Hertz, bending, shear, axial, foundation) integrated over the contact lines",
    "fe": "2-D finite-element tooth sections (plane strain) integrated over the contact lines",
    "ltca": "loaded tooth contact analysis on 3-D FE member bodies with flank modifications",
}


def mesh_stiffness(pair: GearPair, level: str = "pem", n_positions: int = 200, stagger: float = 0.0,
                   youngs_modulus: float = 210e9, poisson_ratio: float = 0.3,
                   bore_radius: tuple[float, float] = (0.0, 0.0), plane: str = "strain",
                   constant_per_width: float = 2.0e10, fe_options: dict | None = None,
                   ltca_options: dict | None = None) -> MeshStiffness:
    """Mesh stiffness of both helices of ``pair`` at ``n_positions`` phases of one mesh period.

    Levels: ``constant`` (``constant_per_width`` [N/m per m] × b per helix), ``iso6336``
    (c_γα b, constant; ISO's value is read as a transverse stiffness per unit face width
    and projected like ``pem``), ``pem`` (potential energy method, integrated over every contact line),
    ``fe`` (the same integral, tooth compliance from the 2-D FE of :mod:`femgear.physics.body.compliance`
    at ``fe_options['n_fe']`` path positions, Hertz as in PEM), ``ltca`` (secant stiffness
    per helix from the loaded tooth contact analysis of :mod:`femgear.physics.ltca` at
    ``ltca_options['force']``; the cycle, with its TE tables, is ``MeshStiffness.ltca``).
    """
    build = PAIR_LEVELS.get(level)
    if build is None:
        raise ValueError(f"level must be one of {', '.join(PAIR_LEVELS)}, got {level!r}")
    return build(pair, n_positions=n_positions, stagger=stagger, youngs_modulus=youngs_modulus,
                 poisson_ratio=poisson_ratio, bore_radius=bore_radius, plane=plane,
                 constant_per_width=constant_per_width, fe_options=fe_options, ltca_options=ltca_options)


def body_options(case: Case) -> dict:
    """``bore_radius`` (each member's bore radius if > 0, else, a member cut on its shaft, its shaft radius but at
    least 1.2 h_t below the root, :func:`femgear.physics.mesh.section.shaft_clamp_radius`), ``groove_width`` and
    ``stagger`` of the member bodies (:func:`femgear.physics.ltca.analysis.build_model`)."""
    from femgear.physics.mesh.section import shaft_clamp_radius

    bores = tuple(m.bore_radius if m.bore_radius > 0 else shaft_clamp_radius(case.pair, j, 0.5 * m.shaft_diameter)
                  for j, m in zip((1, 2), case.members))
    return {"bore_radius": bores, "groove_width": case.groove_width, "stagger": case.stagger}


def ltca_options(case: Case) -> dict:
    """Force F_bn of the operating point, the flank modifications, the member bodies (bore, groove) and their
    resolution (``numerics.body_level`` or the ltca bodies' default) and elements ``numerics.body_elements`` for
    :func:`femgear.physics.ltca.level.ltca_cycle`."""
    body = {k: v for k, v in body_options(case).items() if k != "stagger"}   # the level passes the stagger itself
    return {"force": case.operating.normal_force, "modifications": case.modifications, "body": body,
            "level": case.numerics.level_of("ltca"), "order": body_order(case.numerics.body_elements)}


def body_order(elements: str) -> int | str:
    """The element ``order`` of :func:`femgear.physics.ltca.compliance.member_compliance` for the scene's
    ``numerics.body_elements`` ("p1" → 1; "p2-bending" as it is)."""
    return 1 if elements == "p1" else elements


def case_arguments(case: Case, level: str) -> dict:
    """The keywords of :func:`mesh_stiffness` from the case: stagger, material, bores, ``[stiffness]``."""
    st = case.stiffness
    fe_options: dict = {} if st.fe_mesh_size is None else {"h": st.fe_mesh_size}
    fe_options["level"] = case.numerics.level_of("fe")
    args = dict(n_positions=st.n_positions, stagger=case.stagger,
                youngs_modulus=case.material.youngs_modulus, poisson_ratio=case.material.poisson_ratio,
                bore_radius=case.bore_radii, constant_per_width=st.mesh_stiffness_per_width, fe_options=fe_options)
    if level == "ltca":
        args["ltca_options"] = ltca_options(case)
    return args


def _factory(name: str) -> Callable[..., MeshStiffness]:
    def factory(case: Case, **options: Any) -> MeshStiffness:
        args = case_arguments(case, name)
        fe = {**args.pop("fe_options"), **(options.pop("fe_options", None) or {})}
        ltca = {**args.pop("ltca_options", {}), **(options.pop("ltca_options", None) or {})}
        return PAIR_LEVELS[name](case.pair, **{**args, **options}, fe_options=fe, ltca_options=ltca or None)
    factory.__doc__ = f"The ``{name}`` mesh stiffness of ``case`` ({_SUMMARIES[name]}); ``options`` override."
    return factory


for _name in PAIR_LEVELS:
    REGISTRY.register(_name, _SUMMARIES[_name])(_factory(_name))


def of(case: Case, level: str | None = None, **options: Any) -> MeshStiffness:
    """The mesh stiffness of ``case`` at its ``physics.stiffness`` level (or ``level``); ``options`` override
    the keywords :func:`case_arguments` reads from the case (``fe_options``, ``ltca_options`` are merged)."""
    return REGISTRY.build(level or case.levels.stiffness, case, **options)


def check_resources(case: Case) -> None:
    """Refuse up front (:class:`femgear.errors.ResourceError` naming ``numerics.body_level`` and the level that
    fits) an ``ltca`` stiffness whose member bodies, not cached, need more memory than the budget; a thin rim
    below 0.5 h_t is refused naming its bore (:func:`femgear.physics.ltca.level.body_estimates`)."""
    if case.levels.stiffness != "ltca":
        return
    from femgear.physics.ltca.level import check_body_memory

    opts = ltca_options(case)
    check_body_memory(case.pair, case.material.youngs_modulus, case.material.poisson_ratio, opts["level"],
                      case.stagger, order=opts["order"], **opts["body"])


def has_contact_lines(level: str) -> bool:
    """Whether level ``level`` resolves the load along the contact lines (``ltca``: what the face-resolved
    wear and the LTCA load maps read)."""
    REGISTRY[level]
    return level == "ltca"
