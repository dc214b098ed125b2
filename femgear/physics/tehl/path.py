"""TEHL along the path of contact: h_c, p_max, max ΔT and μ per position
(the seed paper's Fig. 16 analogue); the thermal fields are written by :func:`femgear.edge.io.fields.write_tehl_vtu`.

Positions, load per length, radii, entrainment speeds and SRR come from
:func:`femgear.physics.contact.path.contact_along_path` (or any ``load_per_length`` array, e.g.
the coupling's dynamic w̄').  One discretisation for the path: the position with the largest Moes M
(the thinnest film for its width) is solved first to the tolerance, and its grid level is kept for every
position, so that the path fields are smooth to the solver's tolerance (a level that changed between
positions would step them by up to that tolerance).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from femgear.errors import ConvergenceError
from femgear.physics.contact.film import moes_line
from femgear.physics.tehl.line import TEHLResult, ehl_oil_at, solve_tehl_line
from femgear.physics.tehl.solver import TEHLSetup, _level_of_nodes


@dataclass(frozen=True)
class TEHLPath:
    s: np.ndarray            #: path coordinate [m] (0 at the pitch point)
    srr: np.ndarray
    hc: np.ndarray           #: [m]
    pmax: np.ndarray         #: [Pa]
    dT_max: np.ndarray       #: [K]
    dT_surface: np.ndarray   #: [K]
    mu: np.ndarray
    mu_poiseuille: np.ndarray
    seconds: float
    results: list = field(repr=False, default_factory=list)


def tehl_path_results(w, R, ue, srr, T: float, setup: TEHLSetup, *, level: int | None = None,
                      **options) -> list[TEHLResult]:
    """TEHL line solves at the contacts (arrays ``w``, ``R``, ``ue``, ``srr``; oil at ``T`` [K]) on one grid
    level: ``level``, or the one the heaviest contact's tolerance-driven solve picks (module docstring);
    ``options`` to :func:`solve_tehl_line` (``tol``, ``min_level``, ...)."""
    w, R, ue, srr = np.broadcast_arrays(*(np.atleast_1d(np.asarray(a, dtype=float)) for a in (w, R, ue, srr)))
    kw = {**setup.kwargs(), **options}
    out: list[TEHLResult | None] = [None] * w.size
    if level is None:
        oil = ehl_oil_at(setup.oil, T)
        E = setup.E_red
        M = [moes_line(wi / (E * Ri), oil.eta0 * ui / (E * Ri), oil.alpha * E)[0] for wi, Ri, ui in zip(w, R, ue)]
        first = int(np.argmax(M))
        out[first] = _one(first, w, R, ue, srr, T, kw)
        level = _level_of_nodes(out[first].nodes)
    kw.pop("min_level", None)
    for i in range(w.size):
        if out[i] is None:
            out[i] = _one(i, w, R, ue, srr, T, {**kw, "level": level})
    return out


def _one(i: int, w, R, ue, srr, T, kw) -> TEHLResult:
    try:
        return solve_tehl_line(float(w[i]), float(R[i]), float(ue[i]), float(srr[i]), T, **kw)
    except ConvergenceError as exc:
        raise ConvergenceError(f"tehl path position {i}", str(exc), exc.history) from exc


def tehl_along_path(contact, setup: TEHLSetup, T_bulk: float, level: int | None = None, load_per_length=None,
                    **options) -> TEHLPath:
    """TEHL (oil bulk temperature ``T_bulk`` [K]; grid ``level``, or the path's own, :func:`tehl_path_results`) at
    the positions of a contact pass (:class:`femgear.physics.contact.path.ContactPath`), at its mean load per length
    or ``load_per_length``."""
    k = contact.kin
    w = np.broadcast_to(contact.load_per_length if load_per_length is None else load_per_length, k.R.shape)
    results = tehl_path_results(w, k.R, k.ue, k.srr, T_bulk, setup, level=level, **options)

    def arr(name):
        return np.array([getattr(r, name) for r in results])

    return TEHLPath(s=np.asarray(k.s), srr=np.asarray(k.srr), hc=arr("hc"), pmax=arr("pmax"), dT_max=arr("dT_max"),
                    dT_surface=arr("dT_surface"), mu=arr("mu"), mu_poiseuille=arr("mu_poiseuille"),
                    seconds=float(sum(r.seconds for r in results)), results=results)
