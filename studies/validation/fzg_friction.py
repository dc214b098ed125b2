"""Gear friction of the FZG A test gear over load stages KS 5–12: femgear's μ̄ beside ISO/TS 6336-20's μ_mC and
the FZG power-loss fit of Schlenk with Fernandes's measured lubricant factor (issue 38, item 2).

    PYTHONPATH=$PWD python studies/validation/fzg_friction.py [--coarse] [--gt=ηβσ,σ/β] [--contact=LAW] [--film=FILM]
        [--state=run-in] [--oil=NAME] [--share=B,C] [--ra=R_A]

The pair: FZG A (ISO 14635-1: m 4.5 mm, z 16/24, a 91.5 mm, x 0.8532/−0.5, b 20 mm), bound directly as the
rating's FZG A pair (:func:`femgear.physics.rating.scuffing.fzg_a_pair`: tip diameters from x and a_w,
88.5/112.3 mm, the rig's are 88.77/112.5 mm), because a scene with x2 = −0.5 is refused as undercut today;
the rest of the scene is studies/fzg_c14.toml's (16MnCr5, the rig's shafts).  The test of A/8.3/90: 8.3 m/s at
the pitch circle, 90 °C dip-lubricated, the library's mineral ISO VG 100 (``oil.name = "mineral-vg100"``, an
FVA 3-like oil), ground flanks R_a 0.35 µm (the test gear's, as ISO/TS 6336-20 evaluates it), load stage torques
of ISO 14635-1.

femgear (``formula`` level, the load sharing of :mod:`femgear.physics.lubrication.mixed`, by default Greenwood–Tripp
asperities, the fluid film the mean gap, the scene's default asperity statistics ηβσ 0.04, σ/β 3e-3, μ_b 0.1;
``--contact``, ``--film``, ``--gt`` and ``--state`` set ``roughness.contact`` (``zhou-hoeprich``: the load share
exp(−B λ^C) of λ alone), ``roughness.fluid_film``, the statistics and ``roughness.state``, ``--share`` the
Zhou–Hoeprich B, C, ``--ra`` R_a of both flanks, ``--oil`` the library oil, e.g. ``fva3a``): the flanks' bulk temperature is the oil's plus femgear's own estimate, the fixed
point ϑ_M = ϑ_oil + 0.7 · mean ΔT (the ISO/TS 6336-21 integral-temperature rule femgear's coupling loop uses,
``thermal.bulk_fraction``), fed back as ``thermal.flank_temperature_rise``; μ̄ is the constant μ with femgear's
mesh loss (Ohlendorf's H_V, ``power_loss.equivalent_mu``), the quantity a power-loss measurement gives.

References beside it, both fits to FZG power-loss measurements:
- ISO/TS 6336-20:2017 μ_mC = 0.045 (w_Bt K/(v_ΣC ρ_C))^0.2 η_oil^−0.05 X_R X_L (femgear's rating);
- Schlenk (FZG, 1994), as the GEARpie code (Fernandes, FEUP; CLASSES/CONTACT.py) writes it,
  μ_mz = 0.048 ((F_bn/b)/(v_ΣC ρ_C))^0.2 η_oil^−0.05 R_a^0.25 X_L (N/mm, m/s, mm, mPa s, µm), with the mineral
  oil's X_L = 0.846 of the GEARpie library (its lubricant factors from Fernandes's FZG measurements).
"""

from __future__ import annotations

import argparse
import json
import logging
import math
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[2]
BASE = ROOT / "studies" / "fzg_c14.toml"
STAGES = tuple(range(5, 13))
RA = 0.35e-6
X_L_MINERAL = 0.846          #: the GEARpie library's mineral-oil lubricant factor (Fernandes)
BULK_FRACTION = 0.7          #: ISO/TS 6336-21 C1, femgear's thermal.bulk_fraction default


def setup(gt: tuple[float, float] | None = None, contact: str | None = None, film: str | None = None,
          state: str | None = None, oil: str = "mineral-vg100", share: tuple[float, float] | None = None,
          ra: float = RA) -> list[str]:
    """The scene overrides shared by every stage (the stage sets the torque)."""
    from femgear.physics.rating.scuffing import fzg_a_pair

    pair = fzg_a_pair()
    rpm = 8.3 / (2 * math.pi * pair.rw1) * 60
    out = ['meta.name="fzg_a"', "pair.face_width=0.020", "pinion.profile_shift=0.8532", "gear.profile_shift=-0.5",
           f"operating.speed_rpm={rpm!r}", "operating.ambient_temperature=363.15", f'oil.name="{oil}"',
           "oil.reference_temperature=363.15", f"roughness.ra=[{ra!r}, {ra!r}]", 'physics.lubrication="formula"',
           "numerics.path_points=41"]
    if gt is not None:
        out += [f"roughness.eta_beta_sigma={gt[0]!r}", f"roughness.sigma_over_beta={gt[1]!r}"]
    if share is not None:
        out += [f"roughness.share_b={share[0]!r}", f"roughness.share_c={share[1]!r}"]
    out += [f'roughness.{k}="{v}"' for k, v in (("contact", contact), ("fluid_film", film), ("state", state)) if v]
    return out


def _case(overrides: list[str], torque: float, rise: float):
    from femgear.case import build_case
    from femgear.physics.rating.scuffing import fzg_a_pair
    from femgear.scene import scene_from_dict
    from femgear.scene.load import read_toml

    raw = read_toml(BASE)
    raw["oil"] = {}                     # the library oil (oil.name in the overrides) replaces the C14 scene's own
    raw["pinion"].pop("tip_diameter"), raw["gear"].pop("tip_diameter"), raw["pair"].pop("centre_distance")
    scene = scene_from_dict(raw, [*overrides, f"operating.torque={torque!r}",
                                  f"thermal.flank_temperature_rise={rise!r}"], warn=False)
    return build_case(scene, pair=fzg_a_pair())


def bulk_rise(overrides: list[str], torque: float, tol: float = 0.05) -> float:
    """The fixed point ΔT_M = 0.7 · mean ΔT_contact(ϑ_oil + ΔT_M) of the formula level [K]."""
    from femgear.levels.contact import contact_pass
    from femgear.levels.lubrication import bulk_temperature, friction_along_path, lubrication_solver

    rise = 0.0
    for _ in range(60):
        case = _case(overrides, torque, rise)
        T = np.full(case.path.u.shape, bulk_temperature(case, rise))
        _, dT = friction_along_path(case, contact_pass(case).line_load, lubrication_solver(case), T)
        new = BULK_FRACTION * float(np.mean(dT))
        if abs(new - rise) < tol:
            return new
        rise = 0.5 * (rise + new)
    raise RuntimeError(f"bulk temperature did not settle at T1 = {torque} N m (last {rise:.2f} K)")


def asperity_share(case, rise: float) -> tuple[float, float, float]:
    """(path mean of the asperity load share W_C/W, minimum and mean of the local film parameter λ = h_c/σ) of the
    formula level's split at the bulk temperature, h_c the thermal central film at the local load, radius and
    speeds of each path position (λ of the split: of its fluid part for the JGP split; (0, nan, nan) smooth)."""
    from femgear.levels.contact import contact_pass
    from femgear.levels.lubrication import bulk_temperature, line_friction
    from femgear.physics.lubrication.mixed import load_split
    from femgear.physics.lubrication.traction import thermal_central_film

    lf, k = line_friction(case), case.path
    if lf.roughness is None:
        return 0.0, math.nan, math.nan
    w, T = contact_pass(case).line_load, bulk_temperature(case, rise)
    m = w > 0

    def film(wf, Ef):
        return thermal_central_film(wf, k.R[m], k.ue[m], np.abs(k.srr[m]), T, lf.oil, Ef, lf.solids)[0]

    s = load_split(w[m], k.R[m], film, lf.E_red, lf.roughness)
    return float(np.mean(s.asperity_fraction)), float(np.min(s.film_parameter)), float(np.mean(s.film_parameter))


def schlenk_mu(case) -> float:
    """μ_mz of Schlenk with the mineral X_L of Fernandes (units of the fit: N/mm, m/s, mm, mPa s, µm)."""
    pair, op = case.pair, case.operating
    F_bn = op.pinion_torque / pair.rb1
    w = F_bn / pair.b * 1e-3
    v_t = op.pinion_speed * pair.rw1
    v_sum = 2 * v_t * math.sin(pair.alpha_wt)
    rho_C = pair.u / (1 + pair.u) ** 2 * pair.a_w * math.sin(pair.alpha_wt) * 1e3
    eta = case.oil.viscosity * 1e3
    return 0.048 * (w / (v_sum * rho_C)) ** 0.2 * eta ** -0.05 * (case.flanks.ra_mean * 1e6) ** 0.25 * X_L_MINERAL


def stage(overrides: list[str], ks: int) -> dict:
    from femgear.physics.rating.scuffing import FZG_A_TORQUE
    from femgear.rate import scene_info

    torque = FZG_A_TORQUE[ks - 1]
    rise = bulk_rise(overrides, torque)
    case = _case(overrides, torque, rise)
    info = scene_info(case)
    smooth = scene_info(_case([*overrides, 'roughness.model="smooth"'], torque, rise))
    f, r = info.figures, info.rating
    mu, iso, sch = f.power_loss.equivalent_mu, r.scuffing.path.mu_m, schlenk_mu(case)
    return {"stage": ks, "pinion_torque": torque, "max_hertz_pressure": float(info.contact.hertz_pressure.max()),
            "bulk_rise": rise, "lambda_min": r.own.lambda_min, "lambda_GFmin_iso": r.micropitting.lambda_GFmin,
            "mu_mean": mu, "mu_mean_smooth": smooth.figures.power_loss.equivalent_mu, "mu_mC_iso": iso,
            "mu_mz_schlenk": sch, "ratio_iso": mu / iso, "ratio_schlenk": mu / sch,
            "max_contact_temperature": r.own.max_temperature, "iso_max_contact_temperature":
                r.scuffing.max_contact_temperature, "iso_integral_temperature": r.scuffing.theta_int,
            "power_loss": f.power_loss.mean_loss, "iso_power_loss": f.power_loss_iso.mean_loss,
            **dict(zip(("asperity_share", "film_parameter_min", "film_parameter_mean"), asperity_share(case, rise)))}


def run(coarse: bool = False, gt: tuple[float, float] | None = None, contact: str | None = None,
        film: str | None = None, state: str | None = None, oil: str = "mineral-vg100",
        share: tuple[float, float] | None = None, ra: float = RA) -> dict:
    logging.getLogger("femgear").setLevel(logging.ERROR)
    overrides = setup(gt, contact, film, state, oil, share, ra)
    if coarse:
        overrides = [*overrides, "numerics.path_points=21"]
    stages = (5, 9, 12) if coarse else STAGES
    rows = [stage(overrides, ks) for ks in stages]
    mu, iso, ratio = (np.array([r[k] for r in rows]) for k in ("mu_mean", "mu_mC_iso", "ratio_iso"))
    return {"rows": rows, "coarse": coarse, "gt": gt, "contact": contact, "film": film, "state": state, "oil": oil,
            "share": share, "ra": ra,
            "trend": {"mu_last_over_first": float(mu[-1] / mu[0]), "iso_last_over_first": float(iso[-1] / iso[0]),
                      "ratio_min": float(ratio.min()), "ratio_max": float(ratio.max())}}


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--coarse", action="store_true")
    p.add_argument("--gt", default=None, help="asperity statistics ηβσ,σ/β (default: the scene's 0.04,3e-3)")
    p.add_argument("--contact", default=None, help="roughness.contact (default greenwood-tripp)")
    p.add_argument("--film", default=None, help="roughness.fluid_film (default mean-gap)")
    p.add_argument("--state", default=None, help="roughness.state (default new)")
    p.add_argument("--oil", default="mineral-vg100", help="the library oil (default mineral-vg100)")
    p.add_argument("--share", default=None, help="Zhou–Hoeprich B,C (default: the scene's 1.90,0.99)")
    p.add_argument("--ra", type=float, default=RA, help=f"R_a of both flanks [m] (default {RA})")
    args = p.parse_args(argv)
    gt = tuple(float(x) for x in args.gt.split(",")) if args.gt else None
    share = tuple(float(x) for x in args.share.split(",")) if args.share else None
    res = run(args.coarse, gt, args.contact, args.film, args.state, args.oil, share, args.ra)
    print("KS  T1[Nm]  pH[GPa]  dT_M[K]  λ_min  λ_GF(ISO)  μ̄ smooth  μ̄ femgear  μ_mC ISO  μ_mz Schlenk  "
          "μ̄/μ_mC  μ̄/μ_mz  θmax[°C] θB,ISO[°C]  W_C/W  λ_c min/mean")
    for r in res["rows"]:
        print(f"{r['stage']:2d} {r['pinion_torque']:7.1f} {r['max_hertz_pressure'] / 1e9:7.2f} {r['bulk_rise']:7.1f} "
              f"{r['lambda_min']:6.3f} {r['lambda_GFmin_iso']:9.3f} {r['mu_mean_smooth']:9.4f} {r['mu_mean']:10.4f} "
              f"{r['mu_mC_iso']:9.4f} {r['mu_mz_schlenk']:12.4f} {r['ratio_iso']:8.2f} {r['ratio_schlenk']:7.2f} "
              f"{r['max_contact_temperature'] - 273.15:8.0f} {r['iso_max_contact_temperature'] - 273.15:10.0f}"
              f"  {r['asperity_share']:5.3f}  {r['film_parameter_min']:.3f}/{r['film_parameter_mean']:.3f}")
    t = res["trend"]
    print(f"μ̄(KS {res['rows'][-1]['stage']})/μ̄(KS {res['rows'][0]['stage']}) = {t['mu_last_over_first']:.2f} "
          f"(ISO μ_mC: {t['iso_last_over_first']:.2f}); μ̄/μ_mC {t['ratio_min']:.2f}…{t['ratio_max']:.2f}")
    out = ROOT / "out"
    out.mkdir(exist_ok=True)
    (out / "fzg_friction.json").write_text(json.dumps(res, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
