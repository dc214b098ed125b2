"""Thermal inlet factors and flash temperatures beside a TEHL solve (what a turbo-gear engineer compares).

* Thermal loading L_th = β η0 u_e² / k_f (β = −∂ln η/∂T and η0 at the inlet temperature, u_e the entrainment
  speed (u1 + u2)/2, k_f the oil conductivity): the ratio of the inlet's shear heating to conduction.
* Murch & Wilson (1975, J. Lubr. Technol. 97:212, inlet-zone analysis, pure rolling):
  φ_MW = 3.94 / (3.94 + L_th^0.62).
* Gupta et al. (1992, J. Tribol. 114:609), with sliding: φ_G (:func:`femgear.physics.lubrication.traction.
  gupta_thermal_factor`, with |SRR| and u_e).
  Both forms are as recalled in the project notes; neither paper is in the stored library, so their
  definitions of u (mean or sum speed) and S (SRR or slide-to-sum) could not be checked there (the
  validation study reports the sum-speed and slide-to-sum readings beside them).
* Blok's flash temperature (:func:`femgear.physics.lubrication.flash.blok_flash_temperature`) for the TEHL
  μ, beside the TEHL's own surface temperature rise.
"""

from __future__ import annotations

import numpy as np

from femgear.physics.lubrication.flash import blok_flash_temperature
from femgear.physics.lubrication.oil import OilLaw
from femgear.physics.lubrication.traction import gupta_thermal_factor


def thermal_loading(ue, T, oil: OilLaw, k_oil: float) -> np.ndarray:
    """L_th = β η0 u_e² / k_f [-] at the bulk temperatures ``T`` [K]."""
    T = np.asarray(T, dtype=float)
    return oil.temperature_viscosity(T) * oil.viscosity(0.0, T) * np.asarray(ue, dtype=float) ** 2 / k_oil


def murch_wilson_factor(L_th) -> np.ndarray:
    """φ_MW = 3.94 / (3.94 + L_th^0.62) (Murch & Wilson 1975, rolling)."""
    return 3.94 / (3.94 + np.asarray(L_th, dtype=float) ** 0.62)


def inlet_figures(results, w, R, ue, srr, T, oil: OilLaw, E_red: float, props) -> dict:
    """Per contact (arrays over ``results``, TEHL line or point results with ``hc``, ``mu``, ``dT_surface``):
    ``thermal_loading``, ``phi_murch_wilson``, ``phi_gupta``, ``phi_tehl`` (h_c / h_c,iso), ``flash_tehl``
    [K] and ``flash_blok`` [K]."""
    w, R, ue, srr = (np.broadcast_to(np.asarray(a, dtype=float), (len(results),)) for a in (w, R, ue, srr))
    T = np.broadcast_to(np.asarray(T, dtype=float), w.shape)
    Lth = thermal_loading(ue, T, oil, props.k_oil)
    b = np.sqrt(8.0 * w * R / (np.pi * E_red))
    ph = np.sqrt(w * E_red / (2.0 * np.pi * R))
    mu = np.array([r.mu for r in results])
    v1, v2 = ue * (1 + srr / 2), ue * (1 - srr / 2)
    eta0 = oil.viscosity(0.0, T)
    return {"thermal_loading": Lth, "phi_murch_wilson": murch_wilson_factor(Lth),
            "phi_gupta": gupta_thermal_factor(ph, E_red, srr, ue, eta0, oil.temperature_viscosity(T), props.k_oil),
            "phi_tehl": np.array([r.hc / r.hc_isothermal for r in results]),
            "flash_tehl": np.array([r.dT_surface for r in results]),
            "flash_blok": blok_flash_temperature(mu, w, srr * ue, b, v1, v2, props.B1, props.B2)}
