"""The rating table of docs/rating.md: ISO safety factors beside femgear's own figures, one table per pair.

Covers every scene under studies/zoo/ (globbed, so new zoo scenes join by themselves), plus the
paper's baseline and the FZG C test gear where the zoo has no copy of them.  Run from the repository root:

    PYTHONPATH=$PWD python studies/validation/rating_table.py            # ~10 s per pair
    PYTHONPATH=$PWD python studies/validation/rating_table.py --fillet   # + the FE fillet stress (~20–40 s per pair)

Prints Markdown and writes it to out/rating_table.md (and out/rating_table.json).
"""

from __future__ import annotations

import argparse
import json
import math
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def setup() -> list[Path]:
    """Every zoo scene, plus the paper's baseline and FZG C14 where the zoo has no copy of them."""
    zoo = sorted((ROOT / "studies" / "zoo").glob("*.toml"))
    extra = [ROOT / "studies" / name for name in ("paper_baseline.toml", "fzg_c14.toml")
             if name not in {p.name for p in zoo}]
    return extra + zoo


#: the load factors of the ratings before issue 42 (K_v = K_Hβ = K_Hα = 1 unless the scene gave them)
UNIT_FACTORS = ["rating.dynamic_factor=1.0", "rating.face_load_factor=1.0", "rating.transverse_load_factor=1.0"]


def rate(path: Path, fillet: bool, overrides=()):
    from femgear.case import build_case
    from femgear.levels.contact import contact_pass
    from femgear.physics.contact.path import zone_grid
    from femgear.rate import rate_case
    from femgear.scene import load_scene

    scene = load_scene(path, (["rating.fillet_fe=true"] if fillet else []) + list(overrides))
    case = build_case(scene)
    pair = case.pair
    contact = contact_pass(case, u=zone_grid(pair, scene.numerics.path_points))
    return scene, pair, rate_case(case, contact)


def table(scene, pair, r, unit=None) -> tuple[str, dict]:
    """The pair's Markdown table; ``unit``: the same rating with K_v = K_Hβ = K_Hα = 1 (its S_H, S_F beside)."""
    c = 273.15
    b, s, m, own = r.bending, r.scuffing, r.micropitting, r.own
    f = r.factors
    rows = [
        ("K_v, K_Hβ, K_Hα (ISO 6336-1 B, C, B; grade " f"{f.tolerances.grade})",
         f"{f.K_v.value:.3f}, {f.K_Hbeta.value:.3f}, {f.K_Halpha.value:.3f}",
         "femgear's with its dynamics and LTCA: `femgear run`, results.json `load_factors`"),
        ("S_H (pinion / gear), ISO 6336-2", f"{r.pitting.S_H[0]:.2f} / {r.pitting.S_H[1]:.2f}",
         "" if unit is None else f"K_v = K_Hβ = K_Hα = 1: {unit.pitting.S_H[0]:.2f} / {unit.pitting.S_H[1]:.2f}"),
        ("S_F (pinion / gear), ISO 6336-3 B", f"{b.S_F[0]:.2f} / {b.S_F[1]:.2f}",
         "" if unit is None else f"K_v = K_Hβ = K_Hα = 1: {unit.bending.S_F[0]:.2f} / {unit.bending.S_F[1]:.2f}"),
        ("σ_F0 [MPa] (pinion / gear)", f"{b.sigma_F0[0] / 1e6:.0f} / {b.sigma_F0[1] / 1e6:.0f}",
         "" if own.fillet is None else "FE fillet σ_1: " + " / ".join(
             f"{f.max_principal / 1e6:.0f} ({f.max_principal / s0:.2f} σ_F0, {math.degrees(f.tangent_angle):.0f}°)"
             for f, s0 in zip(own.fillet, b.sigma_F0, strict=True))),
        ("max contact temperature [°C]", f"{s.max_contact_temperature - c:.0f} (θ_M {s.theta_M - c:.0f} + "
         f"θ_fl,max {max(s.path.flash):.0f})", f"{own.max_temperature - c:.0f} ({own.temperature_level}: "
         f"θ_oil + ΔT_flash)"),
        ("scuffing temperature θ_S [°C] (FZG stage)", f"{s.theta_S - c:.0f} ({s.fzg_stage:g})", ""),
        ("S_B, ISO/TS 6336-20", f"{s.S_B:.2f}", ""),
        ("θ_int / θ_intS [°C], S_intS, ISO/TS 6336-21", f"{s.theta_int - c:.0f} / {s.theta_intS - c:.0f}, "
         f"{s.S_intS:.2f}", ""),
        ("min film [µm]", f"{min(m.film) * 1e6:.3f} (h_Y, θ_M {m.theta_M - c:.0f} °C)",
         f"{min(own.film) * 1e6:.3f} (Dowson–Higginson h_min at θ_oil)"),
        ("λ_min", f"{m.lambda_GFmin:.3f} (λ_GFP {m.lambda_GFP:.3f}, GF stage {m.stage:g})", f"{own.lambda_min:.3f}"),
        ("S_λ, ISO/TS 6336-22 B", f"{m.S_lambda:.2f}", ""),
    ]
    head = (f"### {scene.meta.name} ({pair.kind}, m_n {pair.m_n * 1e3:g} mm, z {pair.z1}/{pair.z2}, "
            f"β {math.degrees(pair.beta):.1f}°, T1 {scene.operating.torque:g} N m, "
            f"{scene.operating.speed_rpm:g} rpm, oil {scene.operating.ambient_temperature - c:.0f} °C)\n\n")
    md = head + "| figure | ISO | femgear |\n|---|---|---|\n" + "".join(f"| {a} | {i} | {f} |\n" for a, i, f in rows)
    if r.flags:
        md += "\nFlagged: " + "; ".join(r.flags) + "\n"
    if r.defaults:
        md += "\nDefaults: " + ", ".join(r.defaults) + "\n"
    data = {"scene": scene.meta.name, **r.safety_factors, "K_v": f.K_v.value, "K_Hbeta": f.K_Hbeta.value,
            "K_Halpha": f.K_Halpha.value, "S_F_members": list(b.S_F), "S_H_members": list(r.pitting.S_H),
            "iso_max_contact_temperature": s.max_contact_temperature, "femgear_max_contact_temperature": own.max_temperature,
            "iso_lambda_min": m.lambda_GFmin, "femgear_lambda_min": own.lambda_min, "flags": list(r.flags)}
    return md, data


def run(fillet: bool = False) -> tuple[str, list[dict]]:
    parts, rows = [], []
    for path in setup():
        md, data = table(*rate(path, fillet), unit=rate(path, False, UNIT_FACTORS)[2])
        parts.append(md)
        rows.append(data)
    return "\n".join(parts), rows


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--fillet", action="store_true", help="also solve the FE fillet stress")
    args = ap.parse_args(argv)
    md, rows = run(args.fillet)
    print(md)
    out = ROOT / "out"
    out.mkdir(exist_ok=True)
    (out / "rating_table.md").write_text(md)
    (out / "rating_table.json").write_text(json.dumps(rows, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
