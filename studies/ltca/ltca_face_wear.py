"""Face-resolved against face-uniform LTCA wear on the rig's test gear (issue 12).

    python studies/ltca/ltca_face_wear.py [--coarse] [--workers=2]

The coupled baseline (500 rpm, 200 N m) with the LTCA mesh (``physics.stiffness = "ltca"``) and the
test-gear modifications of studies/paper/rig_conditions.py (:data:`TEST_GEAR_MODIFICATIONS`: linear tip
relief 3 µm over 2.5 mm on both members, lead crowning 5 µm), new and after 1e6 and 3e6 pinion
revolutions of Archard wear, with the wear depth field ``wear.field = "path"`` (face-uniform h(u),
the same on both helices: the LTCA's loads averaged over the face) and ``"face"`` (h(ρ, ζ) per member
and helix from the LTCA's contact-line loads, :mod:`femgear.physics.wear.face`; each coupling pass re-runs
the LTCA on that topography).  Prints per case the largest depth and where it is (member, helix,
path position from the pitch point, face position), the face-mean depth, the mid-face / face-end
ratio, the gear's y amplitude and v_y, the loaded TE p-p of the worn flanks, the passes, the wear time
per pass and the mesh orders the LTCA resolves on the converged worn flanks (the face runs band-limit
their excitation to these, :func:`femgear.system.coupling.passes.worn_orders`; the path runs keep the unworn
cycle's); then the
cost of one wear step (load sharing over the LTCA phases + Archard rates, medians of 5) and of a
pass's wear integration.  Writes ``out/ltca_face_wear/ltca_face_wear.{json,png}`` (depth maps of the
pinion's flanks, both helices, face-resolved beside face-uniform).
"""

from __future__ import annotations

import sys
import time

import numpy as np

try:
    from studies import _common as C
    from studies.paper.rig_conditions import TEST_GEAR_MODIFICATIONS
except ImportError:
    import pathlib
    import sys

    sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2]))
    from rig_conditions import TEST_GEAR_MODIFICATIONS

    from studies import _common as C

CYCLES = (1e6, 3e6)
FIELDS = ("path", "face")


def setup() -> list[tuple[str, list[str]]]:
    mods = list(TEST_GEAR_MODIFICATIONS)
    out = [("new", mods + ["wear.cycles=0.0"])]
    for n in CYCLES:
        out += [(f"{f} {n:.0e}", mods + [f"wear.cycles={n}", f'wear.field="{f}"']) for f in FIELDS]
    return out


def _depth_summary(case) -> dict:
    """Largest depth and where, face mean, mid/end ratio of the face field (the path field: uniform)."""
    u = case.case.path.u - case.case.pair.u_pitch
    wear = C.wear(case)
    if case.tribology.wear_face is None:
        j, k = np.unravel_index(np.argmax(wear), wear.shape)
        return {"max_um": 1e6 * wear[j, k], "member": ("pinion", "gear")[j], "helix": "both",
                "u_mm": 1e3 * u[k], "zeta_mm": None, "face_mean_max_um": 1e6 * wear.max(), "mid_to_end": 1.0}
    face, z = case.tribology.wear_face, case.tribology.face_grid
    j, s, k, m = np.unravel_index(np.argmax(face), face.shape)
    mid = np.argmin(np.abs(z - z[-1] / 2))
    col = face[j, s, k]
    return {"max_um": 1e6 * face[j, s, k, m], "member": ("pinion", "gear")[j], "helix": ("left", "right")[s],
            "u_mm": 1e3 * u[k], "zeta_mm": 1e3 * z[m], "face_mean_max_um": 1e6 * wear.max(),
            "mid_to_end": float(col[mid] / max(0.5 * (col[0] + col[-1]), 1e-300))}


def _setup(coarse: bool):
    from femgear.case import build_case
    from femgear.scene import load_scene
    from femgear.system.coupling import CouplingSetup

    over = TEST_GEAR_MODIFICATIONS + ["wear.cycles=1e6", 'wear.field="face"',
                                      f"numerics.path_points={31 if coarse else 61}"]
    return CouplingSetup.from_case(build_case(load_scene(C.BASELINE, over)), n_phase=64 if coarse else 128)


def worn_orders(setup, case) -> int:
    """Mesh orders the LTCA resolves on the case's converged worn flanks (the ltca level's criterion,
    :func:`femgear.physics.ltca.level.resolved_orders`); the face runs band-limit their excitation to these, the
    path runs keep the unworn cycle's."""
    from femgear.physics.ltca.level import resolved_orders
    from femgear.system.coupling.passes import removed_deviation

    wear, zeta, face = C.wear(case), C.thermal_deviation(case), case.tribology.wear_face
    c = setup.ltca
    return resolved_orders(c.model, c.force, c.modifications, c.stagger, c.n_line,
                           removed_deviation(setup, wear, zeta, face))[0]


def step_cost(setup) -> dict:
    """Seconds per wear step (rates at the unworn state, medians of 5) and of a 1e6-cycle integration, path
    against face, on the test gear's unworn LTCA cycle; the steps each takes."""
    from dataclasses import replace

    from femgear.physics.wear import WearSetup, WearState, run_wear, wear_rates
    from femgear.physics.wear.face import FaceWearState, face_rates, run_face_wear
    from femgear.system.coupling.passes import reference_loads

    zero = np.zeros((2, setup.kin.u.size))
    ref, _ = reference_loads(setup, setup.ltca, zero, zero)
    case = setup.case
    ws = WearSetup(pair=setup.pair, kin=setup.kin, force=setup.static_force, c_l=setup.c_l,
                   coefficient=case.wear.coefficient, hardness=case.material.hardness, reference=ref)
    face = replace(setup.face, ref=ref)

    def median(f) -> float:
        times = []
        for _ in range(5):
            t0 = time.perf_counter()
            f()
            times.append(time.perf_counter() - t0)
        return float(np.median(times))

    out = {"path_step_s": median(lambda: wear_rates(ws, WearState.zero(ws.kin.u.size))),
           "face_step_s": median(lambda: face_rates(ws, face, FaceWearState.zero(ws.kin.u.size, face.grid.size)))}
    for name, run in (("path", lambda: run_wear(ws, 1e6)), ("face", lambda: run_face_wear(ws, face, 1e6))):
        t0 = time.perf_counter()
        st = run()
        out[f"{name}_1e6_s"], out[f"{name}_1e6_steps"] = time.perf_counter() - t0, st.steps
    out["phases"], out["face_points"] = int(ref.phases.size), int(face.grid.size)
    return out


def run(coarse: bool = False, workers: int = 2) -> dict:
    names, jobs = zip(*setup())
    runs = C.run_cases(list(jobs), coarse=coarse, workers=workers, timed=True)
    cases = [c for c, _ in runs]
    rows = {}
    for name, (c, timings) in zip(names, runs):
        rows[name] = {"gear_y_um": C.amplitude(c, "gear", "displacement", "y"),
                      "gear_vy": C.amplitude(c, "gear", "velocity", "y"), "lte_um": 1e6 * c.coupled.state.lte_peak_to_peak,
                      "passes": len(c.coupled.history.iteration) - 1, "converged": c.coupled.converged,
                      "wear_seconds": float(np.median([t["wear"] for t in timings])) if timings
                      else 0.0, **_depth_summary(c)}
    new = rows["new"]
    coupling = _setup(coarse)
    for r, c in zip(rows.values(), cases):
        r["change_percent"] = {k: 100 * (r[k] / new[k] - 1) for k in ("gear_y_um", "gear_vy")}
        r["worn_orders"] = worn_orders(coupling, c)
        r["unworn_orders"] = int(coupling.ltca.resolved_orders)
    out = {"coarse": coarse, "rows": rows, "cost": step_cost(coupling)}
    out["png"] = str(_plot(dict(zip(names, cases))))
    return out


def _plot(cases: dict):
    """Pinion depth maps (ζ across, path position along) for the left and right helix, face against path."""
    fig, axes = C.figure(len(CYCLES), 3, (13, 4 * len(CYCLES)))
    for row, n in enumerate(CYCLES):
        face, path = cases[f"face {n:.0e}"], cases[f"path {n:.0e}"]
        u = 1e3 * (face.case.path.u - face.case.pair.u_pitch)
        z = 1e3 * face.tribology.face_grid
        maps = [face.tribology.wear_face[0, 0], face.tribology.wear_face[0, 1],
                np.repeat(C.wear(path)[0][:, None], z.size, axis=1)]
        top = 1e6 * max(m.max() for m in maps)
        for ax, m, title in zip(axes[row], maps, ("face, left helix", "face, right helix", "path, both helices")):
            im = ax.pcolormesh(z, u, 1e6 * m, vmin=0, vmax=top, shading="gouraud", cmap="viridis")
            ax.set(title=f"pinion, {n:.0e} cycles: {title}", xlabel="face position ζ [mm] (groove at b)",
                   ylabel="u − u_C [mm]")
            fig.colorbar(im, ax=ax, label="depth [µm]")
    return C.save(fig, "ltca_face_wear", "ltca_face_wear.png")


def table(res: dict) -> str:
    head = (f"{'case':>10s} | {'max [µm]':>8s} {'where (member, helix, u−u_C, ζ) [mm]':>38s} | {'face-mean max':>13s} | "
            f"{'mid/end':>7s} | {'gear y [µm] (Δ%)':>18s} | {'gear v_y [m/s] (Δ%)':>20s} | LTE p-p [µm] | passes | wear/pass [s] "
            f"| orders resolved worn (unworn)")
    lines = [head, "-" * len(head)]
    for name, r in res["rows"].items():
        where = f"{r['member']}, {r['helix']}, {r['u_mm']:+.2f}, " + ("-" if r["zeta_mm"] is None else f"{r['zeta_mm']:.2f}")
        lines.append(f"{name:>10s} | {r['max_um']:8.3f} {where:>38s} | {r['face_mean_max_um']:13.3f} | "
                     f"{r['mid_to_end']:7.2f} | {r['gear_y_um']:9.4f} ({r['change_percent']['gear_y_um']:+6.1f}) | "
                     f"{r['gear_vy']:10.3e} ({r['change_percent']['gear_vy']:+6.1f}) | {r['lte_um']:12.3f} | "
                     f"{r['passes']:6d} | {r['wear_seconds']:13.2f} | {r['worn_orders']} ({r['unworn_orders']})")
    c = res["cost"]
    lines += ["", f"cost per wear step ({c['phases']} LTCA phases, {c['face_points']} face points, medians of 5): "
              f"path {1e3 * c['path_step_s']:.1f} ms, face {1e3 * c['face_step_s']:.1f} ms "
              f"(×{c['face_step_s'] / c['path_step_s']:.2f}); 1e6 cycles: path {c['path_1e6_s']:.2f} s in "
              f"{c['path_1e6_steps']} steps, face {c['face_1e6_s']:.2f} s in {c['face_1e6_steps']} steps",
              f"depth map: {res['png']}"]
    return "\n".join(lines)


def main(argv: list[str]) -> int:
    opts = C.parse_args(argv)
    res = run(opts["coarse"], opts["workers"])
    print(table(res))
    print("json:", C.write_results("ltca_face_wear", res))
    print(C.json.dumps({"study": "ltca_face_wear", **{n: {k: r[k] for k in ("max_um", "gear_y_um", "gear_vy", "lte_um")}
                                                      for n, r in res["rows"].items()}, "cost": res["cost"]}))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
