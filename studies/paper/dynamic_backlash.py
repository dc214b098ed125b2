"""Dynamic backlash over one mesh cycle with none / wear / thermal / both: the paper's Fig. 5.

    python studies/paper/dynamic_backlash.py [--coarse] [--workers=2]

b(t) = b0 + (d_D + d_C)/2: the half-width of the dead zone of the left helix, with d_D,
d_C the drive- and coast-flank deviations (wear h1 + h2 on the drive flanks only,
thermal expansion −(ζ_T1 + ζ_T2) on both) averaged over the contact lines at that
instant (:func:`femgear.system.coupling.profile.mesh_deviation`; how it enters the dynamics,
once: :class:`femgear.system.dynamics.model.MeshDeviation`).  The paper's
b(t) = b0 + w1 + w2 − ζ_T1 − ζ_T2 counts the wear fully in the half-backlash and again
in the mesh deflection; femgear's half-width opens by w/2 (the drive flank moves by w,
the coast flank not at all).  b0 = ``pair.backlash`` = 50 µm.
Cases: none, wear (1e6 cycles), thermal (flank temperature rise 30 K), both.  The full
level takes the flank deviations of the converged coupled state (wear under the dynamic
load); ``--coarse`` those of the quasi-static start (static load).  Writes
``out/dynamic_backlash/dynamic_backlash.{json,png}``.

The paper: wear → b > b0, thermal → b < b0, both → first above then below b0 within a
mesh cycle (non-monotonic).  In femgear wear (≈ 7 µm at the root/tip, 0 at the pitch
point) and thermal expansion (≈ 6 µm at 30 K, growing toward the tip) have different
shapes along the path, so their sum changes sign along the path; whether b(t) crosses
b0 within a mesh cycle depends on how many contact lines average it (a helical mesh
with ε_γ ≈ 2.4 averages strongly: the curves are much flatter than the paper's).
Result: wear 1e6 → b ≈ 57.1 µm (+7.1), 30 K → 41.4 µm (−8.6), both → 48.5 µm, always
below b0 (no crossing); b crosses b0 within the cycle only near the balance rise
≈ 25 K (row ``balanced``, derived linearly from the single cases, not run), where the
±0.3 µm intra-cycle wear ripple straddles b0.
"""

from __future__ import annotations

import sys
import time

import numpy as np

try:
    from studies import _common as C
except ImportError:
    import pathlib
    import sys

    sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2]))
    from studies import _common as C


def setup() -> dict[str, list[str]]:
    return dict(C.FLANK_CASES)


def run(coarse: bool = False, workers: int = 2) -> dict:
    t0 = time.perf_counter()
    cases = C.flank_cases(coarse, workers)
    rows = {}
    for label, c in cases.items():
        drive, coast = C.deviation_tables(c)
        b = c.case.backlash + 0.5 * (drive[0] + coast[0])
        d = np.diff(b)
        rows[label] = {"b_um": b * 1e6, "mean_um": float(b.mean() * 1e6), "min_um": float(b.min() * 1e6),
                       "max_um": float(b.max() * 1e6), "crosses_b0": bool(b.min() < c.case.backlash < b.max()),
                       "monotonic": bool(np.all(d >= 0) or np.all(d <= 0)),
                       "max_wear_um": float(C.wear(c).max() * 1e6),
                       "max_thermal_um": float(C.thermal_deviation(c).max() * 1e6)}
    b0 = next(iter(cases.values())).case.backlash
    # the flank rise at which the mean thermal closing balances the mean wear opening (Δb is linear
    # in the deviation and the analytic ζ_T in the rise): derived from the two single cases, not run
    dw, dt = (0.5 * sum(t[0] for t in C.deviation_tables(cases[k])) for k in ("wear", "thermal"))
    scale = -dw.mean() / dt.mean()
    b = b0 + dw + scale * dt
    rows["balanced"] = {"b_um": b * 1e6, "mean_um": float(b.mean() * 1e6), "min_um": float(b.min() * 1e6),
                        "max_um": float(b.max() * 1e6), "crosses_b0": bool(b.min() < b0 < b.max()),
                        "monotonic": bool(np.all(np.diff(b) >= 0) or np.all(np.diff(b) <= 0)),
                        "max_wear_um": rows["wear"]["max_wear_um"],
                        "max_thermal_um": scale * rows["thermal"]["max_thermal_um"],
                        "flank_temperature_rise_K": 30.0 * scale}
    return {"b0_um": b0 * 1e6, "rows": rows, "phase": np.arange(len(rows["none"]["b_um"])) / len(rows["none"]["b_um"]),
            "coarse": coarse, "seconds": time.perf_counter() - t0, "cases": cases}


def table(res: dict) -> str:
    lines = [f"b0 = {res['b0_um']:.1f} µm; b(t) over one mesh cycle",
             f"{'case':>13s} {'mean':>8s} {'min':>8s} {'max':>8s} {'crosses b0':>10s} {'monotonic':>9s} "
             f"{'max h':>7s} {'max ζ_T':>7s}  paper (Fig. 5)"]
    paper = {"none": "= b0", "wear": "> b0", "thermal": "< b0", "wear+thermal": "> b0 then < b0", "balanced": ""}
    for label, r in res["rows"].items():
        lines.append(f"{label:>13s} {r['mean_um']:8.3f} {r['min_um']:8.3f} {r['max_um']:8.3f} {str(r['crosses_b0']):>10s} "
                     f"{str(r['monotonic']):>9s} {r['max_wear_um']:7.2f} {r['max_thermal_um']:7.2f}  {paper[label]}")
    lines.append(f"balanced = wear + thermal at a flank rise of {res['rows']['balanced']['flank_temperature_rise_K']:.1f} K "
                 "(mean thermal closing = mean wear opening; derived linearly from the two single cases)")
    return "\n".join(lines)


def plot(res: dict):
    fig, ax = C.figure(1, 1, (8, 4.5))
    a = ax[0][0]
    for label, r in res["rows"].items():
        a.plot(res["phase"], r["b_um"], ls="--" if label == "balanced" else "-",
               label=label if label != "balanced" else f"wear+thermal {r['flank_temperature_rise_K']:.0f} K")
    a.axhline(res["b0_um"], color="k", lw=0.5, ls=":")
    a.set(title="dynamic backlash over one mesh cycle (Fig. 5)", xlabel="mesh phase t/T_m [-]", ylabel="b [µm]")
    a.legend()
    return C.save(fig, "dynamic_backlash", "dynamic_backlash.png")


def main(argv: list[str]) -> int:
    opts = C.parse_args(argv)
    res = run(opts["coarse"], opts["workers"])
    print(f"dynamic backlash study ({'coarse: quasi-static' if res['coarse'] else 'full: converged coupled'}), "
          f"{res['seconds']:.1f} s")
    print(table(res))
    print("json:", C.write_results("dynamic_backlash", {k: v for k, v in res.items() if k != "cases"}))
    print("plot:", plot(res))
    print(C.json.dumps({"study": "dynamic_backlash", "seconds": res["seconds"],
                        **{f"mean_um_{k}": r["mean_um"] for k, r in res["rows"].items()}}))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
