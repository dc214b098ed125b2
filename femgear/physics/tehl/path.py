"""TEHL along the path of contact: h_c, p_max, max ΔT and μ per position
(the seed paper's Fig. 16 analogue); the thermal fields are written by :func:`femgear.edge.io.fields.write_tehl_vtu`.

Positions, load per length, radii, entrainment speeds and SRR come from
:func:`femgear.physics.contact.path.contact_along_path` (or any ``load_per_length`` array, e.g.
the coupling's dynamic w̄'), solved on one grid level (:func:`femgear.physics.tehl.solver.tehl_path_results`).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from femgear.physics.tehl.solver import TEHLSetup, tehl_path_results


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
