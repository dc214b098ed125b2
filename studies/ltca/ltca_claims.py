"""The paper's wear and temperature claims re-run with the LTCA mesh (3-D FE teeth) beside PEM.

    python studies/ltca/ltca_claims.py [--coarse] [--workers=2]

The claims of README "femgear against the paper's claims" that studies/paper/wear_cycles.py
(wear 0 → 1e6 → 3e6 cycles: gear y and v_y grow; the paper: y +8 %, v_y +50 %) and
studies/paper/temperature_rise.py (a 45 K flank temperature rise raises velocity, slightly
lowers displacement) measure, on the coupled baseline with ``physics.stiffness`` =
``pem`` (the paper's energy method) and ``ltca`` (unmodified flanks, as the paper's gear).
With ``pem`` the wear and thermal deviations enter as contact-line means (drive/coast
deviation tables, :mod:`femgear.system.coupling.profile`); with ``ltca`` each coupling pass
re-runs the LTCA on the worn and expanded drive flanks (the compliance is reused;
:func:`femgear.system.dynamics.build.with_deviated_tooth_contact`) and the coast flanks take the
contact-line mean of the thermal expansion.  Amplitudes: half peak-to-peak of the member centres, steady state; Δ % against
the new gear (wear cases) or against thermal off (45 K).  With ``ltca`` the wear and the
lubrication load are shared along the contact lines like the LTCA cycles (the wear from the
unworn cycle, the contact load of each pass from its deviated cycle:
:func:`femgear.system.coupling.setup.ltca_reference`).  Then the cost of a coupling pass (median
wall time of the LTCA re-run, the dynamics including it, the wear, the contact response),
the passes to convergence and the largest wear depth.  Prints a table and a JSON line;
writes ``out/ltca_claims/ltca_claims.json``.
"""

from __future__ import annotations

import sys

import numpy as np

try:
    from studies import _common as C
except ImportError:
    import pathlib
    import sys

    sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2]))
    from studies import _common as C

CASES = {"new": ["wear.cycles=0.0"], "wear 1e6": ["wear.cycles=1000000.0"], "wear 3e6": ["wear.cycles=3000000.0"],
         "thermal off": ['physics.thermal="none"'], "45 K": ["thermal.flank_temperature_rise=45.0"]}
LEVELS = ("pem", "ltca")
KEYS = (("gear", "displacement", "y"), ("gear", "velocity", "y"), ("gear", "displacement", "x"),
        ("gear", "velocity", "x"))


def setup() -> list[list[str]]:
    """The runs: each case's overrides at each stiffness level (LEVELS × CASES, in that order)."""
    return [ov + [f'physics.stiffness="{lv}"'] for lv in LEVELS for ov in CASES.values()]


def run(coarse: bool = False, workers: int = 2) -> dict:
    jobs = setup()
    cases = C.run_cases(jobs, coarse=coarse, workers=workers, timed=True)
    out = {"coarse": coarse, "levels": {}}
    for i, lv in enumerate(LEVELS):
        rows = {}
        for j, name in enumerate(CASES):
            c, timings = cases[i * len(CASES) + j]
            rows[name] = {f"{m}.{q}.{ax}": C.amplitude(c, m, q, ax) for m, q, ax in KEYS}
            rows[name]["converged"] = c.coupled.converged
            rows[name]["lte_um"] = 1e6 * c.coupled.state.lte_peak_to_peak     # loaded TE p-p of the deviated flanks (ltca)
            rows[name]["passes"] = len(c.coupled.history.iteration) - 1
            rows[name]["wear_max_um"] = 1e6 * float(np.max(C.wear(c)))
            rows[name]["pass_seconds"] = {k: float(np.median([t[k] for t in timings]))
                                          for k in ("ltca", "dynamics", "wear", "contact")} if timings else {}
        for name, r in rows.items():         # wear against the new gear, 45 K against thermal off
            base = rows["thermal off" if name == "45 K" else "new"]
            r["change_percent"] = {k: 100 * (r[k] / base[k] - 1) for k in (f"{m}.{q}.{ax}" for m, q, ax in KEYS)}
        out["levels"][lv] = rows
    return out


def table(res: dict) -> str:
    head = f"{'stiffness':9s} {'case':>9s} | " + " | ".join(f"{m[0]} {ax}{'[µm]' if q == 'displacement' else '_v[m/s]':8s} (Δ%)"
                                                           for m, q, ax in KEYS) + " | LTE p-p [µm]"
    lines = [head, "-" * len(head)]
    for lv, rows in res["levels"].items():
        for name, r in rows.items():
            cells = [f"{r[f'{m}.{q}.{ax}']:10.4g} ({r['change_percent'][f'{m}.{q}.{ax}']:+6.1f})" for m, q, ax in KEYS]
            lines.append(f"{lv:9s} {name:>9s} | " + " | ".join(cells) + f" | {r['lte_um']:.3f}")
    lines += ["", "cost per coupling pass (median over the passes) [s]; passes; largest wear depth [µm]"]
    for lv, rows in res["levels"].items():
        for name, r in rows.items():
            t = "  ".join(f"{k} {v:.2f}" for k, v in r["pass_seconds"].items())
            lines.append(f"{lv:9s} {name:>9s} | {t} | passes {r['passes']} | wear {r['wear_max_um']:.2f}")
    return "\n".join(lines)


def main(argv: list[str]) -> int:
    opts = C.parse_args(argv)
    res = run(opts["coarse"], opts["workers"])
    print(table(res))
    print("json:", C.write_results("ltca_claims", res))
    print(C.json.dumps({"study": "ltca_claims", **{lv: {n: r["change_percent"] for n, r in rows.items()}
                                                   for lv, rows in res["levels"].items()}}))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
