"""The one registry of lubrication levels, used by the static pass, the coupling and the dynamics.

Every level is a contact solver with the map signature
``solver(w=, R=, ue=, srr=, T=) -> (μ, ΔT)`` (load per unit contact length [N/m],
radius [m], entrainment speed [m/s], |slide-to-roll| [-], bulk temperature [K]), so a
:class:`femgear.physics.lubrication.map.FrictionMap` can stand in for any expensive level.

| level      | solver                                                                   |
|------------|--------------------------------------------------------------------------|
| none       | μ = 0, no heating                                                        |
| constant   | μ = ``friction.coefficient``, no heating                                 |
| formula    | thermal Eyring traction of the Hertzian film (:mod:`.path`)             |
| ehl-line   | FE line EHL with Eyring traction, Blok flash temperature (:mod:`femgear.physics.ehl.path`) |
| tehl       | thermal EHL line solves (:mod:`femgear.physics.tehl.solver`); ``repeated``: a friction map of them |
| tehl-point | thermal EHL of the crowned flanks' elliptic contacts (:mod:`femgear.physics.tehl.point_level`), direct solves |

A new level is one entry in :data:`LEVELS` (and its name in :mod:`femgear.scene.levels`).
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from femgear.case import Case

Lubrication = Callable[..., tuple[np.ndarray, np.ndarray]]
"""solver(w=, R=, ue=, srr=, T=) -> (mu, temperature_rise) — the signature of friction maps."""


def _constant(mu0: float) -> Lubrication:
    def constant(w, R, ue, srr, T):
        shape = np.broadcast(w, R, ue, srr, T).shape
        return np.full(shape, mu0), np.zeros(shape)

    return constant


def _formula(case: Case, repeated: bool) -> Lubrication:
    from femgear.physics.lubrication.map import hertz_level_solver

    return hertz_level_solver(case.scene)


def _ehl_line(case: Case, repeated: bool) -> Lubrication:
    from femgear.physics.ehl.path import ehl_line_solver

    return ehl_line_solver(case.scene)


def _tehl(case: Case, repeated: bool) -> Lubrication:
    from femgear.physics.tehl.solver import tehl_line_solver, tehl_map_solver

    return tehl_map_solver(case.scene) if repeated else tehl_line_solver(case.scene)


def _tehl_point(case: Case, repeated: bool) -> Lubrication:
    """Direct solves also when ``repeated`` (a friction map of point solves would cost
    ~170 of them; the path's 21+ direct solves are cheaper)."""
    from femgear.physics.tehl.point_level import tehl_point_solver

    return tehl_point_solver(case.scene, pair=case.pair)


LEVELS: dict[str, Callable[[Case, bool], Lubrication]] = {
    "none": lambda case, repeated: _constant(0.0),
    "constant": lambda case, repeated: _constant(case.friction.coefficient),
    "formula": _formula,
    "ehl-line": _ehl_line,
    "tehl": _tehl,
    "tehl-point": _tehl_point,
}


def lubrication_solver(case: Case, level: str | None = None, *, repeated: bool = False) -> Lubrication:
    """The contact solver of ``level`` (default: the case's ``physics.lubrication``).

    ``repeated``: the solver will be queried many times (the coupling loop): levels with
    a costly direct solve return a friction map of it instead (``tehl``).
    """
    level = level or case.levels.lubrication
    try:
        factory = LEVELS[level]
    except KeyError:
        raise ValueError(f"no lubrication solver for level {level!r} (levels: {', '.join(LEVELS)})") from None
    return factory(case, repeated)


def friction_along_path(case: Case, w: np.ndarray, solver: Lubrication | None = None,
                        T: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray]:
    """μ and the contact temperature rise at the case's path positions for loads ``w`` [N/m]."""
    k = case.path
    solver = solver or lubrication_solver(case)
    T = np.full(k.u.shape, case.operating.ambient_temperature) if T is None else T
    mu, dT = solver(w=np.broadcast_to(w, k.u.shape), R=k.R, ue=k.ue, srr=np.abs(k.srr), T=T)
    return np.asarray(mu, dtype=float), np.asarray(dT, dtype=float)


def static_friction(case: Case) -> float | Callable[[np.ndarray], np.ndarray]:
    """μ for the dynamics without coupling: 0 (``none``), ``friction.coefficient`` (``constant``),
    else μ(u) of the lubrication level at the static line load of the contact pass (load
    shared between the tooth pairs in contact, :func:`femgear.physics.contact.path.contact_along_path`;
    U-shaped, zero at the pitch point), interpolated along the path."""
    level = case.levels.lubrication
    if level in ("none", "constant"):
        return 0.0 if level == "none" else case.friction.coefficient
    from femgear.physics.contact.path import contact_along_path

    u = case.path.u
    w = contact_along_path(case.scene, pair=case.pair, u=u).line_load
    mu = friction_along_path(case, w)[0]
    return lambda x: np.interp(x, u, mu)
