"""Benchmark: cost of the EHL solvers in seconds, memory and machine-independent work units.

    python studies/benchmarks/ehl.py [--lmax 4] [--repeats 3] [--path-level 5] [--quick]

1. Point contact (M, L) = (20, 10) and (200, 10), finest level 1..LMAX (nested iteration:
   the time of level k includes the coarser ones): median wall time of REPEATS solves,
   peak traced memory, work units, Hc, Hmin, their Richardson estimates, the error
   against the finest level, and the cost ratio per refinement.  The cheapest level whose
   Hc and Hmin are both within 1 % of the finest level is reported with its time and WU.
   One work unit (WU) = the median time of one finest-grid residual evaluation of that
   level, film and DC-FFT deflection included (``Level.reynolds_residual``), measured
   in the same run: seconds / WU is the cost in residual evaluations.
2. ``tol``-driven solves: ``solve_point(M, L, tol=0.01, max_level=LMAX)`` (levels chosen
   by the solver).
   Each case is solved by both point methods, ``method='fas'`` (full multigrid, FD; a
   failed multigrid solve falls back to Newton, marked "fallback") and ``'newton'`` (FE
   Newton-Krylov), in the same run.
3. Line contact, a 41-position path of a gear mesh (load, radius and speed varying
   smoothly; Roelands + Dowson-Higginson): the path solved position by position with
   warm starts (``start=``, ``reuse=``), against the median of cold solves of single
   positions of it.
4. Point contact, a 41-position path (M = 20 (1 + 0.5 sin(pi s)), L = 10, 129^2, FAS):
   warm starts from the previous position with the secant predictor (``reuse=``) against
   the median cold solve, in seconds and WU; warm films against cold solves.
Prints tables and one JSON line (the last).
"""

from __future__ import annotations

import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import argparse
import json
import statistics
import time

import numpy as np

from femgear.perf import measure
from femgear.physics.contact.film import nvm_central
from femgear.physics.ehl.core import params as pr
from femgear.physics.ehl.core.domain import default_domain
from femgear.physics.ehl.core.grid import Grid
from femgear.physics.ehl.core.rheology import Rheology
from femgear.physics.ehl.dimensional import EHLOil, solve_line_dimensional
from femgear.physics.ehl.fe.level import Level
from femgear.physics.ehl.fe.line import line_level
from femgear.physics.ehl.point import solve_point

CASES = ((20.0, 10.0), (200.0, 10.0))


def setup() -> argparse.Namespace:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--lmax", type=int, default=4, help="finest level (4 = 257x257)")
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--path-level", type=int, default=5, help="line level of the path (5)")
    ap.add_argument("--quick", action="store_true", help="levels 1-2, 1 repeat, short path (CI)")
    return ap.parse_args()


def work_unit(M: float, L: float, level: int, result) -> float:
    """Median seconds of one residual evaluation (film + deflection + Reynolds) on the
    grid of ``level`` at the solved state of ``result`` (interpolated onto that grid)."""
    lv = Level(Rheology(pr.point_alpha_bar(M, L)), pr.point_lam_bar(M), pr.POINT_LOAD,
               grid=Grid.build(default_domain(), level), sd_factor=1.0)
    from scipy.interpolate import RegularGridInterpolator

    P = RegularGridInterpolator((result.y, result.x), result.P)(np.column_stack([lv.Y, lv.X]))
    PI = P[lv.interior]
    lv.reynolds_residual(PI, result.H0)
    times = []
    for _ in range(max(5, 40 // (level + 1))):
        t = time.perf_counter()
        lv.reynolds_residual(PI, result.H0)
        times.append(time.perf_counter() - t)
    return statistics.median(times)


def point_table(M: float, L: float, lmax: int, repeats: int, method: str = "newton") -> dict:
    rows = []
    for lev in range(1 if method == "newton" else 2, lmax + 1):
        m = measure(lambda: solve_point(M, L, level=lev, method=method), repeats=repeats)
        r = m.value
        wu = work_unit(M, L, lev, r)
        rows.append({"level": lev, "nodes": r.nodes, "seconds": m.seconds, "wu_seconds": wu,
                     "work_units": m.seconds / wu, "peak_MB": m.peak_bytes / 2**20,
                     "Hc": r.Hc, "Hmin": r.Hmin, "est_Hc": r.error_estimate["Hc"],
                     "est_Hmin": r.error_estimate["Hmin"], "newton": r.history["level"].count(r.nodes),
                     "fallback": "fallback" in r.history})
    fin = rows[-1]
    first = None
    for k, row in enumerate(rows):
        row["err_Hc_%"] = 100 * (row["Hc"] / fin["Hc"] - 1)
        row["err_Hmin_%"] = 100 * (row["Hmin"] / fin["Hmin"] - 1)
        row["cost_ratio"] = None if k == 0 else row["seconds"] / rows[k - 1]["seconds"]
        if first is None and k < len(rows) - 1 and max(abs(row["err_Hc_%"]), abs(row["err_Hmin_%"])) <= 1.0:
            first = row
    nvm = float(nvm_central(M, L))
    print(f"\n(M, L) = ({M:g}, {L:g}), method {method}   NVM Hc = {nvm:.4f}")
    print(f"{'level':>5} {'nodes':>6} {'s (med)':>8} {'WU [ms]':>8} {'WU':>6} {'peak MB':>8} {'Hc':>7} "
          f"{'Hmin':>7} {'est Hc %':>8} {'est Hm %':>8} {'its':>6} {'Hc vs fin %':>11} "
          f"{'Hm vs fin %':>11} {'x prev':>6}")
    for row in rows:
        ratio = "" if row["cost_ratio"] is None else f"{row['cost_ratio']:.2f}"
        est = [("" if row[k] is None else f"{100 * row[k]:.3f}") for k in ("est_Hc", "est_Hmin")]
        print(f"{row['level']:>5} {row['nodes']:>6} {row['seconds']:>8.2f} {1e3 * row['wu_seconds']:>8.2f} "
              f"{row['work_units']:>6.0f} {row['peak_MB']:>8.1f} {row['Hc']:>7.4f} {row['Hmin']:>7.4f} "
              f"{est[0]:>8} {est[1]:>8} {row['newton']:>6} {row['err_Hc_%']:>+11.3f} "
              f"{row['err_Hmin_%']:>+11.3f} {ratio:>6}{'  fallback' if row['fallback'] else ''}")
    if first:
        print(f"Hc and Hmin within 1 % of the finest level from level {first['level']} "
              f"({first['nodes']} nodes): {first['seconds']:.2f} s, {first['work_units']:.0f} WU; "
              f"Hc vs NVM {100 * (first['Hc'] / nvm - 1):+.2f} %")
    ratios = [row["cost_ratio"] for row in rows[1:] if row["level"] >= 3]
    if ratios:
        print(f"cost per refinement from 129^2 on: {', '.join(f'{x:.2f}' for x in ratios)}")
    return {"rows": rows, "first_within_1pct": first and first["level"], "nvm": nvm}


def tol_runs(repeats: int, lmax: int) -> dict:
    out = {}
    for M, L in CASES:  # method 'auto': FAS at (20, 10), Newton at (200, 10)
        m = measure(lambda: solve_point(M, L, tol=0.01, max_level=lmax), repeats=repeats)
        r = m.value
        out[f"M{M:g}_L{L:g}"] = {"seconds": m.seconds, "nodes": r.nodes, "Hc": r.Hc, "Hmin": r.Hmin,
                                 "error_estimate": r.error_estimate, "flags": list(r.flags)}
        print(f"tol = 1 %: (M, L) = ({M:g}, {L:g}) -> {r.nodes} nodes, {m.seconds:.2f} s, "
              f"Hc {r.Hc:.4f} (est {100 * r.error_estimate['Hc']:.2f} %), Hmin {r.Hmin:.4f} "
              f"(est {100 * r.error_estimate['Hmin']:.2f} %), flags {list(r.flags) or 'none'}")
    return out


def path_run(level: int, n: int, repeats: int) -> dict:
    """A mesh-cycle-like path: load share 0.7-1 of 300 kN/m, R 6-16 mm, u_e 10-12 m/s.

    Each of ``repeats`` rounds times the cold solves of 9 positions spread along the path
    and then the warm path, back to back; the ratio of a round is the warm path over the
    median cold solve of that round, and the reported ratio is the median of the rounds'
    ratios (a load change on the shared machine hits both sides of one round). Beside it,
    the median over the rounds of the same ratio in process CPU time against the mean cold
    solve (less sensitive to the other users of a shared machine)."""
    oil = EHLOil(eta0=0.02, alpha=2.0e-8, viscosity="roelands", compressible=True)
    E = 2.26e11
    s = np.linspace(0.0, 1.0, n)
    w, R, ue = 3e5 * (0.7 + 0.3 * np.sin(np.pi * s)), 0.006 + 0.01 * s, 10.0 + 2.0 * s

    def cold(i):
        return solve_line_dimensional(w[i], R[i], ue[i], E, oil, level=level)

    def path():
        prev, reuse, out = None, {}, []
        for i in range(n):
            r = solve_line_dimensional(w[i], R[i], ue[i], E, oil, level=level, start=prev, reuse=reuse)
            prev = r.result
            out.append(r)
        return out

    picks = list(range(0, n, max(1, n // 8)))
    ref = [cold(i) for i in picks]  # also warms up imports and caches
    rounds, cpu = [], []
    for _ in range(max(3, repeats)):
        c0 = time.process_time()
        cold_s = statistics.median(measure(lambda i=i: cold(i), repeats=1, trace_memory=False).seconds
                                   for i in picks)
        c1 = time.process_time()
        m = measure(path, repeats=1, trace_memory=False)
        rounds.append((m.seconds / cold_s, m.seconds, cold_s))
        cpu.append((time.process_time() - c1) / ((c1 - c0) / len(picks)))
    ratio, path_s, cold_s = sorted(rounds)[len(rounds) // 2]
    warm = m.value
    dev = {k: max(abs(getattr(warm[i].result, k) / getattr(c.result, k) - 1) for i, c in zip(picks, ref))
           for k in ("Hc", "Hmin", "Pmax")}
    its = [r.result.iterations for r in warm]
    wu = line_work_unit(warm[n // 2], oil)
    print(f"\nline path, {n} positions, level {level} ({16 * 2**level + 1} nodes), median of "
          f"{len(rounds)} rounds: warm path {path_s:.2f} s = {ratio:.1f} x one cold solve ({cold_s:.3f} s; "
          f"rounds {', '.join(f'{r[0]:.1f}' for r in rounds)}); per position {path_s / n / wu:.0f} WU, "
          f"cold {cold_s / wu:.0f} WU (WU {1e3 * wu:.3f} ms); Newton iterations warm "
          f"{statistics.median(its[1:]):.0f} vs cold {statistics.median(r.result.iterations for r in ref):.0f}; "
          f"max |warm/cold - 1|: Hc {dev['Hc']:.1e}, Hmin {dev['Hmin']:.1e}, Pmax {dev['Pmax']:.1e}; "
          f"process-CPU ratio (mean cold solve) {statistics.median(cpu):.1f}")
    return {"positions": n, "level": level, "path_seconds": path_s, "cold_seconds": cold_s,
            "ratio": ratio, "ratios": [r[0] for r in rounds], "cpu_ratio": statistics.median(cpu),
            "wu_seconds": wu,
            "max_rel_dev_hc": dev["Hc"], "max_rel_dev": dev}


def line_work_unit(r, oil: EHLOil) -> float:
    """Median seconds of one line residual evaluation (film with the dense log-kernel
    deflection + Reynolds) at the state of the dimensional line solution ``r``, on its grid."""
    lv = line_level(r.M, r.L, r.result.x, rheology=dict(viscosity=oil.viscosity, ph=r.ph,
                    z=oil.roelands_z(), compressible=oil.compressible))
    PI = r.result.P[lv.interior]
    lv.reynolds_residual(PI, r.result.H0)
    times = []
    for _ in range(20):
        t = time.perf_counter()
        lv.reynolds_residual(PI, r.result.H0)
        times.append(time.perf_counter() - t)
    return statistics.median(times)


def point_path(level: int, n: int, repeats: int) -> dict:
    """A load path M = 20 (1 + 0.5 sin(pi s)) at L = 10 by FAS with warm starts (``start=``
    the previous position, ``reuse=`` the secant predictor), against the median cold solve;
    the warm films against cold solves at every sixth position."""
    Ms = 20.0 * (1.0 + 0.5 * np.sin(np.pi * np.linspace(0.0, 1.0, n)))
    picks = list(range(0, n, max(1, n // 6)))
    colds = {i: measure(lambda i=i: solve_point(Ms[i], 10.0, level=level, method="fas"),
                        repeats=repeats, trace_memory=False) for i in picks}
    cold_s = statistics.median(m.seconds for m in colds.values())

    def path():
        prev, reuse, out = None, {}, []
        for M in Ms:
            prev = solve_point(M, 10.0, level=level, method="fas", start=prev, reuse=reuse)
            out.append(prev)
        return out

    m = measure(path, repeats=max(1, repeats // 2), trace_memory=False)
    wu = work_unit(20.0, 10.0, level, m.value[0])
    dev = {k: max(abs(getattr(m.value[i], k) / getattr(c.value, k) - 1) for i, c in colds.items())
           for k in ("Hc", "Hmin")}
    fine = [r.levels[-1]["iterations"] for r in m.value[1:]]
    print(f"\npoint path, {n} positions, level {level}, FAS: warm path {m.seconds:.2f} s "
          f"({m.seconds / wu:.0f} WU) = {m.seconds / cold_s:.1f} x one cold solve ({cold_s:.3f} s, "
          f"{cold_s / wu:.0f} WU); finest-grid cycles per warm solve: median "
          f"{statistics.median(fine):.0f}, max {max(fine)}; max |warm/cold - 1|: Hc {dev['Hc']:.1e}, "
          f"Hmin {dev['Hmin']:.1e}")
    return {"positions": n, "level": level, "path_seconds": m.seconds, "cold_seconds": cold_s,
            "ratio": m.seconds / cold_s, "wu_seconds": wu, "path_wu": m.seconds / wu,
            "cold_wu": cold_s / wu, "max_rel_dev_hc": dev["Hc"], "max_rel_dev_hmin": dev["Hmin"],
            "fine_cycles_median": statistics.median(fine)}


def run(args: argparse.Namespace) -> dict:
    lmax = 2 if args.quick else args.lmax
    repeats = 1 if args.quick else args.repeats
    out = {"point": {f"M{M:g}_L{L:g}": point_table(M, L, lmax, repeats) for M, L in CASES}}
    # FAS at (20, 10); (200, 10) lies outside its range (alpha_bar 21: method "auto" -> Newton)
    out["point_fas"] = {f"M{M:g}_L{L:g}": point_table(M, L, lmax, repeats, "fas") for M, L in CASES[:1]}
    print()
    out["tol"] = tol_runs(repeats, lmax)
    out["path"] = path_run(args.path_level, 9 if args.quick else 41, repeats)
    out["point_path"] = point_path(2 if args.quick else 3, 9 if args.quick else 41, repeats)
    return out


if __name__ == "__main__":
    res = run(setup())
    print(json.dumps({"benchmark": "ehl", **res}, separators=(",", ":"), default=float))
