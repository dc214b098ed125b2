"""P1 or P2 tetrahedra for the LTCA flank kernels: one measurement, both orders, several meshes.

    python studies/ltca/ltca_element_order.py [--quick | --ltca | --split [--max-p1-level N] [--max-p2-level N]]

All on the member bodies of the baseline scene (:func:`femgear.physics.mesh.segment.member_body`: both
helices, the groove, the rim down to the scene's bore, :func:`femgear.physics.ltca.analysis.body_options`).
For the baseline pinion, a 3 × 3 flank grid (hat loads of 1 N): the FE approach at the
reading depth under the mid-flank, mid-face load (``fe_self``) and its half-space-free bulk
part, with DOFs and wall time, for P1 at segment levels 0–3 and P2 at levels 0–1
(``--quick``: P1 0–1, P2 0).  Prints a table and a JSON line (out/ltca_element_order.json).
``--ltca``: the LTCA outputs themselves for P1 (levels 1, 3) and P2 (level 0), see :func:`run_ltca`.
``--split``: one mid-flank unit load, read at several depths d: the FE approach, its half-space
part and the bulk (their difference), P1 levels 0–5 and P2 levels 0–1 (:func:`run_split`, ~15 min on the
bodies; ``--max-p1-level`` / ``--max-p2-level`` cut the lists).
"""

from __future__ import annotations

import json
import os
import sys
import tempfile
import time
from pathlib import Path

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
ROOT = Path(__file__).resolve().parents[2]


def setup():
    from femgear.physics.geometry.gear import GearPair
    from femgear.scene import load_scene

    scene = load_scene(ROOT / "studies" / "paper_baseline.toml")
    return scene, GearPair.from_scene(scene)


def _pinion_spec(scene, pair, level: int):
    """The pinion body of the scene at ``level`` (bore, groove and stagger as the LTCA builds it)."""
    from femgear.physics.ltca.analysis import body_options
    from femgear.physics.mesh.segment import default_spec

    body = body_options(scene)
    return default_spec(pair, 1, level, r_bore=body["bore_radius"][0], groove=body["groove_width"],
                        stagger=body["stagger"])


def run(quick: bool = False) -> list[dict]:
    from femgear.physics.ltca.compliance import member_compliance

    scene, pair = setup()
    cases = [(1, 0), (1, 1)] + ([] if quick else [(1, 2), (1, 3)]) + [(2, 0)] + ([] if quick else [(2, 1)])
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        os.environ["FEMGEAR_CACHE"] = tmp
        for order, level in cases:
            t0 = time.perf_counter()
            spec = _pinion_spec(scene, pair, level)
            c = member_compliance(pair, 1, spec, scene.material.youngs_modulus,
                                  scene.material.poisson_ratio, order=order, n_rho=3, n_z=3, cache=False)
            rows.append({"order": order, "level": level, "h_tooth_mm": spec.h_tooth * 1e3,
                         "ndofs": int(c.ndofs), "fe_self_mid": float(c.fe_self[4, 4]),
                         "bulk_mid": float(c.bulk[list(c.offsets).index(0)][4, 4]),
                         "asymmetry": c.info["asymmetry"], "seconds": time.perf_counter() - t0,
                         "solve_seconds_per_load": c.info["solve_seconds"] / c.info["solves"]})
    return rows


def run_ltca() -> list[dict]:
    """The LTCA outputs (mean stiffness, LTE p-p and mean; 5 × 7 grid, 64 phases, 200 N m) for P1 at levels 1
    and 3 and P2 at level 0 (the P2 build takes ~12 min on 2 shared cores)."""
    from femgear.physics.ltca.analysis import body_options, build_model, mesh_cycle, normal_force

    scene, pair = setup()
    F = normal_force(pair, scene.operating.torque, scene.operating.driver)
    rows = []
    for order, level in ((1, 1), (1, 3), (2, 0)):
        t0 = time.perf_counter()
        m = build_model(pair, scene.material.youngs_modulus, scene.material.poisson_ratio, level=level, order=order,
                        n_rho=5, n_z=7, **body_options(scene))
        r = mesh_cycle(m, F, None, n_phases=64, keep_lines=False)
        rows.append({"order": order, "level": level, "build_s": time.perf_counter() - t0,
                     "ndofs": [int(m.kernels[k].ndofs) for k in (1, 2)], "lte_pp_um": r.lte_peak_to_peak() * 1e6,
                     "lte_mean_um": float(r.lte.mean() * 1e6), "k_mean": r.mean_stiffness()})
    return rows


SPLIT_DEPTHS_MM = (0.5, 0.7, 0.9, 1.2)


def run_split(max_p1: int = 5, max_p2: int = 1) -> list[dict]:
    """FE − half-space split for the mid node of a 7 × 9 flank grid of the baseline pinion, one solve per mesh.

    With a converged FE the bulk (FE minus half-space at the same depth) should not depend on the
    reading depth d (the local part is the half-space's); d is clipped to half the half tooth thickness.
    """
    import numpy as np

    from femgear.physics.body.elastic3d import Elastic3D
    from femgear.physics.ltca.compliance import flank_unit_loads, halfspace_reading, reading_points
    from femgear.physics.ltca.flank import half_thickness, roll_range
    from femgear.physics.mesh.segment import member_body

    scene, pair = setup()
    E, nu = scene.material.youngs_modulus, scene.material.poisson_ratio
    r0, r1 = roll_range(pair, 1)
    gr, gz = np.linspace(r0, r1, 7), np.linspace(0.0, pair.b, 9)
    rho, z = np.array([gr[3]]), np.array([gz[4]])
    rows = []
    for order, level in [(1, lv) for lv in range(max_p1 + 1)] + [(2, lv) for lv in range(max_p2 + 1)]:
        t0 = time.perf_counter()
        model = Elastic3D(member_body(pair, 1, _pinion_spec(scene, pair, level)), E, nu, order=order)
        loads, xq, weights = flank_unit_loads(pair, 1, model, gr, gz)
        u = model.solve(loads[3 * 9 + 4])
        row = {"order": order, "level": level, "ndofs": int(model.basis.N), "fe": [], "hs": [], "bulk": []}
        for d in SPLIT_DEPTHS_MM:
            x, n = reading_points(pair, 1, rho, z, np.minimum(d * 1e-3, 0.5 * half_thickness(pair, 1, rho)))
            fe = -float(np.sum(np.vstack([M @ u for M in model.probe_matrices(x)]) * n))
            hs = float(halfspace_reading(x, n, xq, weights[3 * 9 + 4], E, nu)[0])
            row["fe"].append(fe), row["hs"].append(hs), row["bulk"].append(fe - hs)
        row["seconds"] = time.perf_counter() - t0
        rows.append(row)
    return rows


def main(argv) -> None:
    if "--split" in argv:
        def _opt(name, default):
            return int(argv[argv.index(name) + 1]) if name in argv else default
        rows = run_split(_opt("--max-p1-level", 5), _opt("--max-p2-level", 1))
        print("order level   DOF    bulk = FE − half-space at d = " + " / ".join(f"{d} mm" for d in SPLIT_DEPTHS_MM)
              + " [1e-10 m/N]   (FE at the last depth)")
        for r in rows:
            print(f"P{r['order']}  {r['level']:4d} {r['ndofs']:7d}   " + " / ".join(f"{b * 1e10:.3f}" for b in r["bulk"])
                  + f"   ({r['fe'][-1] * 1e10:.3f})  {r['seconds']:.0f} s")
        print(json.dumps(rows))
        return
    if "--ltca" in argv:
        rows = run_ltca()
        print("order level  DOF pinion/gear  build [s]  k mean [N/m]  LTE p-p [µm]  LTE mean [µm]")
        for r in rows:
            print(f"P{r['order']}  {r['level']:4d}  {r['ndofs'][0]:7d}/{r['ndofs'][1]:<7d} {r['build_s']:8.0f}  "
                  f"{r['k_mean']:.4e}  {r['lte_pp_um']:12.4f}  {r['lte_mean_um']:12.4f}")
        print(json.dumps(rows))
        return
    rows = run("--quick" in argv)
    print("order level h_tooth[mm]   DOF   FE at depth [m/N]  bulk [m/N]  asym   s/load  total s")
    for r in rows:
        print(f"P{r['order']}  {r['level']:4d}  {r['h_tooth_mm']:9.3f}  {r['ndofs']:7d}  {r['fe_self_mid']:.4e}  "
              f"{r['bulk_mid']:.4e}  {r['asymmetry']:.3f}  {r['solve_seconds_per_load']:6.2f}  {r['seconds']:7.1f}")
    out = ROOT / "out" / "ltca_element_order.json"
    out.parent.mkdir(exist_ok=True)
    out.write_text(json.dumps(rows, indent=1))
    print(json.dumps(rows))


if __name__ == "__main__":
    main(sys.argv[1:])
