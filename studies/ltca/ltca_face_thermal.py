"""Face-resolved against face-uniform thermal growth in the LTCA re-run (``thermal = "fe3d"``, ``wear.field = "face"``).

    python studies/ltca/ltca_face_thermal.py [--coarse] [--crowning=5e-6]

The baseline (500 rpm, 200 N m) with the LTCA mesh, the 3-D thermal level and the face-resolved wear
field, at a bulk flank rise ``thermal.flank_temperature_rise = 30`` K and no wear (``wear.cycles = 0``):
the deviation the LTCA is re-run on is then −ζ_T alone.  Face-resolved: ζ_T(member, helix, u, ζ) of the
3-D unit solutions (:meth:`femgear.system.coupling.thermal.ThermalUnits.face`); face-uniform: its face mean ζ_T(u)
(what the loop used before).  Prints per variant the loaded TE p-p, the helix forces' cycle means, the
load-weighted face centre ζ̄/b of each helix and the load share of the apex half (ζ > b/2), then one
one-way coupled pass of each (the loop's own path: ``setup.thermal`` with and without its 3-D bodies)
with its seconds per part, and the cost of the face field (medians of 20).  Writes
``out/ltca_face_thermal/ltca_face_thermal.{json,png}`` (ζ_T over the pinion's left flank and the cycle's
mean load per face position, both variants).
"""

from __future__ import annotations

import sys
import time
from dataclasses import replace

import numpy as np

try:
    from studies import _common as C
except ImportError:
    import pathlib
    import sys

    sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2]))
    from studies import _common as C

OVER = ['physics.stiffness="ltca"', 'physics.thermal="fe3d"', 'wear.field="face"', "wear.cycles=0.0",
        "thermal.flank_temperature_rise=30.0"]


def setup(coarse: bool, crowning: float = 0.0):
    from femgear.case import build_case
    from femgear.scene import load_scene
    from femgear.system.coupling import CouplingSetup

    over = OVER + [f"numerics.path_points={31 if coarse else 61}", f"modifications.crowning={crowning}"]
    if coarse:
        over += ["numerics.dynamics_cycles=20", "numerics.transient_cycles=10"]
    return CouplingSetup.from_case(build_case(load_scene(C.BASELINE, over)), n_phase=64 if coarse else 128)


def load_profile(res, b: float, n: int = 8) -> dict:
    """Cycle-mean load per face bin of each helix, load centre ζ̄/b and apex-half share (ζ > b/2)."""
    out = {}
    for h, name in enumerate(("left", "right")):
        w = np.concatenate([a[a[:, 0] == h, 4] for a in res.line_load])
        z = np.concatenate([a[a[:, 0] == h, 3] for a in res.line_load])
        hist, _ = np.histogram(z, bins=n, range=(0.0, b), weights=w)
        out[name] = {"centre": float(np.sum(w * z) / np.sum(w) / b), "apex_share": float(w[z > b / 2].sum() / w.sum()),
                     "profile": hist / hist.sum()}
    return out


def compare(setup) -> dict:
    """The deviated LTCA cycle on −ζ_T face-resolved and face-uniform, from the loop's own functions."""
    from femgear.errors import ConvergenceError
    from femgear.system.coupling.passes import pass_thermal, removed_deviation

    n = setup.kin.u.size
    rise, zeta, face = pass_thermal(setup, np.zeros(n))
    wear, wear_face = np.zeros((2, n)), np.zeros((2, 2, n, setup.face.grid.size))
    rows = {}
    for name, field in (("face-resolved", face), ("face-uniform", None)):
        t0 = time.perf_counter()
        try:
            cycle = setup.ltca.deviated(removed_deviation(setup, wear, zeta, wear_face, field))
        except ConvergenceError as exc:
            rows[name] = {"error": str(exc), "seconds": time.perf_counter() - t0}
            continue
        res = cycle.result
        rows[name] = {"lte_um": 1e6 * cycle.lte_peak_to_peak, "force_left": float(np.mean(res.force_left)),
                      "force_right": float(np.mean(res.force_right)), "seconds": time.perf_counter() - t0,
                      **load_profile(res, setup.pair.b)}
    grid = setup.face.grid
    mean = np.trapezoid(face, grid, axis=-1).mean(axis=1) / grid[-1]
    return {"rise": rise, "rows": rows, "zeta_face": face, "zeta": zeta, "grid": grid,
            "face_mean_error": float(np.max(np.abs(mean - zeta)) / np.max(np.abs(zeta))),
            "apex_to_outer": float(np.median(face[:, :, :, -1] / face[:, :, :, 0])),
            "unworn_lte_um": 1e6 * setup.ltca.lte_peak_to_peak}


def passes(setup) -> dict:
    """One one-way coupled pass with the face-resolved growth and with the face-uniform one (bodies dropped)."""
    from femgear.errors import ConvergenceError
    from femgear.system.coupling import run_coupled

    out = {}
    for name, s in (("face-resolved", setup), ("face-uniform", replace(setup, thermal=replace(setup.thermal,
                                                                                                bodies=None)))):
        t0 = time.perf_counter()
        try:
            st = run_coupled(s, one_way=True).state
        except ConvergenceError as exc:
            out[name] = {"error": str(exc), "seconds": time.perf_counter() - t0}
            continue
        out[name] = {"seconds": time.perf_counter() - t0, "pass_seconds": st.seconds, "timings": dict(st.timings),
                     "lte_um": 1e6 * st.lte_peak_to_peak,
                     "thermal_face": st.thermal_face is not None}
    return out


def face_cost(setup) -> dict:
    """Seconds of the face field per pass (``ThermalUnits.face`` + the face deviation), medians of 20."""
    from femgear.system.coupling.passes import removed_deviation
    from femgear.system.coupling.thermal import roll_distances

    n, g = setup.kin.u.size, setup.face.grid
    rho, zero, zf = roll_distances(setup.pair, setup.kin.u), np.zeros((2, n)), np.zeros((2, 2, n, g.size))

    def median(f) -> float:
        times = []
        for _ in range(20):
            t0 = time.perf_counter()
            f()
            times.append(time.perf_counter() - t0)
        return float(np.median(times))

    face = setup.thermal.face(rho, g, 30.0, 0.0)
    return {"face_field_s": median(lambda: setup.thermal.face(rho, g, 30.0, 0.0)),
            "deviation_resolved_s": median(lambda: removed_deviation(setup, zero, zero, zf, face)),
            "deviation_uniform_s": median(lambda: removed_deviation(setup, zero, zero, zf, None)),
            "points": [n, int(g.size)]}


def _plot(cmp: dict, setup, crowning: float = 0.0):
    fig, axes = C.figure(1, 2, (12, 4.2))
    axes = axes[0]
    u = 1e3 * (setup.kin.u - setup.pair.u_pitch) if hasattr(setup.pair, "u_pitch") else 1e3 * setup.kin.u
    z = 1e3 * cmp["grid"]
    im = axes[0].pcolormesh(z, u, 1e6 * cmp["zeta_face"][0, 0], shading="gouraud", cmap="magma")
    axes[0].set(title=f"pinion ζ_T, left helix, ΔT_f = {cmp['rise']:.0f} K", xlabel="ζ [mm] (groove at b)",
                ylabel="u − u_pitch [mm]")
    fig.colorbar(im, ax=axes[0], label="ζ_T [µm]")
    b = setup.pair.b
    for name, r in cmp["rows"].items():
        if "error" in r:
            continue
        for helix, ls in (("left", "-"), ("right", "--")):
            prof = r[helix]["profile"]
            centres = 1e3 * b * (np.arange(prof.size) + 0.5) / prof.size
            axes[1].plot(centres, prof, ls, label=f"{name}, {helix} (ζ̄ = {r[helix]['centre']:.3f} b)")
    axes[1].set(title="cycle load share per face bin", xlabel="ζ [mm] (groove at b)", ylabel="share of helix load")
    axes[1].legend(fontsize=7)
    tag = f"_crowned{1e6 * crowning:.0f}" if crowning else ""
    return C.save(fig, "ltca_face_thermal", f"ltca_face_thermal{tag}.png")


def table(res: dict) -> str:
    c = res["compare"]
    lines = [f"ΔT_f = {c['rise']:.0f} K; ζ_T apex/outer end (median) {c['apex_to_outer']:.3f}; face mean vs loop ζ_T: "
             f"max rel. error {c['face_mean_error']:.2e}; unworn LTE p-p {c['unworn_lte_um']:.3f} µm",
             f"{'variant':>14s} | LTE p-p [µm] | F_left [N] | F_right [N] | ζ̄/b left, right | apex share left, right "
             f"| LTCA [s]"]
    for name, r in c["rows"].items():
        if "error" in r:
            lines.append(f"{name:>14s} | LTCA failed: {r['error']}")
            continue
        lines.append(f"{name:>14s} | {r['lte_um']:12.4f} | {r['force_left']:10.1f} | {r['force_right']:11.1f} | "
                     f"{r['left']['centre']:.4f}, {r['right']['centre']:.4f} | "
                     f"{r['left']['apex_share']:.4f}, {r['right']['apex_share']:.4f} | {r['seconds']:.2f}")
    lines.append("one-way pass:")
    for name, r in res["passes"].items():
        if "error" in r:
            lines.append(f"{name:>14s} | pass failed: {r['error']}")
            continue
        t = ", ".join(f"{k} {v:.2f}" for k, v in r["timings"].items())
        lines.append(f"{name:>14s} | pass {r['pass_seconds']:.2f} s ({t}) | LTE p-p {r['lte_um']:.4f} µm")
    k = res["cost"]
    lines.append(f"face field per pass ({k['points'][0]} u × {k['points'][1]} ζ, medians of 20): ThermalUnits.face "
                 f"{1e3 * k['face_field_s']:.2f} ms; face deviation {1e3 * k['deviation_resolved_s']:.2f} ms "
                 f"(uniform {1e3 * k['deviation_uniform_s']:.2f} ms)")
    lines.append(f"figure: {res['png']}")
    return "\n".join(lines)


def run(coarse: bool = False, crowning: float = 0.0) -> dict:
    """Path against face thermal deviation on the LTCA cycle, their cost and the coupled passes."""
    t0 = time.perf_counter()
    cs = setup(coarse, crowning)
    setup_s = time.perf_counter() - t0
    cmp = compare(cs)
    return {"coarse": coarse, "crowning": crowning, "setup_s": setup_s, "compare": cmp, "cost": face_cost(cs),
            "passes": passes(cs), "png": str(_plot(cmp, cs, crowning))}


def main(argv: list[str]) -> int:
    opts = C.parse_args(argv)
    crowning = float(opts.get("crowning", 0.0))
    res = run(opts["coarse"], crowning)
    setup_s, cmp = res["setup_s"], res["compare"]
    print(f"crowning {1e6 * crowning:.1f} µm; setup {setup_s:.1f} s")
    print(table(res))
    tag = "ltca_face_thermal" + (f"_crowned{1e6 * crowning:.0f}" if crowning else "")
    print("json:", C.write_results("ltca_face_thermal", {k: v for k, v in res.items() if k != "compare"}, tag))
    print(C.json.dumps({"study": "ltca_face_thermal", "crowning": crowning, "setup_s": setup_s,
                        **{n: {k: r.get(k) for k in ("lte_um", "force_left", "force_right", "error")}
                           for n, r in cmp["rows"].items()}, "cost": res["cost"]}))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
