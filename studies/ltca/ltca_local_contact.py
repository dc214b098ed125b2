"""The LTCA's mean mesh stiffness against 2-D plane-strain FE references of the same bodies: the local contact and
the coupling of the teeth through the body.

    python studies/ltca/ltca_local_contact.py [SCENE] [--set KEY=VALUE ...] [--n-fe 9] [--phases 16] [--ltca]

Issue 37: the industrial single-helical stage's LTCA (1.412e9 N/m) sits 15 % below PEM and 20 % below the ``fe``
level.  The ``pem`` and ``fe`` levels are slice models: each tooth pair a spring k'(u) of its own, the springs
in parallel, the pair's local contact flattening added as the load-independent Yang & Lin (1987) term
4(1−ν²)/(π E) per unit face width.  Two independent references, each member's whole transverse section (P2, plane
strain, the bore clamped where the LTCA body is clamped, :func:`femgear.levels.stiffness.body_options`), meshed
down to a/``--contact-elements`` at the contact point and loaded there by the Hertz pressure
p(s) = p_H √(1 − s²/a²) (a = b_H/cos β_b in the section):

(:mod:`femgear.physics.ltca.reference2d`):

- *slices*: at ``--n-fe`` path positions one tooth pair under the mean line load F_n/L; the pair's approach is the
  sum of the two surface points' displacements along the load (no contact formula, no split), the same reading
  averaged over the tooth section through the contact point is the ``fe`` level's; beside it the Weber &
  Banaschek approach of two cylinders from the tooth centre lines,
  2(1−ν²)/(πE) [ln(2h₁/a) + ln(2h₂/a) − ν/(1−ν)] (Weber & Banaschek, Formänderung und Profilrücknahme bei gerad-
  und schrägverzahnten Rädern, Vieweg 1953; h_i the distances from the contact point to the centre lines along
  the load).  k'(u) integrated over the contact lines as the ``fe`` level does
  (:func:`femgear.physics.stiffness.tvms.integrated_mesh_stiffness`).
- *coupled*: at ``--phases`` transverse phases every tooth pair in contact loaded at once in the same sections
  (a load on one tooth read on the others: the body's coupling, which the slice levels leave out), the load
  shared so that all have one approach; its ratio to the same teeth uncoupled (the matrix's diagonal) times the
  slice reference is the coupled slice model's mean stiffness (for a spur pair the 2-D solution itself; for a
  helical pair the slices of the transverse section, uncoupled across the face).

``--ltca``: the LTCA's mean stiffness of the scene's bodies (the level's, from the disk cache) and the same with
its tooth-to-tooth kernels (offsets ≠ 0) dropped, at the same phases.  Prints the tables, the means and a JSON
line.
"""

from __future__ import annotations

import argparse
import json
import math
from pathlib import Path

import numpy as np

try:
    from studies import _common as C
except ImportError:
    import sys

    sys.path.insert(0, str(Path(__file__).resolve().parents[2]))
    from studies import _common as C

ROOT = Path(__file__).resolve().parents[2]


def slice_table(pair, E: float, nu: float, bores, w: float, n_fe: int, h: float, per_width: float) -> dict:
    """The *slices* reference: per path position the pair's surface and section approach per unit line load and the
    Weber–Banaschek and Yang–Lin local terms [m/N · m]; the mean mesh stiffnesses of each [N/m]."""
    from femgear.physics.ltca.reference2d import pair_compliance, section_width, weber_banaschek
    from femgear.physics.stiffness import integrated_mesh_stiffness
    from femgear.physics.stiffness.pem import hertz_compliance
    from femgear.physics.stiffness.tvms import path_samples, tabulated

    u = np.linspace(pair.u_start, pair.u_end, n_fe)
    rows = []
    for ui in u:
        surface, section = pair_compliance(pair, float(ui), E, nu, bores, w, h, per_width)
        a = section_width(pair, float(ui), w, E, nu)
        rows.append({"u": float(ui), "b_H": a * math.cos(pair.beta_b), "surface": surface, "section": section,
                     "weber_banaschek": weber_banaschek(pair, float(ui), a, E, nu)})
    grid = path_samples(pair)

    def mean(c):
        k = tabulated(pair, u, 1.0 / np.asarray(c))(grid)
        return float(np.mean(integrated_mesh_stiffness(pair, grid, k, "reference").k_total))

    col = {k: np.array([r[k] for r in rows]) for k in ("surface", "section", "weber_banaschek")}
    yang_lin = hertz_compliance(E, nu)
    return {"rows": rows, "yang_lin": yang_lin, "direct": mean(col["surface"]),
            "section_yang_lin": mean(col["section"] + yang_lin),
            "section_weber_banaschek": mean(col["section"] + col["weber_banaschek"])}


def coupled_cycle(pair, E: float, nu: float, bores, w: float, n_phases: int, h: float, per_width: float) -> dict:
    """The *coupled* reference over ``n_phases`` transverse phases: the stiffness of the teeth in contact, coupled
    and uncoupled, and the ratio of their cycle means."""
    from femgear.physics.ltca.reference2d import coupled_stiffness, transverse_points

    coupled, alone = [], []
    for phase in np.arange(n_phases) / n_phases:
        u, teeth = transverse_points(pair, phase)
        kc, ku = coupled_stiffness(pair, u, teeth, w * u.size, E, nu, bores, h, per_width)   # each pair near w
        coupled.append(kc), alone.append(ku)
    return {"coupled": coupled, "uncoupled": alone, "ratio": float(np.mean(coupled) / np.mean(alone))}


def ltca_means(case, n_phases: int) -> dict:
    """The LTCA's mean stiffness of ``case``'s bodies (the ``ltca`` level's, disk-cached) at ``n_phases`` phases,
    with and without its tooth-to-tooth kernels (offsets ≠ 0) [N/m]."""
    import dataclasses

    from femgear.levels.stiffness import body_options, body_order
    from femgear.physics.ltca.analysis import build_model, mesh_cycle

    mat = case.material
    body = {k: v for k, v in body_options(case).items() if k != "stagger"}
    model = build_model(case.pair, mat.youngs_modulus, mat.poisson_ratio, level=case.numerics.level_of("ltca"),
                        order=body_order(case.numerics.body_elements), stagger=case.stagger, **body)

    def own_tooth(k):
        keep = (k.offsets == 0)[:, None, None]
        return dataclasses.replace(k, bulk=k.bulk * keep, cross=None if k.cross is None else k.cross * keep)

    out = {}
    for name, kernels in (("ltca", model.kernels), ("ltca_own_tooth", {m: own_tooth(k) for m, k in model.kernels.items()})):
        out[name] = mesh_cycle(dataclasses.replace(model, kernels=kernels), case.operating.normal_force,
                               n_phases=n_phases, stagger=case.stagger, keep_lines=False).mean_stiffness()
    return out


NAMES = {"direct": "slices, at the surface (the Hertz pressure itself)",
         "section_yang_lin": "slices, section + Yang-Lin (the fe level's reading)",
         "section_weber_banaschek": "slices, section + Weber-Banaschek", "coupled_slices": "coupled slices",
         "pem": "pem level (its own bores)", "fe": "fe level (its own bores)", "ltca": "ltca (32 phases)",
         "ltca_own_tooth": "ltca without the tooth-to-tooth kernels"}


def setup(argv=None) -> dict:
    """The options of :func:`run` from the command line."""
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("scene", nargs="?", default=str(ROOT / "studies" / "zoo" / "industrial.toml"))
    ap.add_argument("--set", action="append", default=[], dest="overrides", help="scene override KEY=VALUE (repeatable)")
    ap.add_argument("--n-fe", type=int, default=9, help="path positions of the slice reference")
    ap.add_argument("--phases", type=int, default=16, help="transverse phases of the coupled reference (0: none)")
    ap.add_argument("--level", type=int, default=1, help="element size m_n/(3 + level) on the teeth")
    ap.add_argument("--contact-elements", type=float, default=4.0, help="elements across the Hertz half-width")
    ap.add_argument("--ltca", action="store_true", help="the LTCA's means too (its bodies, disk-cached)")
    ap.add_argument("--coarse", action="store_true", help="5 slice positions, 4 phases")
    return vars(ap.parse_args(argv))


def run(coarse: bool = False, scene: str = str(ROOT / "studies" / "zoo" / "industrial.toml"), overrides=(),
        n_fe: int = 9, phases: int = 16, level: int = 1, contact_elements: float = 4.0, ltca: bool = False) -> dict:
    """The references (and with ``ltca`` the LTCA's means) of ``scene``; ``coarse``: 5 positions, 4 phases."""
    from femgear.case import build_case
    from femgear.levels import stiffness as levels
    from femgear.levels.stiffness import body_options
    from femgear.scene import load_scene

    if coarse:
        n_fe, phases = min(n_fe, 5), min(phases, 4)
    case = build_case(load_scene(Path(scene), list(overrides)))
    pair, mat = case.pair, case.material
    E, nu = mat.youngs_modulus, mat.poisson_ratio
    bores = body_options(case)["bore_radius"]
    h = pair.m_n / (3 + level)
    w = case.operating.normal_force / (pair.n_helices * pair.b * pair.eps_alpha / math.cos(pair.beta_b))
    out = {"scene": Path(scene).stem, "set": list(overrides), "bores": list(bores), "w": w, "level": level,
           "contact_elements": contact_elements}
    out.update(slice_table(pair, E, nu, bores, w, n_fe, h, contact_elements))
    if phases:
        out.update(coupled_cycle(pair, E, nu, bores, w, phases, h, contact_elements))
        out["coupled_slices"] = out["direct"] * out["ratio"]
    out["pem"] = float(np.mean(levels.of(case, "pem").k_total))
    out["fe"] = float(np.mean(levels.of(case, "fe").k_total))
    if ltca:
        out.update(ltca_means(case, 32))
    return out


def main(argv=None) -> dict:
    out = run(**setup(argv))
    bores = out["bores"]
    print(f"{out['scene']} {' '.join(out['set'])}: bores {bores[0] * 1e3:.2f} / {bores[1] * 1e3:.2f} mm, "
          f"mean line load {out['w']:.4g} N/m; per unit line load [m/N·m]:")
    for r in out["rows"]:
        print(f"  u {r['u'] * 1e3:7.3f} mm  b_H {r['b_H'] * 1e3:.4f} mm  surface {r['surface']:.4e}  section "
              f"{r['section']:.4e}  local {r['surface'] - r['section']:.4e}  Weber-Banaschek {r['weber_banaschek']:.4e}"
              f"  Yang-Lin {out['yang_lin']:.4e}")
    if "ratio" in out:
        print(f"coupled / uncoupled teeth in the sections, cycle means: {out['ratio']:.4f}")
    for key, name in NAMES.items():
        if key in out:
            print(f"mean mesh stiffness, {name}: {out[key]:.4e} N/m")
    C.write_results("ltca_local_contact", out)
    print(json.dumps(C.jsonable(out)))
    return out


if __name__ == "__main__":
    main()
