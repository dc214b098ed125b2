"""The speed–accuracy trade of every sub-model with levels, measured against a fine reference.

    python studies/validation/speed_accuracy.py [--quick] [--readme]

For each sub-model every level/resolution is run on the baseline scene and compared
with the finest one run here (the reference row, error 0): wall time (median of
``repeats``), peak traced memory and the error defined per sub-model below.  Writes
``out/speed_accuracy/rows.json``, one Pareto plot per sub-model (PNG), prints the table
and a JSON line, and with ``--readme`` rewrites the table of docs/validation/speed-accuracy.md between the
``speed-accuracy`` markers (so that table is produced here, never typed).

Errors (all relative, max over what is compared):
- stiffness: k_L + k_R over one mesh period (interpolated onto the reference's phases) vs FE at the finest mesh, / mean;
- thermal: ζ_T of the pinion along the path (30 K flank rise) vs FE at the finest mesh;
- lubrication: μ along the path vs the finest FE line EHL, / max μ;
- EHL point solver: central film Hc at (M, L) = (20, 10) vs the finest grid;
- dynamics: gear and pinion amplitudes (x, y, displacement and velocity) vs RK4 at
  1600 steps per mesh period;
- coupled case (presets): gear amplitudes and μ_max of the bidirectional baseline vs
  the ``accurate`` preset.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
from collections.abc import Callable
from pathlib import Path

import numpy as np

from femgear.case import build_case
from femgear.levels import stiffness as stiffness_levels
from femgear.levels.thermal import case_arguments
from femgear.perf import measure, pareto_front
from femgear.physics.body.thermal import analytic_flank_deviation, fe_flank_deviation
from femgear.scene import load_scene

ROOT = Path(__file__).resolve().parents[2]
BASELINE = ROOT / "studies" / "paper_baseline.toml"
OUT = ROOT / "out" / "speed_accuracy"
MARK = ("<!-- speed-accuracy:begin -->", "<!-- speed-accuracy:end -->")


def _rows(submodel: str, cases: list[tuple[str, Callable[[], object]]], error: Callable[[object, object], float],
          repeats: int) -> list[dict]:
    """Measure every case (after one warm-up call of the first); the LAST case is the reference."""
    cases[0][1]()
    results = [(name, measure(fn, repeats if i < len(cases) - 1 else 1)) for i, (name, fn) in enumerate(cases)]
    ref = results[-1][1].value
    return [{"submodel": submodel, "level": name, "seconds": m.seconds, "peak_mb": m.peak_bytes / 2**20,
             "error": float(error(m.value, ref))} for name, m in results]


def stiffness(scene, quick: bool, repeats: int) -> list[dict]:
    case = build_case(scene)
    mn = scene.pair.normal_module
    fe = [2.5, 3.0] if quick else [2.5, 3.0, 4.0]
    cases = [(lv, lambda lv=lv: stiffness_levels.of(case, level=lv)) for lv in ("constant", "iso6336")]
    cases += [(f"pem, {n} phases", lambda n=n: stiffness_levels.of(case, level="pem", n_positions=n)) for n in (100, 200)]
    cases += [("ltca (3-D FE member bodies + contact; cached kernels; a model, not a resolution)",
               lambda: stiffness_levels.of(case, level="ltca"))]
    cases += [(f"fe h=m/{d:g}", lambda d=d: stiffness_levels.of(case, level="fe", fe_options={"h": mn / d}))
              for d in fe]
    return _rows("stiffness", cases, lambda a, r: np.max(np.abs(a.at(r.phase) - r.k_total)) / r.mean, repeats)


def thermal(scene, quick: bool, repeats: int) -> list[dict]:
    from femgear.physics.geometry import path_positions

    s = load_scene(BASELINE, ["thermal.flank_temperature_rise=30"])
    case = build_case(s)
    u = path_positions(case.pair, 21)
    mn = s.pair.normal_module
    fe = [2.5, 4.0] if quick else [2.5, 4.0, 8.0]
    a, rises = case_arguments(case, 1), (case.thermal.flank_temperature_rise, case.thermal.shaft_temperature_rise)
    cases = [("analytic", lambda: analytic_flank_deviation(case.pair, 1, u, *rises, a["expansion"], a["poisson_ratio"],
                                                           a["bore_radius"]))]
    cases += [(f"fe h=m/{d:g}", lambda d=d: fe_flank_deviation(
        case.pair, 1, u, *rises, a["expansion"], a["youngs_modulus"], a["poisson_ratio"], a["conductivity"],
        a["bore_radius"], h=mn / d)) for d in fe]
    return _rows("thermal", cases, lambda a, r: np.max(np.abs(a - r)) / np.max(np.abs(r)), repeats)


def lubrication(scene, quick: bool, repeats: int) -> list[dict]:
    from femgear.case import build_case
    from femgear.levels.contact import reduced_modulus_of
    from femgear.levels.lubrication import envelope_contact, line_friction, oil_law, tehl_setup
    from femgear.physics.ehl.path import ehl_line_solver
    from femgear.physics.lubrication.map import hertz_level_solver
    from femgear.physics.lubrication.path import solids_of

    case = build_case(scene)
    c = envelope_contact(case, n=11)      # only its kinematics and mean load per length are used
    k = c.kin
    args = dict(w=np.full(k.u.shape, c.load_per_length), R=k.R, ue=k.ue, srr=np.abs(k.srr),
                T=np.full(k.u.shape, scene.operating.ambient_temperature))
    tols = [0.05, 0.01] if quick else [0.05, 0.02, 0.01, 0.005, 0.002]
    from femgear.physics.tehl.solver import tehl_line_solver

    E_red, solids = reduced_modulus_of(case), solids_of(case.material, case.oil)
    cases = [("formula", lambda: hertz_level_solver(line_friction(case))(**args)[0]),
             ("tehl (thermal, not a resolution of ehl-line)",
              lambda: tehl_line_solver(tehl_setup(case), tol=case.numerics.ehl_tol)(**args)[0])]
    cases += [(f"ehl-line tol {tol:g}",
               lambda tol=tol: ehl_line_solver(oil_law(case), E_red, solids, case.oil.eyring_stress, tol=tol)(**args)[0])
              for tol in tols]
    return _rows("lubrication μ(u)", cases, lambda a, r: np.max(np.abs(a - r)) / np.max(r), repeats)


def ehl_point(scene, quick: bool, repeats: int) -> list[dict]:
    from femgear.physics.ehl.point import solve_point

    levels = [1, 2, 3] if quick else [1, 2, 3, 4]
    cases = [(f"point level {lv} ({(16 * 2**lv + 1)}²)", lambda lv=lv: solve_point(20.0, 10.0, level=lv).Hc)
             for lv in levels]
    return _rows("EHL point (20,10)", cases, lambda a, r: abs(a - r) / r, repeats)


def dynamics(scene, quick: bool, repeats: int) -> list[dict]:
    from femgear.case import build_case
    from femgear.system.dynamics import build_model
    from femgear.system.dynamics.integrate import simulate
    from femgear.system.dynamics.response import analyse

    model = build_model(build_case(scene), "lumped")
    keys = [f"{m}.{q}.{a}" for m in ("gear", "pinion") for q in ("displacement", "velocity") for a in "xy"]
    periods = 60 if quick else 100

    def amplitudes(method, steps):
        sim = simulate(model, periods * model.mesh_period, model.mesh_period / steps, method)
        a = analyse(sim, periods / 2).amplitudes
        return np.array([a[k] for k in keys])

    cases = [(f"{m} {n}/period", lambda m=m, n=n: amplitudes(m, n))
             for m, steps in (("rk4", (100, 200, 400)), ("expo", (100, 200, 400)), ("newmark", (800,)))
             for n in steps]
    cases.append(("rk4 1600/period", lambda: amplitudes("rk4", 1600)))
    return _rows("dynamics integrator", cases, lambda a, r: np.max(np.abs(a - r) / np.abs(r)), repeats)


def coupled(scene, quick: bool, repeats: int) -> list[dict]:
    from femgear.case import build_case
    from femgear.system.coupling import CouplingSetup, run_coupled

    def run(preset):
        s = _preset_scene(preset)
        st = run_coupled(CouplingSetup.from_case(build_case(s))).state
        a = st.amplitudes
        return np.array([a[k] for k in ("gear.displacement.x", "gear.displacement.y", "gear.velocity.x",
                                        "gear.velocity.y")] + [st.mu.max()])

    presets = ["fast", "balanced"] + ([] if quick else ["accurate"])
    cases = [(f"preset {p}", lambda p=p: run(p)) for p in presets]
    return _rows("coupled case", cases, lambda a, r: np.max(np.abs(a - r) / np.abs(r)), 1)


def _preset_scene(preset: str):
    """The baseline with its fidelity entries replaced by a preset (wear and coupling kept)."""
    from femgear.scene.load import read_toml, scene_from_dict

    raw = read_toml(BASELINE)
    raw["physics"] = {"preset": preset, "wear": raw["physics"]["wear"], "coupling": raw["physics"]["coupling"]}
    raw.pop("numerics", None)
    raw.pop("stiffness", None)
    return scene_from_dict(raw)


SUBMODELS = (stiffness, thermal, lubrication, ehl_point, dynamics, coupled)


def table(rows: list[dict]) -> str:
    front = {(r["submodel"], r["level"]) for sub in {r["submodel"] for r in rows}
             for r in pareto_front([x for x in rows if x["submodel"] == sub])}
    lines = ["| sub-model | level / resolution | time [s] | peak memory [MB] | error vs reference | Pareto |",
             "|---|---|---|---|---|---|"]
    for r in rows:
        err = "reference" if r["error"] == 0 else f"{r['error']:.2e}"
        mark = "✓" if (r["submodel"], r["level"]) in front else ""
        lines.append(f"| {r['submodel']} | {r['level']} | {r['seconds']:.3g} | {r['peak_mb']:.3g} | {err} | {mark} |")
    return "\n".join(lines)


def plot(rows: list[dict], folder: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    for sub in dict.fromkeys(r["submodel"] for r in rows):
        rs = [r for r in rows if r["submodel"] == sub and r["error"] > 0]
        if not rs:
            continue
        fig, ax = plt.subplots(figsize=(6, 4))
        ax.loglog([r["seconds"] for r in rs], [r["error"] for r in rs], "o")
        for r in rs:
            ax.annotate(r["level"], (r["seconds"], r["error"]), fontsize=7)
        front = pareto_front(rs)
        ax.loglog([r["seconds"] for r in front], [r["error"] for r in front], "r-", lw=0.8, label="Pareto front")
        ax.set_xlabel("wall time [s]")
        ax.set_ylabel("error vs reference")
        ax.set_title(sub)
        ax.legend(fontsize=8)
        ax.grid(alpha=0.3, which="both")
        fig.tight_layout()
        fig.savefig(folder / f"pareto_{sub.split()[0].lower()}.png", dpi=110)
        plt.close(fig)


def update_readme(text: str, readme: Path = ROOT / "docs" / "validation" / "speed-accuracy.md") -> None:
    s = readme.read_text(encoding="utf-8")
    start, end = s.index(MARK[0]) + len(MARK[0]), s.index(MARK[1])
    readme.write_text(s[:start] + "\n" + text + "\n" + s[end:], encoding="utf-8")


def setup(argv: list[str]) -> argparse.Namespace:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--quick", action="store_true", help="coarser references (CI)")
    p.add_argument("--readme", action="store_true", help="rewrite the table in docs/validation/speed-accuracy.md")
    p.add_argument("--only", nargs="*", default=None, help="sub-model functions to run")
    p.add_argument("--repeats", type=int, default=3)
    return p.parse_args(argv)


def run(args: argparse.Namespace) -> list[dict]:
    """Run the chosen sub-models; rows are saved after each one and merged with earlier
    rows of the other sub-models (so a failure or ``--only`` loses nothing)."""
    scene = load_scene(BASELINE)
    OUT.mkdir(parents=True, exist_ok=True)
    saved = OUT / "rows.json"
    rows = json.loads(saved.read_text()) if saved.exists() else []
    for fn in SUBMODELS:
        if args.only is None or fn.__name__ in args.only:
            new = fn(scene, args.quick, args.repeats)
            names = {r["submodel"] for r in new}
            rows = [r for r in rows if r["submodel"] not in names] + new
            saved.write_text(json.dumps(rows, indent=1))
    order = {fn.__name__: i for i, fn in enumerate(SUBMODELS)}
    return sorted(rows, key=lambda r: order.get(_KEY.get(r["submodel"], ""), 99))


_KEY = {"stiffness": "stiffness", "thermal": "thermal", "lubrication μ(u)": "lubrication",
        "EHL point (20,10)": "ehl_point", "dynamics integrator": "dynamics", "coupled case": "coupled"}


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    args = setup(argv)
    rows = run(args)
    plot(rows, OUT)
    text = table(rows)
    print(text)
    if args.readme:
        update_readme(text)
    print(json.dumps({"study": "speed_accuracy", "quick": args.quick, "rows": rows}, default=float))
    return 0 if all(math.isfinite(r["error"]) for r in rows) else 1


if __name__ == "__main__":
    sys.exit(main())
