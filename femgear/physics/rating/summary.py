"""A :class:`femgear.physics.rating.suite.PairRating` as plain dicts (``femgear info``, ``results.json``), SI units.

Keys: ``safety_factors`` (S_H, S_F per member, S_B, S_intS, S_lambda, the flagged factors, the
flags and the defaulted ``[rating]`` keys), ``bending``, ``scuffing``, ``micropitting``; each of
the last three holds a ``femgear`` sub-dict with femgear's own figure beside the ISO one;
``load_factors``: K_v, K_Hβ, K_Hα with their sources and ISO 6336-1's values
(:func:`load_factors_summary`).
Temperatures in K.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from femgear.physics.rating.suite import PairRating


def _bending(r: PairRating) -> dict[str, Any]:
    b = r.bending
    out = {
        "method": "ISO 6336-3 method B", "tangential_load": b.F_t,
        "s_Fn": [g.s_Fn for g in b.root], "rho_F": [g.rho_F for g in b.root], "h_Fe": [g.h_Fe for g in b.root],
        "Y_F": list(b.Y_F), "Y_S": list(b.Y_S), "Y_beta": b.Y_beta, "Y_B": list(b.Y_B), "Y_DT": b.Y_DT,
        "K_Fbeta": b.K_Fbeta, "sigma_F0": list(b.sigma_F0), "sigma_F": list(b.sigma_F),
        "Y_NT": list(b.Y_NT), "Y_deltarelT": list(b.Y_deltarelT), "Y_RrelT": list(b.Y_RrelT), "Y_X": b.Y_X,
        "sigma_Flim": b.inputs.sigma_Flim, "sigma_FP": list(b.sigma_FP), "S_F": list(b.S_F),
    }
    own = r.own
    if own is not None and own.fillet is not None:
        out["femgear"] = {
            "method": "2-D FE section, plane strain, max principal stress on the fillet (load at the outer point "
                      "of single contact, F_t/(b cos α_wt) per helix)",
            "fillet_max_principal": [f.max_principal for f in own.fillet],
            "ratio_to_sigma_F0": [f.max_principal / s for f, s in zip(own.fillet, b.sigma_F0, strict=True)],
            "fillet_radius": [f.radius for f in own.fillet],
            "fillet_tangent_angle_deg": [math.degrees(f.tangent_angle) for f in own.fillet],
        }
    return out


def _scuffing(r: PairRating) -> dict[str, Any]:
    s = r.scuffing
    out = {
        "method": "ISO/TS 6336-20 flash temperature, ISO/TS 6336-21 integral temperature",
        "fzg_load_stage": s.fzg_stage, "mu_m": s.path.mu_m, "oil_temperature": s.theta_oil,
        "max_flash_temperature": float(np.max(s.path.flash)), "mean_flash_temperature": s.path.mean_flash,
        "bulk_temperature": s.theta_M, "max_contact_temperature": s.max_contact_temperature,
        "scuffing_temperature": s.theta_S, "S_B": s.S_B,
        "bulk_temperature_integral": s.theta_M_int, "integral_temperature": s.theta_int,
        "permissible_integral_temperature": s.theta_intS, "S_intS": s.S_intS,
    }
    own = r.own
    if own is not None and own.temperature is not None:
        out["femgear"] = {"lubrication_level": own.temperature_level,
                          "max_contact_temperature": own.max_temperature,
                          "max_contact_temperature_position": float(own.u[int(np.argmax(own.temperature))])}
    return out


def _micropitting(r: PairRating) -> dict[str, Any]:
    m = r.micropitting
    out = {
        "method": "ISO/TS 6336-22 method B", "load_stage": m.stage, "bulk_temperature": m.theta_M,
        "min_film": float(np.min(m.film)), "lambda_GFmin": m.lambda_GFmin, "lambda_GFmin_position": m.u_min,
        "lambda_GFT": m.lambda_GFT, "lambda_GFP": m.lambda_GFP, "S_lambda": m.S_lambda,
    }
    own = r.own
    if own is not None:
        out["femgear"] = {"film": own.film_level, "min_film": float(np.min(own.film)), "lambda_min": own.lambda_min,
                          "lambda_min_position": float(own.u[int(np.argmin(own.specific_film))])}
    return out


def load_factors_summary(r: PairRating) -> dict[str, Any] | None:
    """K_v, K_Hβ, K_Hα: each ``value`` (used), ``source``, ``iso`` (ISO 6336-1's value beside), ``iso_method``,
    ``femgear`` (femgear's own value where its physics computed it, else None) and ``note``; with ISO's inputs."""
    f = r.factors
    if f is None:
        return None
    out: dict[str, Any] = {name: {"value": k.value, "source": k.source, "iso": k.iso, "iso_method": k.iso_method,
                                  "femgear": k.femgear, "note": k.note}
                           for name, k in (("K_v", f.K_v), ("K_Hbeta", f.K_Hbeta), ("K_Halpha", f.K_Halpha))}
    b, c, t = f.dynamic_b, f.face_c, f.tolerances
    out["K_v"].update({"helices": list(f.K_v_helices), "resonance_ratio": b.N, "resonance_speed_rpm": b.n_E1,
                       "N_S": b.N_S, "regime": b.regime, "B_p": b.B_p, "B_f": b.B_f, "B_k": b.B_k,
                       "tip_relief": b.tip_relief})
    out["K_Hbeta"].update({"F_beta_x": c.F_beta_x, "F_beta_y": c.F_beta_y, "y_beta": c.y_beta,
                           "crowning": c.crowning, "c_gamma_beta": c.c_gamma_beta})
    out["accuracy_grade"] = {"grade": t.grade, "f_pt": list(t.f_pt), "f_falpha": list(t.f_falpha),
                             "f_Hbeta": list(t.f_Hbeta), "f_pb": t.f_pb}
    return out


def pair_rating_summary(r: PairRating) -> dict[str, Any]:
    sf = r.safety_factors
    factors = {"S_H": list(r.pitting.S_H), "S_F": list(r.bending.S_F), "S_B": sf["S_B"], "S_intS": sf["S_intS"],
               "S_lambda": sf["S_lambda"]}
    factors["flagged"] = [k for k in factors if r.flagged(k)]
    factors["flags"] = list(r.flags)
    factors["defaults"] = list(r.defaults)
    out = {"safety_factors": factors, "bending": _bending(r), "scuffing": _scuffing(r),
           "micropitting": _micropitting(r)}
    lf = load_factors_summary(r)
    if lf is not None:
        out["load_factors"] = lf
    return out
