"""LTCA of the baseline pair: mesh convergence, stiffness vs ISO 6336 / PEM, Harris map, pressure map.

    python studies/ltca/ltca_study.py [--coarse]

1. Mesh convergence (P1 segment levels 1–4, h_tooth = m_n/3 … m_n/6; ``--coarse``: 0, 1): LTE
   peak-to-peak and mean secant mesh stiffness at the scene torque, unmodified flanks, 64
   phases; the change between the two finest levels, the observed order p of the three
   finest (:func:`observed_order`), the Richardson extrapolation and each level's error
   against it (level 1 is the default: mesh + compliance ≤ 60 s; level 4 costs ~5 min a member).
2. Mean mesh stiffness against ISO 6336 c_γα (both helices, normal direction) and PEM; the member
   bodies (:func:`body_checks`): the cross-helix compliance's size and effect, the rim down to the
   bore against the earlier clamp at r_f − 3 m_n, the far-field grading against a finer one.
3. Harris map: a linear "long" tip relief on both members designed for the scene load
   (:func:`relief_design`): the baseline (β = 30°) with the helical rule C_a = w/c_γ (the mean
   mesh deflection), the near-spur pair (β = 1°, segment level 0, the case of the classic map)
   with the spur rule C_a = F_bt/(b c′) (the single-pair deflection) and, for comparison, with
   the helical rule; each also with the amount minimising LTE p-p at the design load
   (Tavakoli & Houser, ASME JMTAD 108:86, 1986); LTE p-p against load 0.1–2 × design, PNG
   ``out/ltca_harris.png``.
4. Discretisation of the contact problem: 64 vs 128 phases (LTE harmonics 1–5), 16 vs 32
   points per contact line (LTE p-p, mean stiffness).
5. The pressure map of the design case on the 3-D pinion flank, ``out/ltca_pressure.vtu``.
Prints a table and one JSON line (also ``out/ltca_study.json``).
"""

from __future__ import annotations

import json
import math
import os
import sys
from pathlib import Path

from femgear.case import build_case
from femgear.case.pair import pair_from_scene
from femgear.levels.stiffness import body_options

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
import numpy as np

ROOT = Path(__file__).resolve().parents[2]


def setup(scene_path=ROOT / "studies" / "paper_baseline.toml"):
    from femgear.scene import load_scene

    scene = load_scene(scene_path)
    return scene, pair_from_scene(scene)


def convergence(scene, pair, levels, phases=64):
    from femgear.physics.ltca.analysis import build_model, mesh_cycle, normal_force
    from femgear.physics.mesh.segment import default_spec

    E, nu = scene.material.youngs_modulus, scene.material.poisson_ratio
    F = normal_force(pair, scene.operating.torque, scene.operating.driver)
    rows = []
    for lv in levels:
        model = build_model(pair, E, nu, level=lv, **body_options(build_case(scene)))
        r = mesh_cycle(model, F, None, n_phases=phases, keep_lines=False)
        rows.append({"level": lv, "h_tooth_mm": default_spec(pair, 1, lv).h_tooth * 1e3,
                     "ndofs": [int(model.kernels[m].ndofs) for m in (1, 2)],
                     "lte_pp_um": r.lte_peak_to_peak() * 1e6, "lte_mean_um": float(r.lte.mean() * 1e6),
                     "k_mean": r.mean_stiffness()})
    out = {"rows": rows}
    if len(rows) >= 2:
        a, b = rows[-2], rows[-1]
        out["change_finest_lte_pp"] = abs(b["lte_pp_um"] - a["lte_pp_um"]) / abs(b["lte_pp_um"])
        out["change_finest_k_mean"] = abs(b["k_mean"] - a["k_mean"]) / b["k_mean"]
    if len(rows) >= 3:
        h = [r["h_tooth_mm"] for r in rows[-3:]]
        for key in ("lte_pp_um", "k_mean"):
            f = [r[key] for r in rows[-3:]]
            p = observed_order(h, f)
            out[f"order_{key}"] = p
            if math.isfinite(p):           # Richardson: f(h) = f* + C h^p through the two finest
                extra = f[2] + (f[2] - f[1]) * h[2] ** p / (h[1] ** p - h[2] ** p)
                out[f"extrapolated_{key}"] = extra
                out[f"default_error_{key}"] = [(r[key] - extra) / extra for r in rows]
    return out


def body_checks(scene, pair, level=1, phases=64):
    """The member bodies at ``level``: size of the cross-helix compliance, what it, the rim down to the bore
    and the far-field grading do to the mean stiffness and LTE p-p (unmodified flanks, scene torque).

    Variants: ``no_cross`` (the same kernels with the cross-helix block dropped, and with it the half-space
    surface term between the helices: the helices coupled only through the common approach), ``clamp_rf_3mn`` (the
    body clamped at r_f − 3 m_n, the earlier segment's clamp), ``fine_far_field`` (grade 0.25, h_far
    6 h_tooth, all five teeth at ≤ h: the grading's cost in accuracy)."""
    from dataclasses import replace

    from femgear.physics.ltca.analysis import build_model, mesh_cycle, normal_force
    from femgear.physics.mesh.segment import default_spec

    E, nu = scene.material.youngs_modulus, scene.material.poisson_ratio
    F = normal_force(pair, scene.operating.torque, scene.operating.driver)
    body = body_options(build_case(scene))
    h_tooth = default_spec(pair, 1, level).h_tooth
    models = {"default": build_model(pair, E, nu, level=level, **body)}
    models["no_cross"] = replace(models["default"], kernels={m: replace(k, cross=None)
                                                             for m, k in models["default"].kernels.items()})
    models["clamp_rf_3mn"] = build_model(pair, E, nu, level=level, **{**body, "bore_radius": (0.0, 0.0)})
    models["fine_far_field"] = build_model(pair, E, nu, level=level, **body,
                                           spec_options={"grade": 0.25, "h_far": 6 * h_tooth, "fine_teeth": 5})
    out = {}
    for name, model in models.items():
        r = mesh_cycle(model, F, None, n_phases=phases, keep_lines=False)
        out[name] = {"k_mean": r.mean_stiffness(), "lte_pp_um": r.lte_peak_to_peak() * 1e6,
                     "ndofs": [int(model.kernels[m].ndofs) for m in (1, 2)]}
    for m in (1, 2):
        k = models["default"].kernels[m]
        mid = int(np.nonzero(k.offsets == 0)[0][0])
        out[f"member{m}_cross"] = {"max_cross_over_max_self": float(np.abs(k.cross).max() / np.abs(k.bulk[mid]).max()),
                                   "mean_abs_cross_over_mean_diag_self": float(np.abs(k.cross).mean()
                                                                                / np.mean(np.diag(k.bulk[mid])))}
    return out


def observed_order(h, f) -> float:
    """Order p of f(h) = f* + C h^p through three levels of any spacing (bisection on p ∈ [0.2, 8]).

    (Roache, *Verification and Validation in Computational Science and Engineering*, 1998,
    §5.4: the observed order from three grids; with a constant refinement ratio r it is
    ln(Δ₀₁/Δ₁₂)/ln r.)  NaN when the changes do not shrink monotonically (no asymptotic range).
    """
    d01, d12 = f[1] - f[0], f[2] - f[1]
    if d01 == 0 or d12 == 0 or d01 * d12 < 0 or abs(d12) >= abs(d01):
        return float("nan")
    target = d01 / d12

    def g(p):
        return (h[0] ** p - h[1] ** p) / (h[1] ** p - h[2] ** p) - target

    lo, hi = 0.2, 8.0
    if g(lo) * g(hi) > 0:
        return float("nan")
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if g(lo) * g(mid) > 0 else (lo, mid)
    return 0.5 * (lo + hi)


def discretisation(scene, pair, level):
    """Phases (64 vs 128) and contact points per line (16 vs 32) at one segment level, unmodified and
    with a 5 µm / 0.4 p_bt tip relief: LTE p-p, mean stiffness and LTE harmonics 1–5."""
    from femgear.physics.ltca.analysis import build_model, mesh_cycle, normal_force
    from femgear.scene.schema import Modifications

    E, nu = scene.material.youngs_modulus, scene.material.poisson_ratio
    F = normal_force(pair, scene.operating.torque, scene.operating.driver)
    model = build_model(pair, E, nu, level=level, **body_options(build_case(scene)))
    out = {}
    for name, mods in (("unmodified", None), ("tip_relief", Modifications(tip_relief=5e-6, tip_relief_length=0.4 * pair.p_bt))):
        runs = {(n, m): mesh_cycle(model, F, mods, n_phases=n, n_line=m, keep_lines=False)
                for n, m in ((64, 16), (128, 16), (64, 32))}
        ref = runs[(64, 16)]
        h0 = ref.harmonics(5)
        out[name] = {
            "lte_pp_um": ref.lte_peak_to_peak() * 1e6, "k_mean": ref.mean_stiffness(),
            "harmonics_um": (h0 * 1e6).tolist(),
            "phases_128_harmonics_change": (np.abs(runs[(128, 16)].harmonics(5) - h0) / h0.max()).tolist(),
            "points_32_lte_pp_change": abs(runs[(64, 32)].lte_peak_to_peak() / ref.lte_peak_to_peak() - 1),
            "points_32_k_change": abs(runs[(64, 32)].mean_stiffness() / ref.mean_stiffness() - 1),
        }
    return out


def near_spur_pair(pair):
    """The baseline pair at β = 1° (ε_β ≈ 0.03): the spur case the classic Harris map describes."""
    from dataclasses import replace

    return replace(pair, beta=math.radians(1.0))


def relief_design(pair, unmodified, rule: str) -> tuple[float, float]:
    """(amount, length) of a linear tip relief on both members designed for the load of ``unmodified``.

    Length: the "long" relief over the two-pair zone, L_Ca = (ε_α − 1) p_bt = g_α − p_bt,
    starting at the highest point of single tooth contact (Smith, *Gear Noise and
    Vibration*, 2nd ed. 2003, ch. 5: the Harris map; [RECALLED]).  Amount, the deflection
    the relief is to take up at the design load [RECALLED: Niemann & Winter,
    *Maschinenelemente* II, 1989, §21; Smith ch. 5]:
    - ``spur``: the single-pair deflection C_a = F_bt/(b c′) — a tooth pair alone carries the
      whole load at the start of its relief; from the LTCA: the largest loaded TE of the
      unmodified pair over the cycle (its single-pair zone);
    - ``helical``: the load per unit length on the total contact lines over the stiffness per
      unit length, C_a = w/c_γ = F_bn/(L̄ c_γ,n) = the mean mesh deflection; from the LTCA:
      the cycle mean of the loaded TE (normal, both helices).
    """
    length = pair.g_alpha - pair.p_bt
    if rule == "spur":
        return float(unmodified.lte.max()), length
    if rule == "helical":
        return float(unmodified.lte.mean()), length
    raise ValueError(f"rule must be 'spur' or 'helical', got {rule!r}")


def harris(scene, pair, level, factors, phases=32, rule="helical"):
    """LTE p-p against load for a linear tip relief designed by ``rule`` (:func:`relief_design`) for the scene
    load, for the relief amount minimising LTE p-p at that load (Tavakoli & Houser, ASME JMTAD 108:86, 1986),
    and unmodified."""
    from femgear.physics.ltca.analysis import build_model, mesh_cycle, normal_force
    from femgear.scene.schema import Modifications

    E, nu = scene.material.youngs_modulus, scene.material.poisson_ratio
    Fd = normal_force(pair, scene.operating.torque, scene.operating.driver)
    model = build_model(pair, E, nu, level=level, **body_options(build_case(scene)))
    ref = mesh_cycle(model, Fd, None, n_phases=phases, keep_lines=False)
    Ca, length = relief_design(pair, ref, rule)
    mods = Modifications(tip_relief=Ca, tip_relief_length=length)
    amounts = Ca * np.linspace(0.1, 3.0, 30)
    pp_design = [mesh_cycle(model, Fd, Modifications(tip_relief=a, tip_relief_length=length), n_phases=phases,
                            keep_lines=False).lte_peak_to_peak() for a in amounts]
    Ca_opt = float(amounts[int(np.argmin(pp_design))])
    mods_opt = Modifications(tip_relief=Ca_opt, tip_relief_length=length)
    pp, pp0, ppo = [], [], []
    for f in factors:
        pp.append(mesh_cycle(model, f * Fd, mods, n_phases=phases, keep_lines=False).lte_peak_to_peak())
        pp0.append(mesh_cycle(model, f * Fd, None, n_phases=phases, keep_lines=False).lte_peak_to_peak())
        ppo.append(mesh_cycle(model, f * Fd, mods_opt, n_phases=phases, keep_lines=False).lte_peak_to_peak())
    design = mesh_cycle(model, Fd, mods_opt, n_phases=64)
    return {"rule": rule, "eps_alpha": pair.eps_alpha, "eps_beta": pair.b * math.sin(pair.beta) / (math.pi * pair.m_n),
            "design_force": Fd, "tip_relief_um": Ca * 1e6, "relief_length_mm": length * 1e3,
            "mean_deflection_um": float(ref.lte.mean() * 1e6), "single_pair_deflection_um": float(ref.lte.max() * 1e6),
            "factors": list(factors), "lte_pp_um": [p * 1e6 for p in pp], "lte_pp_unmodified_um": [p * 1e6 for p in pp0],
            "argmin_factor": float(factors[int(np.argmin(pp))]),
            "local_minima_factors": [float(factors[i]) for i in range(1, len(pp) - 1) if pp[i] < pp[i - 1] and pp[i] < pp[i + 1]],
            "argmin_ratio_factor": float(factors[int(np.argmin(np.asarray(pp) / np.asarray(pp0)))]),
            "lte_pp_at_design_vs_amount_um": [p * 1e6 for p in pp_design], "amounts_um": (amounts * 1e6).tolist(),
            "tip_relief_optimised_um": Ca_opt * 1e6, "lte_pp_optimised_um": [p * 1e6 for p in ppo],
            "argmin_factor_optimised": float(factors[int(np.argmin(ppo))])}, design, model


def run(coarse: bool = False) -> dict:
    from femgear.edge.io.ltca import write_flank_pressure
    from femgear.physics.stiffness import uniform_mesh_stiffness
    from femgear.physics.stiffness.pem import pem_mesh_stiffness
    from femgear.physics.stiffness.tvms import iso6336_helix_stiffness

    scene, pair = setup()
    levels = (0, 1) if coarse else (1, 2, 3, 4)
    conv = convergence(scene, pair, levels)
    body = body_checks(scene, pair, 0 if coarse else 1)
    factors = np.round(np.linspace(0.1, 2.0, 8 if coarse else 14), 3)
    h, design, model = harris(scene, pair, 0 if coarse else 1, factors, rule="helical")
    h_spur = None if coarse else harris(scene, near_spur_pair(pair), 0, factors, rule="spur")[0]
    h_spur_helical = None if coarse else harris(scene, near_spur_pair(pair), 0, factors, rule="helical")[0]
    disc = discretisation(scene, pair, 0 if coarse else 1)
    E, nu = scene.material.youngs_modulus, scene.material.poisson_ratio
    k_iso, record = iso6336_helix_stiffness(pair, E)
    iso = uniform_mesh_stiffness(pair, k_iso, "iso6336", 16, iso=record)
    pem = pem_mesh_stiffness(pair, E, nu, 64)
    out = {"convergence": conv, "body": body, "discretisation": disc, "harris": h, "harris_near_spur": h_spur,
           "harris_near_spur_helical_rule": h_spur_helical, "k_iso6336": iso.mean, "k_pem": pem.mean,
           "k_ltca": conv["rows"][-1]["k_mean"], "k_ltca_default": conv["rows"][0]["k_mean"],
           "level_default": conv["rows"][0]["level"], "level_finest": conv["rows"][-1]["level"], "design_p_max_GPa": float(design.p_max_left.max() / 1e9)}
    (ROOT / "out").mkdir(exist_ok=True)
    out["vtk"] = str(write_flank_pressure(ROOT / "out" / "ltca_pressure.vtu", design, pair,
                                          scene.material.youngs_modulus, scene.material.poisson_ratio))
    _plot([(out[k], t) for k, t in HARRIS_TITLES.items()], ROOT / "out" / "ltca_harris.png")
    (ROOT / "out" / "ltca_study.json").write_text(json.dumps(out, indent=1))
    return out


HARRIS_TITLES = {"harris": "baseline pair (β = 30°), helical rule C_a = w/c_γ",
                 "harris_near_spur": "near-spur pair (β = 1°), spur rule C_a = F_bt/(b c′)",
                 "harris_near_spur_helical_rule": "near-spur pair (β = 1°), helical rule C_a = w/c_γ"}


def _plot(maps, path):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from femgear.edge.io.figures import save_figure

    maps = [(h, t) for h, t in maps if h is not None]
    fig, axes = plt.subplots(1, len(maps), figsize=(6 * len(maps), 4), squeeze=False)
    for ax, (h, title) in zip(axes[0], maps):
        _harris_panel(ax, h, title)
    save_figure(fig, path)


def _print_harris(h, title):
    print(f"Harris map, {title} (ε_α {h['eps_alpha']:.2f}, ε_β {h['eps_beta']:.2f}): design {h['design_force']:.0f} N, "
          f"mean deflection {h['mean_deflection_um']:.2f} µm, single-pair {h['single_pair_deflection_um']:.2f} µm; "
          f"tip relief {h['tip_relief_um']:.2f} µm over {h['relief_length_mm']:.2f} mm → LTE p-p minimum at "
          f"{h['argmin_factor']:.2f} × design load; local minima at "
          + ", ".join(f"{f:.2f}" for f in h["local_minima_factors"]) + " ×; LTE p-p relieved / unmodified smallest at "
          f"{h['argmin_ratio_factor']:.2f} × design load")
    print(f"  relief minimising LTE p-p at the design load: {h['tip_relief_optimised_um']:.2f} µm → minimum at "
          f"{h['argmin_factor_optimised']:.2f} × design load")
    for f, p, po, p0 in zip(h["factors"], h["lte_pp_um"], h["lte_pp_optimised_um"], h["lte_pp_unmodified_um"]):
        print(f"  {f:5.2f} × design: LTE p-p {p:.4f} µm, optimised relief {po:.4f} µm (unmodified {p0:.4f} µm)")


def _harris_panel(ax, h, title):
    F = np.asarray(h["factors"]) * h["design_force"] / 1e3
    ax.plot(F, h["lte_pp_um"], "o-", label=f"tip relief {h['tip_relief_um']:.1f} µm, {h['relief_length_mm']:.1f} mm")
    ax.plot(F, h["lte_pp_optimised_um"], "^-", label=f"tip relief {h['tip_relief_optimised_um']:.1f} µm "
            "(p-p minimised at the design load)")
    ax.plot(F, h["lte_pp_unmodified_um"], "s--", label="unmodified")
    ax.axvline(h["design_force"] / 1e3, color="k", lw=0.8, ls=":", label="design load")
    ax.set_xlabel("normal force, both helices [kN]")
    ax.set_ylabel("LTE peak-to-peak [µm]")
    ax.set_title(f"Harris map (LTCA), {title}")
    ax.legend(fontsize=7)


def main(argv) -> None:
    out = run(coarse="--coarse" in argv)
    print("level  h_tooth[mm]  DOF pinion/gear   LTE p-p [µm]  LTE mean [µm]  k mean [N/m]")
    for r in out["convergence"]["rows"]:
        print(f"{r['level']:5d}  {r['h_tooth_mm']:10.3f}  {r['ndofs'][0]:7d}/{r['ndofs'][1]:<7d}  "
              f"{r['lte_pp_um']:12.4f}  {r['lte_mean_um']:13.4f}  {r['k_mean']:.4e}")
    c = out["convergence"]
    print(f"change between the two finest: LTE p-p {c.get('change_finest_lte_pp', float('nan')):.2%}, "
          f"k mean {c.get('change_finest_k_mean', float('nan')):.2%}; observed order (three finest) LTE p-p "
          f"{c.get('order_lte_pp_um', float('nan')):.2f}, k {c.get('order_k_mean', float('nan')):.2f}")
    for key, name in (("lte_pp_um", "LTE p-p"), ("k_mean", "k mean")):
        if f"extrapolated_{key}" in c:
            print(f"  {name}: Richardson-extrapolated {c[f'extrapolated_{key}']:.5g}; error per level "
                  + " ".join(f"L{r['level']} {e:+.2%}" for r, e in zip(c["rows"], c[f"default_error_{key}"])))
    b = out["body"]
    for name in ("no_cross", "clamp_rf_3mn", "fine_far_field"):
        print(f"body variant {name}: k mean {b[name]['k_mean']:.4e} ({b[name]['k_mean'] / b['default']['k_mean'] - 1:+.2%} "
              f"vs the default body), LTE p-p {b[name]['lte_pp_um']:.4f} µm "
              f"({b[name]['lte_pp_um'] / b['default']['lte_pp_um'] - 1:+.2%}), DOF {b[name]['ndofs']}")
    for m in (1, 2):
        c = b[f"member{m}_cross"]
        print(f"member {m} cross-helix kernel: max |cross| / max |same-helix| {c['max_cross_over_max_self']:.3f}, "
              f"mean |cross| / mean diagonal same-helix {c['mean_abs_cross_over_mean_diag_self']:.3f}")
    for name, d in out["discretisation"].items():
        print(f"{name}: LTE p-p {d['lte_pp_um']:.4f} µm, harmonics 1-5 [µm] " + " ".join(f"{x:.4f}" for x in d["harmonics_um"])
              + "; 128 vs 64 phases: harmonic change / largest " + " ".join(f"{x:.1e}" for x in d["phases_128_harmonics_change"])
              + f"; 32 vs 16 points per line: LTE p-p {d['points_32_lte_pp_change']:.2%}, k {d['points_32_k_change']:.2%}")
    for key, lv in (("k_ltca_default", out["level_default"]), ("k_ltca", out["level_finest"])):
        print(f"mean mesh stiffness (both helices, normal): LTCA level {lv} {out[key]:.4e}, ISO 6336 c_γα "
              f"{out['k_iso6336']:.4e} ({out[key] / out['k_iso6336'] - 1:+.1%}), PEM {out['k_pem']:.4e} "
              f"({out[key] / out['k_pem'] - 1:+.1%})")
    for key, title in HARRIS_TITLES.items():
        if out.get(key) is not None:
            _print_harris(out[key], title)
    print(f"design case p_max {out['design_p_max_GPa']:.2f} GPa; pressure map {out['vtk']}; PNG out/ltca_harris.png")
    print(json.dumps(out))


if __name__ == "__main__":
    main(sys.argv[1:])
