"""Thin rims on the baseline pair: femgear's FE fillet stress against ISO 6336-3's Y_B, mesh stiffness and LTE.

    python studies/body/thin_rim.py [--coarse] [--no-ltca]

The baseline gear's rim is swept over s_R/h_t = 0.5, 0.7, 1.0, 1.2, 2.0 (s_R the rim below the root circle, h_t
the tooth depth), against the solid disc of the scene itself (the body on its Ø40 mm shaft, s_R/h_t = 5.2).

1. Fillet stress (2-D plane-strain P2 section of the whole gear, :class:`femgear.physics.body.compliance.ToothFE`)
   under one load at the gear's outer point of single contact (ISO 6336-3 method B's load point), relative to
   the solid disc, beside ISO 6336-3's rim factor Y_B = 1.6 ln(2.242 h_t/s_R) (1 from s_R/h_t ≥ 1.2), with three
   supports of the rim: ``clamped`` (its inner circle held: a rim on a rigid shaft, femgear's bodies), ``web``
   (a webbed gear: the rim on a central web :data:`WEB_RATIO` of the face width thick, from a hub of the face
   width, :data:`HUB_RATIO` times the shaft's diameter, the shaft clamped: the solid disc but for the web) and
   ``distributed`` (only the inner circle's mean rigid motion held, a distributing coupling: a free ring, the
   softest bound).
2. The rim's effect on the single stiffness: the members' 2-D tooth compliance at the pitch point, and the
   pair's single stiffness with both members' rims alike (Hertz term included) beside ISO 6336-1's gear blank
   factor C_R for the webbed gears; unless ``--no-ltca``, the ``ltca`` level (the 3-D member bodies, clamped
   at the gear's bore): mean mesh stiffness and loaded TE peak-to-peak per rim.

Finding (docs/models/body-stiffness.md, "Thin rims against ISO 6336-3's Y_B"): the FE ratio follows Y_B within
15 % only where Y_B = 1 (s_R/h_t ≥ 1.2).  Below, it depends on the support, which ISO's one curve does not name.
At 0.5 h_t, where Y_B = 2.40, the clamped rim gives 0.95 and the web 1.10.  The free ring moves the largest root
stress to the compression fillet (5.2×) and to a root 58° away (4.2×).  The same dependence is published:

- "Simple stress formulae for a thin-rimmed spur gear", J. Mech. Transm. Autom. Des. 107(3):406 (1985): FE
  fillet stresses fitted to rim thickness and supporting condition;
- Lewicki & Ballarini, "Effect of rim thickness on gear crack propagation path", J. Mech. Des. 119:88 (1997),
  NASA TM-107229: tested and modelled backup ratios 3.3 and 1.0 broke teeth, 0.3 broke rims, and 0.5 broke
  either;
- Lewicki & Ballarini, Int. J. Fract. 87:59 (1997): the fillet's compressive cyclic stress grows as the rim
  thins.

The webbed pair's single stiffness follows ISO 6336-1's C_R within 11 %.

Prints a table and one JSON line (also ``out/body/thin_rim.json``).  ``--coarse``: coarser sections
(h = m_n/3) and no LTCA (the test setting).
"""

from __future__ import annotations

import json
import math
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[2]
RATIOS = (0.5, 0.7, 1.0, 1.2, 2.0)
SUPPORTS = ("clamped", "web", "distributed")
MEASURES = ("tension", "compression", "anywhere")
WEB_RATIO = 0.25     #: web thickness over face width b_s/b of the webbed gears (ISO 6336-1's C_R: 0.2 ≤ b_s/b ≤ 1.2)
HUB_RATIO = 1.8      #: hub diameter over shaft diameter of the webbed gears (a common proportion of steel hubs)


def setup(scene_path: str | Path = ROOT / "studies" / "paper_baseline.toml"):
    from femgear.scene import load_scene

    return load_scene(scene_path)


def _rim(pair, member: int) -> tuple[float, float]:
    """(root radius, tooth depth h_t) of ``member`` [m]."""
    rf, ra = (pair.rf1, pair.ra1) if member == 1 else (pair.rf2, pair.ra2)
    return rf, ra - rf


def _bores(pair, member: int = 2, ratios=RATIOS) -> dict:
    """The rim's inner radius per s_R/h_t of ``ratios`` [m]."""
    rf, h_t = _rim(pair, member)
    return {r: rf - r * h_t for r in ratios}


def _model(scene, pair, member: int, bore: float, support: str, h: float | None, **kw):
    """One member's section with the rim's inner radius ``bore``; the solid disc when ``bore`` is the shaft."""
    from femgear.physics.body.compliance import ToothFE

    m = scene.material
    shaft = 0.5 * (scene.pinion if member == 1 else scene.gear).shaft_diameter
    web = None
    if support == "web":                  # the rim's inner circle ``bore`` on a web, the shaft clamped
        if bore > HUB_RATIO * shaft:      # (else the solid disc: ISO's C_R = 1, a web as wide as the face)
            web = (WEB_RATIO, HUB_RATIO * shaft, bore)
        support, bore = "clamped", shaft
    return ToothFE(pair, member, m.youngs_modulus, m.poisson_ratio, h=h, bore_radius=bore, support=support,
                   web=web, **kw)


def root_stresses(scene, pair, bore: float, support: str, h: float) -> dict:
    """Root stresses of the gear under one load at its outer point of single contact [Pa]: the loaded tooth's
    tension fillet (largest σ₁ on it, ISO's σ_F), its compression fillet (|smallest σ₃|) and the largest σ₁ on
    any fillet of the body (a thin rim that bends puts it elsewhere), with its polar angle from the loaded tooth."""
    from femgear.physics.body.fillet import fillet_principal

    m = scene.material
    model = _model(scene, pair, 2, bore, support, h, n_teeth=None, refine_ratio=0.2)
    disp, _, _ = model.solve_load(pair.u_end - pair.p_bt, 1.0e5)    # N/m: linear, the ratios do not depend on it
    fp = fillet_principal(model, disp, m.youngs_modulus, m.poisson_ratio)
    tooth = np.abs(fp.polar) < math.pi / pair.z2
    k = np.unravel_index(int(np.argmax(fp.s1)), fp.s1.shape)
    return {"tension": float(fp.s1[tooth].max()), "compression": float(-fp.s3[tooth].min()),
            "anywhere": float(fp.s1.max()), "anywhere_deg": float(np.degrees(fp.polar[k])),
            "dofs": int(model.ndofs)}


def fillet_curve(scene, pair, coarse: bool, ratios=RATIOS, supports=SUPPORTS) -> dict:
    """Root stresses per rim (s_R/h_t in ``ratios``) and support, and relative to the solid disc on the scene's
    shaft."""
    h = pair.m_n / 3 if coarse else pair.m_n / 5
    ref_bore = 0.5 * scene.gear.shaft_diameter
    out = {}
    for support in supports:
        thick = root_stresses(scene, pair, ref_bore, support, h)
        rows = {r: root_stresses(scene, pair, b, support, h) for r, b in _bores(pair, ratios=ratios).items()}
        out[support] = {"thick": thick, "rows": rows,
                        "ratio": {r: {q: row[q] / thick[q] for q in MEASURES} for r, row in rows.items()}}
    out["reference_ratio"] = (pair.rf2 - ref_bore) / (pair.ra2 - pair.rf2)
    return out


def compliance_curve(scene, pair, coarse: bool) -> dict:
    """Tooth compliances at the pitch point per rim and support [m/N · m], relative to the solid disc: the gear's
    for every support; for ``clamped`` and ``web`` also the pinion's (its rim at the same s_R/h_t) and the pair's
    single stiffness with both rims alike (Hertz included), beside ISO 6336-1's C_R for ``web``."""
    from femgear.physics.stiffness.iso6336 import gear_blank_factor
    from femgear.physics.stiffness.pem import hertz_compliance

    h = pair.m_n / 3 if coarse else None
    m = scene.material
    c_hertz = hertz_compliance(m.youngs_modulus, m.poisson_ratio)
    shafts = {1: 0.5 * scene.pinion.shaft_diameter, 2: 0.5 * scene.gear.shaft_diameter}

    def member_curve(member, support):
        def c(bore):
            return _model(scene, pair, member, bore, support, h, n_positions=1).compliance(pair.u_pitch)
        thick = c(shafts[member])
        return thick, {r: c(b) for r, b in _bores(pair, member).items()}

    out = {}
    for support in SUPPORTS:
        thick2, c2 = member_curve(2, support)
        row = {"thick": thick2, "ratio": {r: c2[r] / thick2 for r in RATIOS}}
        if support != "distributed":
            thick1, c1 = member_curve(1, support)
            k_thick = 1.0 / (c_hertz + thick1 + thick2)
            row["pinion_ratio"] = {r: c1[r] / thick1 for r in RATIOS}
            row["pair_stiffness_ratio"] = {r: 1.0 / (c_hertz + c1[r] + c2[r]) / k_thick for r in RATIOS}
        out[support] = row
    out["C_R"] = {r: gear_blank_factor(r * _rim(pair, 2)[1], WEB_RATIO, pair.m_n) for r in RATIOS}
    return out


def ltca_curve(scene, pair) -> dict:
    """Mean mesh stiffness and loaded TE p-p of the ``ltca`` level per gear rim (3-D bodies, clamped bores)."""
    from femgear.case import build_case
    from femgear.levels import stiffness as stiffness_levels

    rows = {}
    for label, bore in [("thick", 0.0)] + list(_bores(pair).items()):
        s = scene.model_copy(update={"gear": scene.gear.model_copy(update={"bore_radius": bore})})
        st = stiffness_levels.of(build_case(s), level="ltca")
        rows[label] = {"k_mean": float(st.mean), "lte_pp": float(st.ltca.lte_peak_to_peak)}
    return rows


def run(scene=None, coarse: bool = False, ltca: bool = True) -> dict:
    from femgear.case.pair import pair_from_scene
    from femgear.physics.rating.bending import rim_factor

    scene = scene or setup()
    pair = pair_from_scene(scene)
    out = {"h_t": pair.ra2 - pair.rf2, "rf": pair.rf2, "ratios": list(RATIOS), "web_ratio": WEB_RATIO,
           "hub_ratio": HUB_RATIO,
           "shaft_radius": 0.5 * scene.gear.shaft_diameter, "Y_B": {r: rim_factor(r) for r in RATIOS},
           "fillet": fillet_curve(scene, pair, coarse), "compliance": compliance_curve(scene, pair, coarse)}
    if ltca and not coarse:
        out["ltca"] = ltca_curve(scene, pair)
    return out


def report(res: dict) -> str:
    f, c = res["fillet"], res["compliance"]
    lines = [f"baseline gear: h_t = {res['h_t'] * 1e3:.3f} mm, r_f = {res['rf'] * 1e3:.3f} mm; solid disc "
             f"s_R/h_t = {f['reference_ratio']:.2f} (clamped on the scene's shaft, radius {res['shaft_radius'] * 1e3:.0f} "
             f"mm); web b_s/b = {res['web_ratio']:g} on a hub of {res['hub_ratio']:g} shaft diameters.  Root stresses relative to the solid disc:",
             "| s_R/h_t | ISO Y_B | clamped: tension fillet | compression fillet | web: tension fillet | "
             "compression fillet | free ring: tension fillet | compression fillet | largest σ₁ anywhere (at) |",
             "|---|---|---|---|---|---|---|---|---|"]
    for r in res["ratios"]:
        cl, w, d = (f[s]["ratio"][r] for s in SUPPORTS)
        at = f["distributed"]["rows"][r]["anywhere_deg"]
        lines.append(f"| {r:g} | {res['Y_B'][r]:.3f} | {cl['tension']:.3f} | {cl['compression']:.3f} | "
                     f"{w['tension']:.3f} | {w['compression']:.3f} | {d['tension']:.3f} | {d['compression']:.3f} | "
                     f"{d['anywhere']:.3f} ({at:+.0f}°) |")
    lines += ["", "Single stiffness relative to the solid disc (2-D sections at the pitch point):",
              "| s_R/h_t | gear tooth compliance: clamped | web | free ring | pair single stiffness, both rims "
              "alike: clamped | web | ISO 6336-1 C_R (web) | web / C_R |", "|---|---|---|---|---|---|---|---|"]
    for r in res["ratios"]:
        kw = c["web"]["pair_stiffness_ratio"][r]
        lines.append(f"| {r:g} | {c['clamped']['ratio'][r]:.3f} | {c['web']['ratio'][r]:.3f} | "
                     f"{c['distributed']['ratio'][r]:.2f} | {c['clamped']['pair_stiffness_ratio'][r]:.3f} | "
                     f"{kw:.3f} | {c['C_R'][r]:.3f} | {kw / c['C_R'][r]:.3f} |")
    if "ltca" in res:
        t = res["ltca"]["thick"]
        lines += ["", "`ltca` level (3-D bodies, the gear clamped at its rim's inner circle):",
                  "| gear rim | k mean [N/m] | change | LTE p-p [µm] | change |", "|---|---|---|---|---|"]
        for label, row in res["ltca"].items():
            lines.append(f"| {label if label == 'thick' else f's_R/h_t = {label:g}'} | {row['k_mean']:.4e} | "
                         f"{100 * (row['k_mean'] / t['k_mean'] - 1):+.1f} % | {row['lte_pp'] * 1e6:.4f} | "
                         f"{100 * (row['lte_pp'] / t['lte_pp'] - 1):+.1f} % |")
    return "\n".join(lines)


def main(argv=None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    res = run(coarse="--coarse" in argv, ltca="--no-ltca" not in argv)
    print(report(res))
    out = ROOT / "out" / "body"
    out.mkdir(parents=True, exist_ok=True)
    text = json.dumps(res, default=float)
    (out / "thin_rim.json").write_text(text)
    print(text)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
