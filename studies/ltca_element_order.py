"""P1 or P2 tetrahedra for the LTCA flank kernels: one measurement, both orders, several meshes.

    python studies/ltca_element_order.py [--quick]

For the baseline pinion, a 3 × 3 flank grid (hat loads of 1 N): the FE approach at the
reading depth under the mid-flank, mid-face load (``fe_self``) and its half-space-free bulk
part, with DOFs and wall time, for P1 at segment levels 0–3 and P2 at levels 0–1
(``--quick``: P1 0–1, P2 0).  Prints a table and a JSON line (out/ltca_element_order.json).
"""

from __future__ import annotations

import json
import os
import sys
import tempfile
import time
from pathlib import Path

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
ROOT = Path(__file__).resolve().parents[1]


def run(quick: bool = False) -> list[dict]:
    from femgear.geometry.gear import GearPair
    from femgear.ltca.compliance import member_compliance
    from femgear.mesh.segment import default_spec
    from femgear.scene import load_scene

    scene = load_scene(ROOT / "studies" / "paper_baseline.toml")
    pair = GearPair.from_scene(scene)
    cases = [(1, 0), (1, 1)] + ([] if quick else [(1, 2), (1, 3)]) + [(2, 0)] + ([] if quick else [(2, 1)])
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        os.environ["FEMGEAR_CACHE"] = tmp
        for order, level in cases:
            t0 = time.perf_counter()
            c = member_compliance(pair, 1, default_spec(pair, 1, level), scene.material.youngs_modulus,
                                  scene.material.poisson_ratio, order=order, n_rho=3, n_z=3, cache=False)
            rows.append({"order": order, "level": level, "h_tooth_mm": default_spec(pair, 1, level).h_tooth * 1e3,
                         "ndofs": int(c.ndofs), "fe_self_mid": float(c.fe_self[4, 4]),
                         "bulk_mid": float(c.bulk[list(c.offsets).index(0)][4, 4]),
                         "asymmetry": c.info["asymmetry"], "seconds": time.perf_counter() - t0,
                         "solve_seconds_per_load": c.info["solve_seconds"] / c.info["solves"]})
    return rows


def main(argv) -> None:
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
