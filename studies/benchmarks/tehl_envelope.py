"""Benchmark: the line TEHL over the gear envelope, and the speed figures of issue 43.

    python studies/benchmarks/tehl_envelope.py [--json FILE] [--quick] [--no-base]

Points (60, corners included): gear contacts built from an oil at its inlet temperature, the entrainment
speed u_e, the Hertz pressure p_H, the slide-to-roll ratio and the reduced radius R (steel, E' 226 GPa,
Eyring τ0 5 MPa, limiting shear 0.08 p): the 24 corners u_e 0.05 / 60 m/s x p_H 0.5 / 2.5 GPa x SRR 0 / +2 / −2
(one surface at rest) x the coldest and the hottest inlet, with the oil of each speed: ISO VG 220 at 20 / 150 °C
on R 10 mm at 0.05 m/s, the turbine oil VG 32 at 40 / 150 °C on R 20 mm at 60 m/s (colder, or on a smaller
radius, the contact leaves L ≤ 25 and M ≥ 1: VG 32 at 20 °C and 60 m/s has L = 36, any oil at 20 °C and 60 m/s
L ≥ 35); a turbo line (VG 32 at 50 °C, u_e 20–85
m/s, 0.8 GPa); heavy wind and mill contacts (PAO VG 320 at 60 °C, 1.5–2 GPa, R 40 mm); middle points (VG 100 at
80 °C).  Each point prints its Moes M and L, converged, thermal iterations, CPU seconds, h_c/h_c,iso, the energy
balance error and the film's error estimate; the summary the median and largest CPU seconds of the converged
points (targets ≤ 1 s and ≤ 5 s) and the M, L covered.

Also: opposite sliding at zero entrainment (the thermal-wedge dimple; not with ``--quick``), the isothermal
(M, L) = (1000, 4.3) to 1 % (target ≤ 0.5 s), the Galerkin (FE) solver of the base tree at
its own tolerance-driven grid for the same accuracy, the base tree's line TEHL at five contacts where it converges
(its default level 5 and level 6, against this tree at its tolerance; ``--no-base`` skips both).  The turbo
pair's ``tehl`` run against the baseline's is ``studies/benchmarks/tehl_pair_cost.py``.  CPU seconds are process
time (the machine is shared); timings are medians of 3 where marked.
"""

from __future__ import annotations

import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import argparse
import json
import math
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[2]
E_RED = 226e9
OILS = {  # eta0 [Pa s], alpha [1/Pa], beta_T [1/K], T0 [K], rho0 [kg/m3] (the zoo's oils at their reference)
    "VG32": (0.0183, 16e-9, 0.038, 323.15, 850.0),
    "VG320": (0.108, 13e-9, 0.040, 333.15, 830.0),
    "VG220": (0.0685, 20e-9, 0.045, 333.15, 869.0),
    "VG100": (0.0342, 20e-9, 0.041, 333.15, 859.0),
}


def points(quick: bool = False) -> list[dict]:
    """The envelope grid (oil, inlet °C, u_e m/s, p_H Pa, SRR, R m)."""
    pts = []
    for ue, oil, temps, R in ((0.05, "VG220", (20.0, 150.0), 0.01), (60.0, "VG32", (40.0, 150.0), 0.02)):
        for ph in (0.5e9, 2.5e9):
            for srr in (0.0, 2.0, -2.0):
                for T in temps:
                    pts.append(dict(oil=oil, T=T, ue=ue, ph=ph, srr=srr, R=R, group="corner"))
    for ue in (20.0, 40.0, 60.0, 85.0):
        for srr in (0.0, 0.4, -0.4):
            pts.append(dict(oil="VG32", T=50.0, ue=ue, ph=0.8e9, srr=srr, R=0.02, group="turbo"))
    for ue in (0.3, 1.0, 3.0):
        for ph in (1.5e9, 2.0e9):
            for srr in (0.0, 0.3):
                pts.append(dict(oil="VG320", T=60.0, ue=ue, ph=ph, srr=srr, R=0.04, group="heavy"))
    for ue in (1.0, 10.0):
        for ph in (1.0e9, 1.5e9):
            for srr in (0.0, 0.5, 1.0):
                pts.append(dict(oil="VG100", T=80.0, ue=ue, ph=ph, srr=srr, R=0.01, group="middle"))
    return pts[::6] if quick else pts


def _setup(oil: str):
    from femgear.physics.lubrication.flash import thermal_effusivity
    from femgear.physics.lubrication.oil import OilLaw
    from femgear.physics.tehl.energy import ThermalProps

    eta0, alpha, beta, T0, rho = OILS[oil]
    B = thermal_effusivity(38.0, 7850.0, 460.0)
    return OilLaw(eta0=eta0, alpha=alpha, beta_t=beta, T0=T0, rho0=rho), ThermalProps(
        k_oil=0.13, c_oil=2000.0, B1=B, B2=B, k1=38.0, k2=38.0)


def solve_point(p: dict, solver=None) -> dict:
    """One envelope point: its figures, or the error of a point that does not converge."""
    from femgear.physics.tehl.line import solve_tehl_line

    oil, props = _setup(p["oil"])
    w = 2.0 * math.pi * p["R"] * p["ph"] ** 2 / E_RED
    t = time.process_time()
    try:
        r = (solver or solve_tehl_line)(w, p["R"], p["ue"], p["srr"], p["T"] + 273.15, oil, E_RED, props, tau0=5e6,
                                        limiting_shear=0.08)
    except Exception as exc:    # a point that fails is reported, not hidden
        return {**p, "converged": False, "error": str(exc)[:200], "cpu": time.process_time() - t}
    return {**p, "converged": True, "M": r.M, "L": r.L, "iterations": r.iterations, "newton": r.newton_iterations,
            "nodes": r.nodes, "cpu": time.process_time() - t, "ratio": r.hc / r.hc_isothermal,
            "balance": abs(r.heat["balance_error"]), "estimate": max(r.error_estimate.values()), "mu": r.mu,
            "dT_max": r.dT_max, "layers": r.layers, "temperature_estimate": r.temperature_estimate,
            "continuation": len(r.history["continuation"])}


def isothermal_heavy(base: bool) -> dict:
    """(1000, 4.3) to 1 %: the FD solver (median of 3 CPU seconds) and the base tree's FE solver at its own
    tolerance-driven grid (one run)."""
    from femgear.physics.ehl.fd.line import solve_line_fd

    cpu = []
    for _ in range(3):
        t = time.process_time()
        r = solve_line_fd(1000.0, 4.3, tol=0.01)
        cpu.append(time.process_time() - t)
    out = {"fd": {"Hc": r.Hc, "Hmin": r.Hmin, "nodes": r.nodes, "estimate": max(r.error_estimate.values()),
                  "cpu": float(np.median(cpu))}}
    if base:
        with tempfile.TemporaryDirectory() as tmp:
            _export_base(Path(tmp))
            code = ("import time, json; from femgear_base.physics.ehl.fe.line import solve_line; "
                    "t = time.process_time(); r = solve_line(1000.0, 4.3, tol=0.01); "
                    "print(json.dumps({'Hc': r.Hc, 'Hmin': r.Hmin, 'nodes': r.nodes, 'estimate': "
                    "max(v for v in r.error_estimate.values() if v is not None), 'flags': list(r.flags), "
                    "'cpu': time.process_time() - t}))")
            p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=tmp,
                               env={**os.environ, "PYTHONPATH": tmp})
            out["fe_base"] = json.loads(p.stdout.strip().splitlines()[-1]) if p.returncode == 0 else {
                "error": p.stderr.strip()[-300:]}
    return out


def _export_base(into: Path, rev: str = "7e5b70f") -> None:
    from studies.benchmarks.tehl_compare import export_base

    export_base(rev, into)


#: contacts where the base tree's TEHL converges (the baseline's mid-path contact and 10 m/s, 1 GPa), for the
#: same-run comparison: (w N/m, R m, u_e m/s, SRR)
COMPARE = [(84332.0, 0.0123, 1.09, 0.0), (84332.0, 0.0123, 1.09, 0.3), (84332.0, 0.0123, 1.09, 1.0),
           (336000.0, 0.0123, 10.0, 0.0), (336000.0, 0.0123, 10.0, 0.5)]


def compare_base() -> list[dict]:
    """The base tree's line TEHL (its default level 5, and level 6 to gauge its error) against this one at its
    default tolerance, on the baseline's oil and steel, CPU seconds in the same run."""
    code = """
import json, sys, time
sys.path.insert(0, sys.argv[1])
from femgear_base.case import build_case
from femgear_base.levels.lubrication import tehl_setup
from femgear_base.physics.tehl.line import solve_tehl_line
from femgear_base.scene import load_scene
setup = tehl_setup(build_case(load_scene(sys.argv[2])))
out = []
for w, R, ue, srr in json.loads(sys.argv[3]):
    row = {}
    for lev in (5, 6):
        t = time.process_time()
        r = solve_tehl_line(w, R, ue, srr, 313.0, level=lev, **setup.kwargs())
        row[lev] = {"hc": r.hc, "hmin": r.hmin, "mu": r.mu, "cpu": time.process_time() - t}
    out.append(row)
print(json.dumps(out))
"""
    from femgear.case import build_case
    from femgear.levels.lubrication import tehl_setup
    from femgear.physics.tehl.line import solve_tehl_line
    from femgear.scene import load_scene

    baseline = str(ROOT / "studies" / "paper_baseline.toml")
    with tempfile.TemporaryDirectory() as tmp:
        _export_base(Path(tmp))
        p = subprocess.run([sys.executable, "-c", code, tmp, baseline, json.dumps(COMPARE)], capture_output=True,
                           text=True, cwd=tmp)
    if p.returncode != 0:
        return [{"error": p.stderr.strip()[-300:]}]
    base = json.loads(p.stdout.strip().splitlines()[-1])
    setup = tehl_setup(build_case(load_scene(baseline)))
    rows = []
    for (w, R, ue, srr), b in zip(COMPARE, base):
        t = time.process_time()
        r = solve_tehl_line(w, R, ue, srr, 313.0, **setup.kwargs())
        rows.append({"contact": [w, R, ue, srr], "new": {"hc": r.hc, "hmin": r.hmin, "mu": r.mu,
                                                          "cpu": time.process_time() - t,
                                                          "estimate": max(r.error_estimate.values())},
                     "base5": b["5"], "base6": b["6"]})
    return rows


def opposite_sliding() -> list[dict]:
    """Opposite sliding at zero entrainment (the thermal-wedge dimple, :mod:`femgear.physics.tehl.opposite`) on the
    baseline's mid-path contact (its oil and steel, 84.3 kN/m, R 12.3 mm, 40 °C): each surface at 5 and 10 m/s, and
    at 5 m/s under twice the load.  The dimple's depth is h_c less the smaller of the two rims' minima."""
    from femgear.physics.contact.hertz import reduced_modulus
    from femgear.physics.lubrication.oil import OilLaw
    from femgear.physics.lubrication.path import solids_of
    from femgear.physics.tehl.opposite import solve_tehl_opposite
    from femgear.physics.tehl.solver import thermal_props
    from femgear.scene import load_scene

    sc = load_scene(ROOT / "studies" / "paper_baseline.toml")
    oil = OilLaw.from_table(sc.oil, sc.oil_reference_temperature)
    props = thermal_props(solids_of(sc.material, sc.oil), sc.oil.specific_heat, sc.material.conductivity)
    E = reduced_modulus(sc.material.youngs_modulus, sc.material.poisson_ratio)
    rows = []
    for w, U in ((84332.0, 5.0), (84332.0, 10.0), (168664.0, 5.0)):
        t = time.process_time()
        try:
            r = solve_tehl_opposite(w, 0.0123, U, -U, 313.0, oil, E, props, tau0=sc.oil.eyring_stress)
        except Exception as exc:    # reported, not hidden
            rows.append({"w": w, "U": U, "converged": False, "error": str(exc)[:200]})
            continue
        X = r.x / r.b
        rim = min(r.h[(X < 0) & (X > -1)].min(), r.h[(X > 0) & (X < 1)].min())
        rows.append({"w": w, "U": U, "converged": True, "hc": r.hc, "rim": rim, "depth": r.hc - rim,
                     "pmax_ph": r.pmax / r.ph, "dT_max": r.dT_max, "mu": r.mu,
                     "balance": abs(r.heat["balance_error"]), "estimate": max(r.error_estimate.values()),
                     "cpu": time.process_time() - t})
    return rows


def main(argv: list[str] | None = None) -> dict:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--json", help="write the figures to this file")
    ap.add_argument("--quick", action="store_true", help="every sixth point only")
    ap.add_argument("--no-base", action="store_true", help="skip the base tree's FE line and TEHL solves")
    args = ap.parse_args(argv)
    rows = []
    print(f"{'group':7} {'oil':5} {'T':>4} {'u_e':>6} {'p_H':>5} {'SRR':>5} {'M':>8} {'L':>6} conv {'its':>4} "
          f"{'nodes':>5} {'nz':>3} {'CPU s':>6} {'hc/iso':>7} {'balance':>8} {'estimate':>8} {'dT K':>6} {'est K':>5}")
    for p in points(args.quick):
        r = solve_point(p)
        rows.append(r)
        if r["converged"]:
            print(f"{p['group']:7} {p['oil']:5} {p['T']:4.0f} {p['ue']:6.2f} {p['ph'] / 1e9:5.2f} {p['srr']:5.1f} "
                  f"{r['M']:8.3g} {r['L']:6.3g} {'yes':4} {r['iterations']:4d} {r['nodes']:5d} {r['layers']:3d} "
                  f"{r['cpu']:6.2f} {r['ratio']:7.3f} {r['balance']:8.1e} {100 * r['estimate']:7.2f}% "
                  f"{r['dT_max']:6.1f} {r['temperature_estimate'] or 0.0:5.2f}", flush=True)
        else:
            print(f"{p['group']:7} {p['oil']:5} {p['T']:4.0f} {p['ue']:6.2f} {p['ph'] / 1e9:5.2f} {p['srr']:5.1f} "
                  f"FAILED ({r['cpu']:.1f} s): {r['error']}", flush=True)
    ok = [r for r in rows if r["converged"]]
    cpu = [r["cpu"] for r in ok]
    summary = {"points": len(rows), "converged": len(ok), "cpu_median": float(np.median(cpu)) if cpu else None,
               "cpu_max": float(np.max(cpu)) if cpu else None,
               "balance_max": max((r["balance"] for r in ok), default=None),
               "estimate_max": max((r["estimate"] for r in ok), default=None),
               "temperature_estimate_max": max((r["temperature_estimate"] or 0.0 for r in ok), default=None),
               "M_range": [min(r["M"] for r in ok), max(r["M"] for r in ok)] if ok else None,
               "L_range": [min(r["L"] for r in ok), max(r["L"] for r in ok)] if ok else None}
    print(f"\n{summary['converged']}/{summary['points']} converged; CPU median {summary['cpu_median']:.2f} s, "
          f"max {summary['cpu_max']:.2f} s (targets 1 / 5 s); energy balance <= {summary['balance_max']:.1e}; "
          f"error estimate <= {100 * summary['estimate_max']:.2f} %, peak rise <= "
          f"{summary['temperature_estimate_max']:.2f} K; M {summary['M_range'][0]:.3g}–"
          f"{summary['M_range'][1]:.4g}, L {summary['L_range'][0]:.3g}–{summary['L_range'][1]:.3g}")
    iso = isothermal_heavy(not args.no_base)
    print(f"isothermal (1000, 4.3) to 1 %: FD Hc {iso['fd']['Hc']:.4f} Hmin {iso['fd']['Hmin']:.4f} on "
          f"{iso['fd']['nodes']} nodes, estimate {100 * iso['fd']['estimate']:.2f} %, {iso['fd']['cpu']:.3f} s CPU "
          "(median of 3; target 0.5 s)")
    if "fe_base" in iso:
        print(f"  base tree's FE solver, tol 1 %: {iso['fe_base']}")
    out = {"summary": summary, "isothermal": iso, "points": rows}
    if not args.no_base:
        out["compare"] = compare_base()
        for c in out["compare"]:
            if "error" in c:
                print("base TEHL:", c["error"])
                continue
            n, b5, b6 = c["new"], c["base5"], c["base6"]
            print(f"TEHL {c['contact']}: new {n['cpu']:.2f} s (estimate {100 * n['estimate']:.2f} %), base level 5 "
                  f"{b5['cpu']:.2f} s (h_c {b5['hc'] / b6['hc'] - 1:+.2%}, h_min {b5['hmin'] / b6['hmin'] - 1:+.2%} "
                  f"from its level 6, {b6['cpu']:.2f} s); new - base level 6: h_c {n['hc'] / b6['hc'] - 1:+.2%}, "
                  f"h_min {n['hmin'] / b6['hmin'] - 1:+.2%}")
    if not args.quick:
        out["opposite"] = opposite_sliding()
        for o in out["opposite"]:
            if not o["converged"]:
                print(f"opposite sliding w' {o['w']:.0f} N/m, ±{o['U']:g} m/s: FAILED: {o['error']}")
                continue
            print(f"opposite sliding (u_e = 0) w' {o['w']:.0f} N/m, ±{o['U']:g} m/s: h_c {1e9 * o['hc']:.0f} nm, rims "
                  f"{1e9 * o['rim']:.0f} nm, dimple {1e9 * o['depth']:.0f} nm, p_max/p_H {o['pmax_ph']:.2f}, "
                  f"peak rise {o['dT_max']:.0f} K, mu {o['mu']:.4f}, balance {o['balance']:.1e}, estimate "
                  f"{100 * o['estimate']:.2f} %, {o['cpu']:.1f} s CPU")
    if args.json:
        Path(args.json).write_text(json.dumps(out, indent=1))
    return out


if __name__ == "__main__":
    sys.path.insert(0, str(ROOT))
    main()
