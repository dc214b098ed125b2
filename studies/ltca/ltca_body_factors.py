"""The LTCA's mean mesh stiffness of a pair, one body or contact factor at a time.

    python studies/ltca/ltca_body_factors.py [SCENE] [--set KEY=VALUE ...] [--only NAME ...]

Issue 37: is the single-helical LTCA's gap to PEM and FE a discretisation of its bodies?  Beside the default (the
``ltca`` level's bodies: ``numerics.body_level`` and ``numerics.body_elements``, five teeth on a whole ring, the
reading depth 0.4 m_n, 16 points per contact line; unmodified flanks, 32 phases) each row changes one thing: the
teeth of the body (7), the reading depth of the FE/half-space split (0.25 and 0.6 m_n), the points per contact line
(32), the body level (+2).  Each changed body is built once into the disk cache (``$FEMGEAR_CACHE``; 1–3 min a
member for the industrial stage's p2-bending bodies, ≤ 3.4 GB).  Prints one line per row and a JSON line.
"""

from __future__ import annotations

import argparse
import json
import time
from pathlib import Path

try:
    from studies import _common as C
except ImportError:
    import sys

    sys.path.insert(0, str(Path(__file__).resolve().parents[2]))
    from studies import _common as C

ROOT = Path(__file__).resolve().parents[2]
ROWS = ("default", "teeth 7", "depth 0.25", "depth 0.6", "points 32", "level +2")


def row_model(case, name: str):
    """The :class:`femgear.physics.ltca.analysis.LTCAModel` of row ``name`` (bodies from the disk cache)."""
    from femgear.levels.stiffness import body_options, body_order
    from femgear.physics.ltca.analysis import LTCAModel
    from femgear.physics.ltca.compliance import member_compliance
    from femgear.physics.mesh.segment import default_spec

    pair, mat = case.pair, case.material
    body = body_options(case)
    level = case.numerics.level_of("ltca") + (2 if name == "level +2" else 0)
    teeth = 7 if name == "teeth 7" else 5
    depth = float(name.split()[1]) * pair.m_n if name.startswith("depth") else None
    t0 = time.perf_counter()
    kernels = {m: member_compliance(pair, m, default_spec(pair, m, level, n_teeth=teeth, r_bore=body["bore_radius"][m - 1],
                                                          groove=body["groove_width"], stagger=body["stagger"]),
                                    mat.youngs_modulus, mat.poisson_ratio, order=body_order(case.numerics.body_elements),
                                    depth=depth)
               for m in (1, 2)}
    return LTCAModel(pair, mat.youngs_modulus, mat.poisson_ratio, kernels, level, time.perf_counter() - t0,
                     body["stagger"])


def setup(argv=None) -> dict:
    """The options of :func:`run` from the command line."""
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("scene", nargs="?", default=str(ROOT / "studies" / "zoo" / "industrial.toml"))
    ap.add_argument("--set", action="append", default=[], dest="overrides", help="scene override KEY=VALUE (repeatable)")
    ap.add_argument("--only", action="append", choices=ROWS, dest="rows", help="rows to run (repeatable; default all)")
    return vars(ap.parse_args(argv))


def run(coarse: bool = False, scene: str = str(ROOT / "studies" / "zoo" / "industrial.toml"), overrides=(),
        rows=None) -> dict:
    """Each row's mean stiffness [N/m]; ``coarse``: the default and the points-per-line rows (no new body)."""
    from femgear.case import build_case
    from femgear.physics.ltca.analysis import mesh_cycle
    from femgear.scene import load_scene

    case = build_case(load_scene(Path(scene), list(overrides)))
    out = {"scene": Path(scene).stem, "set": list(overrides), "rows": {}}
    for name in rows or (ROWS[::4] if coarse else ROWS):
        model = row_model(case, name)
        res = mesh_cycle(model, case.operating.normal_force, n_phases=32, stagger=model.stagger,
                         n_line=32 if name == "points 32" else 16, keep_lines=False)
        out["rows"][name] = {"k_mean": res.mean_stiffness(), "dofs": [int(c.ndofs) for c in model.kernels.values()],
                             "build_seconds": model.seconds}
    return out


def main(argv=None) -> dict:
    out = run(**setup(argv))
    ref = out["rows"].get("default", {}).get("k_mean")
    for name, row in out["rows"].items():
        change = f" ({100 * (row['k_mean'] / ref - 1):+.2f} %)" if ref and name != "default" else ""
        print(f"{name:12s} k mean {row['k_mean']:.4e} N/m{change}  DOF {row['dofs']}  bodies {row['build_seconds']:.0f} s")
    C.write_results("ltca_body_factors", out)
    print(json.dumps(C.jsonable(out)))
    return out


if __name__ == "__main__":
    main()
