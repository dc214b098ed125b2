"""The LTCA alone at several torques (``femgear ltca``): TE analyses, load maps and the Harris map.

:func:`run_ltca` builds the member bodies' compliance once (:func:`femgear.physics.ltca.analysis.build_model`,
disk-cached) and runs one mesh cycle per torque with the scene's modifications: the loaded TE
and its analysis (:func:`femgear.physics.ltca.te.analyse_cycle`), the helices alone
(:func:`femgear.physics.ltca.te.helix_alone_te`), the same cycle with twice the points per contact line
(the discretisation check of the harmonics), and the maps of both members in mesh
(:func:`femgear.physics.ltca.maps.load_maps`).  The design torque is always solved first: a
modification under which a helix loses contact there is refused (:func:`femgear.physics.ltca.te.check_contact`).
No dynamics, no lubrication.  Pure: typed inputs, a frozen result; files are written by
:mod:`femgear.edge.io.ltca` and :mod:`femgear.edge.plot.ltca`.
"""

from __future__ import annotations

import time
from dataclasses import dataclass

from femgear.physics.geometry.gear import GearPair
from femgear.physics.ltca.maps import LoadMaps
from femgear.physics.ltca.te import HarrisMap, TEAnalysis


@dataclass(frozen=True)
class LTCAOptions:
    """Resolution of the tool's cycles (the defaults are those of the ``ltca`` stiffness level's model)."""

    n_phases: int = 64          #: phases per mesh period
    n_line: int = 16            #: points per contact line
    n_harmonics: int = 5        #: mesh orders reported
    refine_check: bool = True   #: also solve with 2 n_line points (harmonics' discretisation change)
    helix_alone: bool = True    #: the per-helix TE (each helix alone at its mean share; two-helix pairs only)
    level: int = 1              #: member body mesh level (:func:`femgear.physics.mesh.segment.default_spec`)
    order: int | str = 1        #: member body elements: 1 (P1) or "p2-bending" (:func:`femgear.physics.ltca.compliance.member_compliance`)


@dataclass(frozen=True)
class LTCAToolResult:
    """Everything ``femgear ltca`` computed."""

    torques: tuple[float, ...]              #: [N m], in the order given
    analyses: tuple[TEAnalysis, ...]        #: one per torque
    maps: tuple[LoadMaps, ...]              #: one per torque
    design: TEAnalysis                      #: at the design torque (one of ``analyses`` if listed)
    harris: HarrisMap | None
    options: LTCAOptions
    model_seconds: float                    #: compliance build (or cache read) [s]
    cached: bool                            #: both compliances came from the disk cache
    seconds: float                          #: total wall time [s]


def _cycle(model, pair, E, nu, torque, driver, modifications, stagger, opts: LTCAOptions):
    """(TEAnalysis, LTCAResult) of one torque."""
    from femgear.physics.ltca.analysis import mesh_cycle, normal_force
    from femgear.physics.ltca.te import analyse_cycle, helix_alone_te

    F = normal_force(pair, torque, driver)
    res = mesh_cycle(model, F, modifications, n_phases=opts.n_phases, stagger=stagger, n_line=opts.n_line)
    fine = (mesh_cycle(model, F, modifications, n_phases=opts.n_phases, stagger=stagger, n_line=2 * opts.n_line,
                       keep_lines=False) if opts.refine_check else None)
    alone = helix_alone_te(model, res, modifications) if opts.helix_alone and pair.n_helices == 2 else None
    a = analyse_cycle(res, pair, E, nu, torque, opts.n_harmonics, alone, fine)
    return a, res


def run_ltca(pair: GearPair, youngs_modulus: float, poisson_ratio: float, modifications, torques,
             design_torque: float, driver: str = "pinion", body: dict | None = None,
             harris_torques=None, options: LTCAOptions = LTCAOptions(), model=None) -> LTCAToolResult:
    """LTCA of ``pair`` at ``torques`` [N m] on the ``driver`` (checked beforehand by the caller:
    :func:`femgear.physics.ltca.te.check_torques`); ``body``: bore_radius, groove_width, stagger
    (:func:`femgear.levels.stiffness.body_options`); ``harris_torques``: the Harris map's torques (None: none);
    ``model``: a prebuilt :class:`femgear.physics.ltca.analysis.LTCAModel` of these bodies (a test's coarse model)."""
    from femgear.physics.ltca.analysis import build_model
    from femgear.physics.ltca.maps import load_maps
    from femgear.physics.ltca.te import check_contact, harris_map

    t0 = time.perf_counter()
    body = dict(body or {})
    stagger = float(body.pop("stagger", 0.0))
    if model is None:
        model = build_model(pair, youngs_modulus, poisson_ratio, level=options.level, order=options.order,
                            stagger=stagger, **body)
    groove = float(body.get("groove_width", 0.0))
    args = (model, pair, youngs_modulus, poisson_ratio)
    design, _ = _cycle(*args, design_torque, driver, modifications, stagger,
                       LTCAOptions(options.n_phases, options.n_line, options.n_harmonics, False, False, options.level,
                                   options.order))
    check_contact(design, modifications)
    analyses, maps = [], []
    for t in torques:
        a, res = _cycle(*args, float(t), driver, modifications, stagger, options)
        analyses.append(a)
        maps.append(load_maps(res, pair, youngs_modulus, poisson_ratio, float(t), a.worst_phase, groove, stagger))
        if abs(float(t) - design_torque) <= 1e-12 * design_torque:
            design = a
    harris = None
    if harris_torques is not None:
        harris = harris_map(model, harris_torques, modifications, design_torque, driver, options.n_phases,
                            options.n_line, stagger)
    cached = all(bool(model.kernels[m].info.get("cached", False)) for m in (1, 2))
    return LTCAToolResult(tuple(float(t) for t in torques), tuple(analyses), tuple(maps), design, harris, options,
                          model.seconds, cached, time.perf_counter() - t0)


__all__ = ["LTCAOptions", "LTCAToolResult", "run_ltca"]
