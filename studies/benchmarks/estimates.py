"""The memory and time estimates of the FE stages against what each stage then uses (issue 39 item 3).

    python studies/benchmarks/estimates.py [--pairs paper_baseline,fzg_a,...] [--stages fe,fe-thermal,fe3d,ltca]
                                           [--members 1,2] [--cap-gb 8]

For every zoo pair, FE stage and member: the stage's own :class:`femgear.perf.Estimate` (the one it
announces before it starts, from the same code), then the stage itself, cold (no cache), in a child
process of its own (``FEMGEAR_FORK=0``: the body is built in that process, so its ``getrusage`` peak is
the stage's; BLAS on one thread, as in ``femgear run``'s children).  Stages and what they run:

- ``fe``: the ``fe`` stiffness's section of the member (:class:`femgear.physics.body.compliance.ToothFE`, the
  scene's level) and its compliance at the level's 9 path positions;
- ``fe-thermal``: the ``thermal = "fe"`` section (:func:`femgear.physics.body.thermal.gear_thermo_elastic`);
- ``fe3d``: the ``thermal = "fe3d"`` body's two unit solutions (:func:`femgear.physics.ltca.thermal.thermal_units_3d`);
- ``ltca``: the ``ltca`` body's unit-load kernels (:func:`femgear.physics.ltca.compliance.member_compliance`,
  the scene's elements and level, 63 unit loads a loaded helix).

Columns: the estimate's memory and the measured peak resident memory (ratio measured/estimate), the
estimate's time and the CPU time of the child (ratio); the wall time beside it.  The estimates model an
unloaded machine: on a shared one compare the CPU time (the stages run on one core).  Prints a table and
one JSON line (written to ``out/benchmarks/estimates.json``).
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
PAIRS = ("paper_baseline", "fzg_a", "automotive_spur", "small_spur", "marine")
STAGES = ("fe", "fe-thermal", "fe3d", "ltca")


def _case(pair: str):
    from femgear.case import build_case
    from femgear.scene import load_scene

    return build_case(load_scene(ROOT / "studies" / "zoo" / f"{pair}.toml"))


def _fe(case, member: int):
    import numpy as np

    from femgear.physics.body.compliance import ToothFE

    p, m = case.pair, case.material
    u = np.linspace(p.u_start, p.u_end, 9)
    model = ToothFE(p, member, m.youngs_modulus, m.poisson_ratio, bore_radius=case.bore_radii[member - 1],
                    level=case.numerics.level_of("fe"), n_positions=u.size)
    for ui in u:
        model.compliance(ui)
    return model.estimate


def _fe_thermal(case, member: int):
    import femgear.physics.body.thermal as th

    seen, original = [], th.section_estimate

    def recorded(*args, **kwargs):           # the estimate the stage announces (it calls this function)
        seen.append(original(*args, **kwargs))
        return seen[-1]

    th.section_estimate = recorded
    try:
        m = case.material
        th.gear_thermo_elastic(case.pair, member, 1.0, 0.0, m.thermal_expansion, m.youngs_modulus, m.poisson_ratio,
                               m.conductivity, case.bore_radii[member - 1], case.thermal.mesh_size)
    finally:
        th.section_estimate = original
    return seen[0]


def _fe3d(case, member: int):
    from dataclasses import replace

    from femgear.physics.ltca.compliance import build_estimate
    from femgear.physics.ltca.thermal import body_spec, thermal_units_3d

    m, level = case.material, case.numerics.level_of("fe3d")
    spec = body_spec(case.pair, member, level, case.bore_radii[member - 1], case.groove_width, case.stagger)
    est = build_estimate(case.pair, member, spec, 1, 2)
    thermal_units_3d(case.pair, member, m.thermal_expansion, m.youngs_modulus, m.poisson_ratio,
                     case.bore_radii[member - 1], case.groove_width, case.stagger, level=level, cache=False)
    return replace(est, stage=est.stage.replace("LTCA", "fe3d thermal"))


def _ltca(case, member: int):
    from femgear.levels.stiffness import body_options, body_order
    from femgear.physics.ltca.compliance import build_estimate, member_compliance
    from femgear.physics.mesh.segment import default_spec

    body, m = body_options(case), case.material
    order = body_order(case.numerics.body_elements)
    spec = default_spec(case.pair, member, case.numerics.level_of("ltca"), r_bore=body["bore_radius"][member - 1],
                        groove=body["groove_width"], stagger=body["stagger"])
    est = build_estimate(case.pair, member, spec, order, 63 * (1 if case.stagger == 0 else 2))
    member_compliance(case.pair, member, spec, m.youngs_modulus, m.poisson_ratio, order=order, cache=False)
    return est


RUNNERS = {"fe": _fe, "fe-thermal": _fe_thermal, "fe3d": _fe3d, "ltca": _ltca}


def child(pair: str, stage: str, member: int) -> dict:
    """Run one stage in this process; its estimate and what it used (the libraries imported first: a user's
    run has them loaded before its FE stages start)."""
    import gmsh  # noqa: F401
    import pyamg  # noqa: F401
    import scipy.sparse.linalg  # noqa: F401
    import skfem  # noqa: F401

    import femgear.physics.body.mixed3d
    import femgear.physics.body.thermal
    import femgear.physics.ltca.thermal  # noqa: F401
    from femgear.physics.body.elastic3d import cholmod_backend

    cholmod_backend()
    case = _case(pair)
    before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024
    t, c = time.perf_counter(), time.process_time()
    est = RUNNERS[stage](case, member)
    wall, cpu = time.perf_counter() - t, time.process_time() - c
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024
    return {"pair": pair, "stage": stage, "member": member, "estimate": est.stage, "dofs": est.dofs,
            "est_GiB": est.memory_bytes / 2**30, "peak_GiB": peak / 2**30, "start_GiB": before / 2**30,
            "est_s": est.seconds, "cpu_s": cpu, "wall_s": wall}


def measure(pair: str, stage: str, member: int, cap_gb: float) -> dict:
    env = {**os.environ, "FEMGEAR_FORK": "0", "OPENBLAS_NUM_THREADS": "1", "OMP_NUM_THREADS": "1"}
    code = (f"import json, resource; resource.setrlimit(resource.RLIMIT_AS, ({int(cap_gb * 2**30)}, "
            f"{int(cap_gb * 2**30)})); import sys; sys.path.insert(0, {str(ROOT)!r}); "
            f"from studies.benchmarks.estimates import child; print(json.dumps(child({pair!r}, {stage!r}, {member})))")
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, cwd=ROOT)
    if run.returncode != 0:
        return {"pair": pair, "stage": stage, "member": member, "error": (run.stderr.strip().splitlines() or ["?"])[-1]}
    return json.loads(run.stdout.strip().splitlines()[-1])


def table(rows: list[dict]) -> str:
    lines = ["| pair | stage | member | DOF | estimate [GiB] | peak [GiB] | ratio | estimate [s] | CPU [s] | ratio | wall [s] |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        if "error" in r:
            lines.append(f"| {r['pair']} | {r['stage']} | {r['member']} | failed: {r['error']} |||||||")
            continue
        lines.append(f"| {r['pair']} | {r['stage']} | {r['member']} | {r['dofs'] / 1e3:.0f} k | {r['est_GiB']:.2f} | "
                     f"{r['peak_GiB']:.2f} | {r['peak_GiB'] / r['est_GiB']:.2f} | {r['est_s']:.1f} | {r['cpu_s']:.1f} | "
                     f"{r['cpu_s'] / max(r['est_s'], 1e-9):.2f} | {r['wall_s']:.1f} |")
    return "\n".join(lines)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--pairs", default=",".join(PAIRS))
    ap.add_argument("--stages", default=",".join(STAGES))
    ap.add_argument("--members", default="1,2")
    ap.add_argument("--cap-gb", type=float, default=8.0, help="address-space cap of each child [GiB]")
    args = ap.parse_args(argv)
    rows = []
    for pair in args.pairs.split(","):
        for stage in args.stages.split(","):
            for member in (int(m) for m in args.members.split(",")):
                rows.append(measure(pair, stage, member, args.cap_gb))
                print(table(rows[-1:]).splitlines()[-1], flush=True)
    print(table(rows))
    out = ROOT / "out" / "benchmarks"
    out.mkdir(parents=True, exist_ok=True)
    (out / "estimates.json").write_text(json.dumps(rows, indent=1))
    print(json.dumps(rows))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
