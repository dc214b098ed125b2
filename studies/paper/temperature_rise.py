"""Tooth temperature rise cases on the coupled baseline: the paper's Figs 12–13 (temperature panels).

    python studies/paper/temperature_rise.py [--coarse] [--workers=2]

Cases: flank temperature rise 0 (thermal off), 15, 30, 45 K, and "from lubrication"
(``thermal.flank_temperature_rise = 0``: the mean contact temperature rise of the
lubrication model along the path, the paper's Δf(t)).  Wear is off (a new gear), so the
thermal expansion ζ_T of both flanks is the only profile deviation.  Prints the
amplitude table (paper: temperature rise increases the velocity and slightly decreases
the displacement), writes ``out/temperature_rise/temperature_rise.json``, the dynamic
mesh force over ten mesh periods (Fig. 12) and the phase planes of the gear centre
(Fig. 13).

Physics: the analytic thermal model expands each flank by ζ_T(u), largest at the tip
(radial growth) and nearly uniform over the path; a uniform ζ_T only closes the
backlash and leaves the mesh deflection unchanged, so the dynamic response changes
only through the non-uniform part of ζ_T along the contact lines (a small meshing error
at the mesh harmonics: 0.005 µm peak-to-peak at 30 K, studies/paper/meshing_error.py).
Friction and temperature rise enter μ(u) as well.  Result (full level): from 0 to 45 K
the gear's y displacement grows by 1.7 % and its y velocity falls by 0.3 % — a
negligible effect, opposite in sign to the paper's (velocity up, displacement slightly
down), and its sign is not robust (the coarse CI level gives the reverse).
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

#: label → flank temperature rise [K]; None = thermal model off; 0 = from the lubrication model
RISES = {"off": None, "15 K": 15.0, "30 K": 30.0, "45 K": 45.0, "lubrication": 0.0}


def setup(rise: float | None) -> list[str]:
    if rise is None:
        return ['physics.thermal="none"']
    return [f"thermal.flank_temperature_rise={rise!r}"]


def run(coarse: bool = False, workers: int = 2) -> dict:
    t0 = time.perf_counter()
    cases = C.run_cases([setup(r) for r in RISES.values()], coarse=coarse, workers=workers)
    rows = []
    for label, c in zip(RISES, cases):
        row = {"case": label, "flank_temperature_rise_K": c.tribology.flank_temperature_rise,
               "max_thermal_deviation_um": float(np.abs(C.thermal_deviation(c)).max() * 1e6),
               "mesh_force_amplitude_N": c.coupled.state.amplitudes["mesh_force.L.amplitude"],
               "mesh_force_mean_N": c.coupled.state.amplitudes["mesh_force.L.mean"], "seconds": c.seconds}
        row.update({f"{m}.{q}.{ax}": C.amplitude(c, m, q, ax) for m, q, ax in C.AMPLITUDE_KEYS})
        rows.append(row)
    return {"rows": rows, "cases": cases, "coarse": coarse, "seconds": time.perf_counter() - t0}


def table(res: dict) -> str:
    lines = [C.amplitude_table(res["cases"], list(RISES)), "",
             f"{'case':>12s} {'ΔT_flank[K]':>11s} {'max ζ_T[µm]':>11s} {'F_amp[N]':>9s} {'F_mean[N]':>9s}"]
    for r in res["rows"]:
        lines.append(f"{r['case']:>12s} {r['flank_temperature_rise_K']:11.2f} {r['max_thermal_deviation_um']:11.3f} "
                     f"{r['mesh_force_amplitude_N']:9.2f} {r['mesh_force_mean_N']:9.1f}")
    ref = res["rows"][0]
    lines.append("")
    lines.append("gear change vs thermal off [%]: " + "; ".join(
        f"{r['case']}: y {100 * (r['gear.displacement.y'] / ref['gear.displacement.y'] - 1):+.1f}, "
        f"v_y {100 * (r['gear.velocity.y'] / ref['gear.velocity.y'] - 1):+.1f}" for r in res["rows"][1:]))
    return "\n".join(lines)


def plot(res: dict) -> list:
    fig, ax = C.figure(2, 1, (9, 7))
    ref = C.series(res["cases"][0])
    for label, c in zip(RISES, res["cases"]):
        s = C.series(c)
        ax[0][0].plot(s["t"] * 1e3, s["mesh_force"], lw=0.8, label=label)
        n = min(len(s["t"]), len(ref["t"]))
        ax[1][0].plot(s["t"][:n] * 1e3, s["mesh_force"][:n] - ref["mesh_force"][:n], lw=0.8, label=label)
    ax[0][0].set(title="dynamic mesh force (both helices), last 10 mesh periods (Fig. 12)", xlabel="t [ms]",
                 ylabel="F [N]")
    ax[1][0].set(title="difference from thermal off", xlabel="t [ms]", ylabel="ΔF [N]")
    for a in ax[:, 0]:
        a.legend(fontsize=7)
    paths = [C.save(fig, "temperature_rise", "mesh_force.png")]
    fig, ax = C.figure(1, 2)
    for label, c in zip(RISES, res["cases"]):
        s = C.series(c)
        for j in range(2):                 # x, y
            ax[0][j].plot(s["gear.displacement"][:, j] * 1e6, s["gear.velocity"][:, j] * 1e3, lw=0.6, label=label)
    for j, axis in enumerate("xy"):
        ax[0][j].set(title=f"gear phase plane, {axis} (Fig. 13)", xlabel=f"{axis} [µm]", ylabel=f"v_{axis} [mm/s]")
        ax[0][j].legend(fontsize=7)
    paths.append(C.save(fig, "temperature_rise", "phase_plane.png"))
    return paths


def main(argv: list[str]) -> int:
    opts = C.parse_args(argv)
    res = run(opts["coarse"], opts["workers"])
    print(f"temperature rise study ({'coarse' if res['coarse'] else 'full'}), {res['seconds']:.1f} s")
    print(table(res))
    print("json:", C.write_results("temperature_rise", {k: v for k, v in res.items() if k != "cases"}))
    print("plots:", *map(str, plot(res)))
    print(C.json.dumps({"study": "temperature_rise", "seconds": res["seconds"],
                        **{f"gear_vel_y_{r['case'].replace(' ', '')}": r["gear.velocity.y"] for r in res["rows"]}}))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
