"""Accumulated wear 0, 1, 2, 3 × 10⁶ cycles on the coupled baseline: the paper's Table 4, Figs 11, 15, 16.

    python studies/paper/wear_cycles.py [--coarse] [--workers=2]

Each level is the bidirectional coupled baseline (PEM stiffness, thermal Eyring
traction, analytic thermal expansion, Archard wear under the dynamic load, lumped
dynamics) with ``wear.cycles`` set; amplitudes are half peak-to-peak of the member
centres over the steady state.  Prints the amplitude table beside the paper's Table 4
and the change of each amplitude relative to 3 × 10⁶ cycles (as the paper reports it),
writes ``out/wear_cycles/wear_cycles.json`` and three figures: amplitudes vs cycles
(Fig. 11), wear depth along the path (Fig. 15), μ and contact temperature rise along
the path per wear level (Fig. 16).

Reading of the results (see the README):
- wear deepens with cycles, least at the pitch point (zero sliding) and most at the
  pinion root, as the paper's Fig. 15;
- femgear's amplitudes grow with wear, velocity slightly more than displacement (the
  paper's ranking) — but far more strongly than the paper's +8 % / +50 %: the new
  gear's only excitation is the small PEM stiffness ripple of the two helices (±2.5 %),
  while the worn profile, averaged over the contact lines, adds a meshing error of
  ≈ 0.8 µm peak-to-peak per 10⁶ cycles at the mesh frequency
  (studies/paper/meshing_error.py), many times the ripple's transmission error;
- μ(u) is U-shaped with μ = 0 at the pitch point.  Wear removes most material where
  sliding is fastest (the ends of the path), so the worn ends carry less load and the
  load concentrates near the pitch point: μ and the contact temperature rise increase
  near the pitch point and *decrease* at the ends — the paper's Fig. 16 instead shifts
  the whole curve upward, attributing it to lubrication degraded by wear (thinner
  film, mixed friction), which femgear's smooth-surface traction model does not have
  (no roughness evolution, no asperity load share).
"""

from __future__ import annotations

import sys
import time

import numpy as np

try:
    from studies import _common as C
except ImportError:                                   # run as a script from studies/
    import pathlib
    import sys

    sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2]))
    from studies import _common as C

CYCLES = (0.0, 1e6, 2e6, 3e6)
PAPER_WEAR = C.PAPER_WEAR


def setup(cycles: float = 0.0) -> list[str]:
    """Overrides of the baseline for ``cycles`` mesh cycles of wear."""
    return [f"wear.cycles={cycles!r}", PAPER_WEAR]


def run(coarse: bool = False, workers: int = 2, cycles: tuple[float, ...] = CYCLES) -> dict:
    """``cycles`` must end with the reference level (the paper: 3e6) for the relative changes."""
    t0 = time.perf_counter()
    cases = C.run_cases([setup(n) for n in cycles], coarse=coarse, workers=workers)
    rows = []
    for n, c in zip(cycles, cases):
        row = {"cycles": n, "max_wear_pinion_um": float(C.wear(c)[0].max() * 1e6),
               "max_wear_gear_um": float(C.wear(c)[1].max() * 1e6), "mu_mean": float(np.mean(c.tribology.friction_coefficient)),
               "seconds": c.seconds}
        row.update({f"{m}.{q}.{ax}": C.amplitude(c, m, q, ax) for m, q, ax in C.AMPLITUDE_KEYS})
        rows.append(row)
    ref = rows[-1]
    gear_keys = [f"gear.{q}.{ax}" for _, q, ax in C.AMPLITUDE_KEYS[:4]]
    change = {f"{int(r['cycles'] / 1e6)}": {k: 100 * (r[k] / ref[k] - 1) for k in gear_keys} for r in rows[:-1]}
    return {"rows": rows, "change_vs_3e6_percent": change, "cases": cases, "coarse": coarse,
            "seconds": time.perf_counter() - t0}


#: the paper's reductions of the gear amplitudes vs 3e6 cycles (2e6, 1e6, 0) [%]: x, y, v_x, v_y
PAPER_REDUCTION = {"2": (-2.1, -2.9, -10.9, -10.6), "1": (-3.1, -5.8, -20.0, -19.7), "0": (-4.1, -8.1, -27.2, -50.0)}


def table(res: dict) -> str:
    cases = res["cases"]
    lines = [C.amplitude_table(cases, [int(r["cycles"] / 1e6) for r in res["rows"]], C.PAPER_TABLE4), "",
             "max wear depth [µm] pinion / gear: " + ", ".join(
                 f"{r['cycles']:.0e}: {r['max_wear_pinion_um']:.2f}/{r['max_wear_gear_um']:.2f}" for r in res["rows"]),
             "", "gear amplitude change vs 3e6 cycles [%] (femgear / paper):"]
    for k, ch in res["change_vs_3e6_percent"].items():
        if k not in PAPER_REDUCTION or res["rows"][-1]["cycles"] != 3e6:
            continue
        lines.append(f"  {k}e6 cycles: " + ", ".join(f"{name} {v:+.1f}/{p:+.1f}" for name, v, p in
                                                     zip(("x", "y", "v_x", "v_y"), ch.values(), PAPER_REDUCTION[k])))
    return "\n".join(lines)


def plot(res: dict) -> list:
    rows, cases = res["rows"], res["cases"]
    n = [r["cycles"] / 1e6 for r in rows]
    fig, ax = C.figure(2, 2, (11, 7))
    for j, member in enumerate(("gear", "pinion")):
        for i, q in enumerate(("displacement", "velocity")):
            a = ax[i][j]
            for k, axis in enumerate("xy"):
                a.plot(n, [r[f"{member}.{q}.{axis}"] for r in rows], "os"[k] + "-", label=f"femgear {axis}")
                a.plot(n, [C.PAPER_TABLE4[member].get(int(v), (np.nan,) * 4)[2 * i + k] for v in n], "os"[k] + "--",
                       mfc="none", label=f"paper {axis}")
            a.set(title=f"{member} {q} amplitude", xlabel="wear cycles [1e6]",
                  ylabel="[µm]" if q == "displacement" else "[m/s]", yscale="log")
            a.legend(fontsize=7)
    paths = [C.save(fig, "wear_cycles", "amplitudes.png")]
    fig, ax = C.figure(1, 2)
    for c, r in zip(cases, rows):
        for j in range(2):                 # pinion, gear
            ax[0][j].plot(c.case.path.u * 1e3, C.wear(c)[j] * 1e6, label=f"{r['cycles']:.0e} cycles")
    for j, name in enumerate(("pinion", "gear")):
        ax[0][j].axvline(cases[0].case.pair.u_pitch * 1e3, color="k", lw=0.5)
        ax[0][j].set(title=f"{name}: wear depth along the path (Fig. 15)", xlabel="path position u [mm]",
                     ylabel="wear depth [µm]")
        ax[0][j].legend(fontsize=7)
    paths.append(C.save(fig, "wear_cycles", "wear_depth.png"))
    fig, ax = C.figure(1, 2)
    for c, r in zip(cases, rows):
        ax[0][0].plot(c.case.path.u * 1e3, c.tribology.friction_coefficient, label=f"{r['cycles']:.0e}")
        ax[0][1].plot(c.case.path.u * 1e3, c.tribology.temperature_rise, label=f"{r['cycles']:.0e}")
    ax[0][0].set(title="friction coefficient along the path (Fig. 16)", xlabel="u [mm]", ylabel="μ [-]")
    ax[0][1].set(title="contact temperature rise", xlabel="u [mm]", ylabel="ΔT [K]")
    for a in ax[0]:
        a.legend(fontsize=7, title="cycles")
    paths.append(C.save(fig, "wear_cycles", "friction_temperature.png"))
    return paths


def main(argv: list[str]) -> int:
    opts = C.parse_args(argv)
    res = run(opts["coarse"], opts["workers"])
    print(f"wear cycles study ({'coarse' if res['coarse'] else 'full'}), {res['seconds']:.1f} s; amplitudes = "
          "half peak-to-peak of the member centres, steady state")
    print(table(res))
    print("json:", C.write_results("wear_cycles", {k: v for k, v in res.items() if k != "cases"}))
    print("plots:", *map(str, plot(res)))
    print(C.json.dumps({"study": "wear_cycles", "seconds": res["seconds"],
                        **{f"gear_vel_y_{int(r['cycles'] / 1e6)}e6": r["gear.velocity.y"] for r in res["rows"]}}))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
