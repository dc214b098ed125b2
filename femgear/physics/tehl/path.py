"""TEHL along the path of contact: h_c, p_max, max ΔT and μ per position
(the seed paper's Fig. 16 analogue); the thermal fields are written by :func:`femgear.edge.io.fields.write_tehl_vtu`.

Positions, load per length, radii, entrainment speeds and SRR come from
:func:`femgear.physics.contact.path.contact_along_path` (or any ``load_per_length`` array, e.g.
the coupling's dynamic w̄').
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from femgear.errors import ConvergenceError
from femgear.physics.tehl.line import TEHLResult, solve_tehl_line
from femgear.physics.tehl.solver import TEHLSetup


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


def tehl_along_path(contact, setup: TEHLSetup, T_bulk: float, level: int, load_per_length=None,
                    **options) -> TEHLPath:
    """TEHL (grid ``level``, oil bulk temperature ``T_bulk`` [K]) at the positions of a contact pass
    (:class:`femgear.physics.contact.path.ContactPath`), at its mean load per length or ``load_per_length``."""
    k = contact.kin
    w = np.broadcast_to(contact.load_per_length if load_per_length is None else load_per_length, k.R.shape)
    kw = {**setup.kwargs(), **options}
    results: list[TEHLResult] = []
    for i in range(k.R.size):
        try:
            results.append(solve_tehl_line(float(w[i]), float(k.R[i]), float(k.ue[i]), float(k.srr[i]), T_bulk,
                                           level=level, **kw))
        except ConvergenceError as exc:
            raise ConvergenceError(f"tehl path position {i} (s = {k.s[i]:.4g} m)", str(exc), exc.history) from exc

    def arr(name):
        return np.array([getattr(r, name) for r in results])

    return TEHLPath(s=np.asarray(k.s), srr=np.asarray(k.srr), hc=arr("hc"), pmax=arr("pmax"), dT_max=arr("dT_max"),
                    dT_surface=arr("dT_surface"), mu=arr("mu"), mu_poiseuille=arr("mu_poiseuille"),
                    seconds=float(sum(r.seconds for r in results)), results=results)
