"""The FZG rig predicted on conditions it was not fitted to: a path model per accelerometer, fitted on half of
Table 7 and tested on the other half.

    python studies/paper/rig_holdout.py [--json FILE] [--workers=2] [--recompute]

Why.  femgear computes the shaft's motion at its bearing stations; the rig measures on the housing, behind a path
(bearing, housing wall, accelerometer mount) that neither the paper nor femgear models and whose FRF is not
published (docs/validation/paper.md, "Why the rig comparison fails").  The honest use of the rig data is to fit a
path with few parameters on part of it and to predict the rest.

The source.  The same runs as today's unfitted comparison (``studies/paper/rig_conditions.py --ltca``: the coupled
baseline at the 15 speeds × torques, the ``ltca`` mesh stiffness with the test-gear modifications chosen before
any result, free torques, sampled at ≥ 25.6 kHz): the stiffness level the unfitted 13/30 used, so the two
rows compare the path and nothing else.  Each condition's record gives the bearing forces F_j(t) (the load of
the shaft on bearing j, :mod:`femgear.system.dynamics.bearings`) and, for the unfitted row, the stations'
accelerations; cached under ``out/rig_holdout/records`` (``--recompute`` runs them again).

The path model (chosen before any fit was run).  Accelerometer p (1: the pinion's bearing housing, 2: the
gear's) reads a_j(t) = h_p * (F_j · n)(t) for each of its member's two stations j, n the transverse line of
action (the rig's accelerometer axis, as in the unfitted comparison), with the accelerance of a gain and one mode
(:func:`femgear.physics.housing.frf.modal_accelerance`: g_p, f_n,p, ζ_p; 3 parameters per accelerometer), then the
rig's chain (4th-order Butterworth at 5 kHz) and Table 7's "maximum acceleration": max over time of |a|, max over
the two stations.  The gain-only model (g_p alone: the mass line) is reported beside it.  Fit: least squares of
ln(model/test) over the fitted values (g_p in closed form, (f_n, ζ) on a grid then Nelder–Mead; f_n ∈ 300 Hz …
15 kHz, ζ ∈ 0.01 … 0.5).

The split (chosen before any fit was run, written here first): the 30 values are 15 conditions (speed index
a = 0 … 4 for 100 … 500 rpm, torque index b = 0 … 2 for 100 … 200 N m) × 2 accelerometers (p = 0, 1); the value is
FITTED when a + b + p is even, HELD OUT when it is odd: a checkerboard over speed × torque that alternates between
the two accelerometers, 8 values of point 1 and 7 of point 2 fitted (15), the other 15 held out, every speed and
every torque on both sides for both accelerometers.

Output: the table of the 30 values (fitted or held out, test, unfitted, fitted path), the counts within a factor 2
and within 20 % on the held-out 15 for the fitted path, the gain-only path and the unfitted model (the same 15),
and ``--json FILE`` with ``held_out_within_2x``, ``held_out_within_20pct``, ``held_out_total``, ``fitted_on`` and
``parameters``.  Every table and figure says "fitted on conditions …".
"""

from __future__ import annotations

import hashlib
import json
import math
import sys
import time
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

import numpy as np

try:
    from studies import _common as C
    from studies.paper import rig_conditions as R
except ImportError:
    sys.path.insert(0, str(Path(__file__).resolve().parents[2]))
    from studies import _common as C
    from studies.paper import rig_conditions as R

CONDITIONS = [(n, T) for n in R.SPEEDS for T in R.TORQUES]
RECORDS = C.ROOT / "out" / "rig_holdout" / "records"
F_N_BOUNDS = (300.0, 15000.0)
ZETA_BOUNDS = (0.01, 0.5)


def fitted(a: int, b: int, p: int) -> bool:
    """The split (module docstring): value (speed index a, torque index b, accelerometer p) is fitted when a + b + p
    is even."""
    return (a + b + p) % 2 == 0


def split() -> tuple[list[tuple[int, int]], list[tuple[int, int]]]:
    """(fitted, held out): lists of (condition index, accelerometer 0/1)."""
    fit, held = [], []
    for i, (n, T) in enumerate(CONDITIONS):
        a, b = R.SPEEDS.index(n), R.TORQUES.index(T)
        for p in range(2):
            (fit if fitted(a, b, p) else held).append((i, p))
    return fit, held


def setup() -> dict:
    """What runs: the 15 conditions' overrides and the split (fitted / held out) of the 30 values."""
    fit, held = split()
    return {"conditions": {c: overrides(*c) for c in CONDITIONS}, "fitted": fit, "held_out": held}


def overrides(speed: float, torque: float) -> list[str]:
    """The unfitted comparison's condition (``rig_conditions.py --ltca``)."""
    return R.setup(speed, torque) + R.TEST_GEAR_MODIFICATIONS


def _record_path(speed: float, torque: float) -> Path:
    key = hashlib.sha1(json.dumps(overrides(speed, torque)).encode()).hexdigest()[:12]
    return RECORDS / f"{int(speed)}rpm_{int(torque)}Nm_{key}.npz"


def record(args) -> dict:
    """Run one condition; its steady record: t, the bearing forces F (n_t, 4, 3) [N], the stations' accelerations
    (n_t, 4, 3) [m/s²], the mesh frequency and α_wt."""
    speed, torque = args
    result = C.run(overrides(speed, torque))
    r = result.coupled.state.dynamics.response
    out = {"t": r.t, "force": r.bearings.force, "acceleration": r.bearing_acceleration,
           "mesh_frequency": r.mesh_frequency, "alpha_wt": result.case.pair.alpha_wt, "seconds": result.seconds}
    path = _record_path(speed, torque)
    path.parent.mkdir(parents=True, exist_ok=True)
    np.savez(path, **out)
    return out


def records(workers: int = 2, recompute: bool = False) -> list[dict]:
    """The 15 records, from the cache where present."""
    todo = [c for c in CONDITIONS if recompute or not _record_path(*c).exists()]
    if todo:
        if workers <= 1:
            for c in todo:
                record(c)
        else:
            with ProcessPoolExecutor(max_workers=min(workers, len(todo))) as pool:
                list(pool.map(record, todo))
    return [dict(np.load(_record_path(*c))) for c in CONDITIONS]


def _window(rec: dict) -> slice:
    t, fm = rec["t"], float(rec["mesh_frequency"])
    dt = float(t[1] - t[0])
    n = min(t.size, int(round(math.floor(t.size * dt * fm + 1e-6) / (fm * dt))))
    return slice(t.size - n, t.size)


def prepare(rec: dict) -> dict:
    """The line-of-action bearing forces of the record's last whole mesh periods and their spectrum."""
    a = float(rec["alpha_wt"])
    n_dir = np.array([math.sin(a), math.cos(a)])
    w = _window(rec)
    F = rec["force"][w][:, :, :2] @ n_dir                                        # (n, 4)
    t = rec["t"][w]
    dt = float(t[1] - t[0])
    return {"t": t, "spectrum": np.fft.rfft(F - F.mean(axis=0), axis=0), "f": np.fft.rfftfreq(t.size, dt),
            "n": t.size, "unfitted": R.rig_measures(rec["t"], rec["acceleration"], np.array([*n_dir, 0.0]),
                                                    float(rec["mesh_frequency"]))}


def peak(prep: dict, p: int, gain: float, f_n: float | None, zeta: float) -> float:
    """Table 7's measure of accelerometer p through the path (module docstring)."""
    from femgear.physics.housing.frf import modal_accelerance

    H = modal_accelerance(prep["f"], gain, f_n, zeta)
    a = np.fft.irfft(H[:, None] * prep["spectrum"][:, 2 * p:2 * p + 2], n=prep["n"], axis=0)   # (n, 2 stations)
    # the record is periodic over its whole mesh periods: filter three repeats, keep the last (the filter's start-up
    # transient is gone)
    t3 = np.arange(3 * prep["n"]) * float(prep["t"][1] - prep["t"][0])
    filt = C.rig_filter(t3, np.tile(a, (3, 1)))[-prep["n"]:]
    return float(np.abs(filt).max())


def fit_point(preps: list[dict], tests: np.ndarray, p: int, modal: bool) -> dict:
    """The path parameters of accelerometer p fitted on the given records and test values."""
    from scipy.optimize import minimize

    logt = np.log(tests)

    def shape(x):                     # (ln f_n, ln ζ) → ln of the unit-gain predictions
        f_n, zeta = (math.exp(x[0]), math.exp(x[1])) if modal else (None, 0.0)
        return np.log([peak(pr, p, 1.0, f_n, zeta) for pr in preps])

    def cost(x):
        r = logt - shape(x)
        return float(np.sum((r - r.mean()) ** 2))

    if modal:
        grid = [(math.log(f), math.log(z)) for f in np.geomspace(*F_N_BOUNDS, 36) for z in np.geomspace(*ZETA_BOUNDS, 7)]
        x0 = min(grid, key=cost)
        lo, hi = np.log([F_N_BOUNDS[0], ZETA_BOUNDS[0]]), np.log([F_N_BOUNDS[1], ZETA_BOUNDS[1]])
        res = minimize(lambda x: cost(np.clip(x, lo, hi)), x0, method="Nelder-Mead",
                       options={"xatol": 1e-4, "fatol": 1e-10, "maxiter": 400})
        x = np.clip(res.x, lo, hi)
        f_n, zeta = math.exp(x[0]), math.exp(x[1])
    else:
        x, f_n, zeta = None, None, 0.0
    gain = math.exp(float(np.mean(logt - shape(x))))
    return {"gain": gain, "natural_frequency": f_n, "damping_ratio": zeta if modal else None}


def counts(pred: np.ndarray, test: np.ndarray) -> dict:
    ratio = pred / test
    return {"within_2x": int(np.sum(np.abs(np.log(ratio)) <= math.log(2))),
            "within_20pct": int(np.sum(np.abs(ratio - 1) < 0.2)), "total": int(ratio.size),
            "ratio_min": float(ratio.min()), "ratio_max": float(ratio.max())}


def run(workers: int = 2, recompute: bool = False) -> dict:
    t0 = time.perf_counter()
    recs = records(workers, recompute)
    preps = [prepare(r) for r in recs]
    test = np.array([[C.PAPER_TABLE7[(int(n), int(T))][i] for i in (1, 3)] for n, T in CONDITIONS])
    unfitted = np.array([[pr["unfitted"]["peak1"], pr["unfitted"]["peak2"]] for pr in preps])
    fit, held = split()
    models = {}
    for label, modal in (("gain_and_mode", True), ("gain_only", False)):
        params = {}
        pred = np.zeros_like(test)
        for p in range(2):
            idx = [i for i, q in fit if q == p]
            params[f"point{p + 1}"] = prm = fit_point([preps[i] for i in idx], test[idx, p], p, modal)
            pred[:, p] = [peak(pr, p, prm["gain"], prm["natural_frequency"], prm["damping_ratio"] or 0.0)
                          for pr in preps]
        models[label] = {"parameters": params, "prediction": pred,
                         "held_out": counts(np.array([pred[i, p] for i, p in held]), np.array([test[i, p] for i, p in held])),
                         "fitted": counts(np.array([pred[i, p] for i, p in fit]), np.array([test[i, p] for i, p in fit]))}
    primary = models["gain_and_mode"]
    held_unfitted = counts(np.array([unfitted[i, p] for i, p in held]), np.array([test[i, p] for i, p in held]))
    fitted_on = [{"speed_rpm": CONDITIONS[i][0], "torque_Nm": CONDITIONS[i][1], "point": p + 1} for i, p in fit]
    return {"study": "rig_holdout", "stiffness": "ltca (rig_conditions.py --ltca test gears)", "conditions": CONDITIONS,
            "test": test, "unfitted": unfitted, "unfitted_all": counts(unfitted.ravel(), test.ravel()),
            "unfitted_held_out": held_unfitted, "models": models, "fitted_on": fitted_on,
            "held_out_within_2x": primary["held_out"]["within_2x"],
            "held_out_within_20pct": primary["held_out"]["within_20pct"],
            "held_out_total": primary["held_out"]["total"], "parameters": primary["parameters"],
            "seconds": time.perf_counter() - t0}


def fitted_label(res: dict) -> str:
    pts = {1: [], 2: []}
    for f in res["fitted_on"]:
        pts[f["point"]].append(f"{f['speed_rpm']:.0f}/{f['torque_Nm']:.0f}")
    return ("fitted on conditions (rpm/N m) " + "; ".join(f"point {p}: " + ", ".join(v) for p, v in pts.items()))


def table(res: dict) -> str:
    fit = {(f["speed_rpm"], f["torque_Nm"], f["point"]) for f in res["fitted_on"]}
    pm, pg = res["models"]["gain_and_mode"]["prediction"], res["models"]["gain_only"]["prediction"]
    lines = [f"FZG rig, Table 7 'maximum acceleration' [m/s²]: path model per accelerometer, {fitted_label(res)}",
             f"{'rpm':>4s} {'N m':>4s} {'pt':>2s} {'set':>8s} | {'test':>7s} {'unfitted':>8s} {'ratio':>6s} | "
             f"{'path':>7s} {'ratio':>6s} | {'gain':>7s} {'ratio':>6s}"]
    for i, (n, T) in enumerate(res["conditions"]):
        for p in range(2):
            t = res["test"][i][p]
            tag = "fitted" if (n, T, p + 1) in fit else "held-out"
            lines.append(f"{n:4.0f} {T:4.0f} {p + 1:2d} {tag:>8s} | {t:7.4f} {res['unfitted'][i][p]:8.3g} "
                         f"{res['unfitted'][i][p] / t:6.2f} | {pm[i][p]:7.3g} {pm[i][p] / t:6.2f} | "
                         f"{pg[i][p]:7.3g} {pg[i][p] / t:6.2f}")
    for label, m in res["models"].items():
        prm = "; ".join(f"{k}: g {v['gain']:.4g} 1/kg" + (f", f_n {v['natural_frequency']:.4g} Hz, ζ {v['damping_ratio']:.3g}"
                                                           if v["natural_frequency"] else "")
                        for k, v in m["parameters"].items())
        h, f = m["held_out"], m["fitted"]
        lines.append(f"{label} ({prm}): held out {h['within_2x']}/{h['total']} within 2x, {h['within_20pct']}/"
                     f"{h['total']} within 20 % (ratio {h['ratio_min']:.2f}-{h['ratio_max']:.2f}); on its fitted "
                     f"values {f['within_2x']}/{f['total']} and {f['within_20pct']}/{f['total']}")
    u, ua = res["unfitted_held_out"], res["unfitted_all"]
    lines.append(f"unfitted (bearing-station acceleration, no path): the same held-out values {u['within_2x']}/"
                 f"{u['total']} within 2x, {u['within_20pct']}/{u['total']} within 20 %; all 30: {ua['within_2x']}/30 "
                 f"and {ua['within_20pct']}/30 (ratio {ua['ratio_min']:.2f}-{ua['ratio_max']:.2f})")
    return "\n".join(lines)


def plot(res: dict):
    fig, ax = C.figure(1, 2)
    fit = {(f["speed_rpm"], f["torque_Nm"], f["point"]) for f in res["fitted_on"]}
    for p in range(2):
        a = ax[0][p]
        for T in R.TORQUES:
            idx = [i for i, c in enumerate(res["conditions"]) if c[1] == T]
            rpm = [res["conditions"][i][0] for i in idx]
            line, = a.plot(rpm, np.asarray(res["test"])[idx, p], "o--", mfc="none", label=f"test {T:.0f} N m")
            pred = np.asarray(res["models"]["gain_and_mode"]["prediction"])[idx, p]
            a.plot(rpm, pred, "-", color=line.get_color(), lw=1.0, label=f"path model {T:.0f} N m")
            for r_, y in zip(rpm, pred):
                a.plot(r_, y, "s" if (r_, T, p + 1) in fit else "x", color=line.get_color(), ms=5)
        a.set(title=f"point {p + 1}: path model (■ fitted, × held out)", xlabel="input speed [rpm]",
              ylabel="max |a| [m/s²]", yscale="log")
        a.legend(fontsize=6)
    fig.suptitle(fitted_label(res), fontsize=7)
    return C.save(fig, "rig_holdout", "rig_holdout.png")


def main(argv: list[str]) -> int:
    argv = list(argv)
    if "--json" in argv and argv.index("--json") + 1 < len(argv):     # --json FILE as well as --json=FILE
        k = argv.index("--json")
        argv[k:k + 2] = [f"--json={argv[k + 1]}"]
    opts = C.parse_args(argv)
    res = run(int(opts.get("workers", 2)), bool(opts.get("recompute", False)))
    print(table(res))
    if "json" in opts:
        Path(str(opts["json"])).write_text(json.dumps(C.jsonable({k: res[k] for k in (
            "held_out_within_2x", "held_out_within_20pct", "held_out_total", "fitted_on", "parameters",
            "unfitted_held_out", "unfitted_all", "stiffness", "models")}), indent=1))
        print("json:", opts["json"])
    print("results:", C.write_results("rig_holdout", res))
    print("plot:", plot(res))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
