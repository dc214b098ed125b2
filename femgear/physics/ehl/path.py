"""The ``ehl-line`` lubrication level: FE line-contact EHL at positions of the path.

At each contact the isothermal FE line solution (:func:`solve_line_dimensional`,
Roelands viscosity and Dowson–Higginson density at the inlet viscosity η(0, T_bulk) and α(T_bulk))
gives the pressure and film fields; the sliding traction is the Ree–Eyring shear
τ0 asinh(η(p, T) γ̇/τ0), γ̇ = |v1 − v2|/h, integrated over them, and the contact
temperature rise is Blok's flash temperature for that μ.  μ = ∫τ dx / w'.  (The thermal
film and its feedback on the viscosity are the ``tehl`` level.)  Consecutive positions (or
map points) are warm-started from the previous solution with the LU factors kept
(:func:`femgear.physics.ehl.fe.line.solve_line`'s ``start`` and ``reuse``).
"""

from __future__ import annotations

import numpy as np

from femgear.errors import SceneError
from femgear.physics.ehl.dimensional import EHLOil, solve_line_dimensional
from femgear.physics.lubrication.flash import blok_flash_temperature
from femgear.physics.lubrication.oil import OilLaw
from femgear.physics.lubrication.traction import Solids, shear_stress


def ehl_line_solver(oil: OilLaw, E_red: float, solids: Solids, tau0: float, level: int):
    """The ``ehl-line`` contact solver in the map signature (w, R, ue, srr, T) -> (μ, ΔT): FE line EHL on grid
    ``level`` with ``oil``, reduced modulus ``E_red`` [Pa], ``solids`` (Blok's flash temperature) and the
    Eyring stress ``tau0`` [Pa]."""

    def solve(w, R, ue, srr, T):
        w, R, ue, srr, T = np.broadcast_arrays(*(np.atleast_1d(np.asarray(a, dtype=float)) for a in (w, R, ue, srr, T)))
        mu, dT = np.empty(w.shape), np.empty(w.shape)
        prev, reuse = None, {}  # warm start from the previous position / map point
        for i in np.ndindex(w.shape):
            ehl = EHLOil(eta0=float(oil.viscosity(0.0, T[i])), alpha=float(oil.pressure_viscosity(T[i])),
                         viscosity="roelands", compressible=True)
            try:
                r = solve_line_dimensional(w[i], R[i], ue[i], E_red, ehl, level=level, start=prev, reuse=reuse)
            except SceneError as exc:       # the solver's own range (a light, slow contact's long inlet)
                raise SceneError("physics.lubrication", f'"ehl-line": {exc.message}; use "formula" or "tehl"') \
                    from None
            prev = r.result
            vs = abs(srr[i]) * ue[i]
            tau = shear_stress(oil.viscosity(r.p, T[i]), vs / r.h, "eyring", tau0)
            mu[i] = np.trapezoid(tau, r.x) / w[i]
            b = np.sqrt(8 * w[i] * R[i] / (np.pi * E_red))
            dT[i] = blok_flash_temperature(mu[i], w[i], vs, b, ue[i] * (1 + srr[i] / 2), ue[i] * (1 - srr[i] / 2),
                                           solids.B1, solids.B2)
        return mu, dT

    return solve


def ehl_line_films(w, R, ue, T: float, oil: OilLaw, E_red: float, level: int) -> tuple[np.ndarray, ...]:
    """Central film, minimum film [m] and pressure peak [Pa] of the isothermal FE line EHL at each contact
    (arrays ``w``, ``R``, ``ue`` over the contacts; inlet viscosity η(0, ``T``)), each warm-started from the
    previous one."""
    ehl = EHLOil(eta0=float(oil.viscosity(0.0, T)), alpha=float(oil.pressure_viscosity(T)), viscosity="roelands",
                 compressible=True)
    out, prev = [], None
    for wi, Ri, ui in zip(w, R, ue):
        r = solve_line_dimensional(float(wi), float(Ri), float(ui), E_red, ehl, level=level, start=prev)
        prev = r.result
        out.append((r.hc, r.hmin, r.pmax))
    hc, hmin, pmax = np.array(out).T
    return hc, hmin, pmax
