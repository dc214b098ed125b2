"""The zoo matrix: every zoo scene at every physics level, run or refused up front, with its invariants checked.

Rows: the scenes of ``studies/zoo/`` (and the paper's baseline).  Columns: each sub-model's
levels one at a time on top of the scene's own ``[physics]`` (with the companions a level
needs: a dynamics level for bidirectional coupling, one-way coupling without dynamics), plus
the scene's full fidelity (``ltca`` + ``fe3d`` + the point TEHL where the crowned contact is
inside its range, else the line TEHL, else the FE line EHL; the baseline with the paper's 10 µm crowning).

A cell is one ``femgear run ... --json`` in a subprocess.  Its verdict:

- ``ok`` — exit 0 and the invariants hold: the time-mean load along the path carries the
  normal force (helical: b/(p_bt cos β_b) ∫ w̄ du = F_n per helix, to 2 %; spur, whose load jumps
  at B and D: w̄ b = F_n inside the single-contact zone; ``ltca``, whose w̄ is the mean over the
  phases that load u: the LTCA's own force balance per phase, to 1e-6), the mean bearing loads of each
  member balance the mean mesh force on it (radially and axially, to 1 %; without dynamics the static loads
  the static normal force), the rating's K_v, K_Hβ, K_Hα listed with their sources (K_v from the dynamics
  where the cell has them), films positive, contact temperatures finite and non-negative (zero only for the
  levels without heating), coupling converged, the film's own error estimate (the ``ehl-line`` and ``tehl``
  levels must carry one; ``tehl-point``'s face slices do) at most :data:`MAX_ESTIMATE`, and
  the film and temperature within a factor of :data:`FACTOR` of the formula figures of
  ``femgear info`` (a coarse net for unit or scaling faults, not a validation);
- ``refused: <line>`` — exit 2 within :data:`REFUSAL_SECONDS` of CPU time with one line naming the key;
- ``refused (physics, after computing it): <line>`` — exit 2 with one line of a refusal that only the computed
  physics decides (:data:`PHYSICS_REFUSAL`: a backlash that the thermal growth closes), at any time;
- ``FAIL: ...`` — anything else (a raw solver line, a broken invariant, a late refusal).

Run: ``python studies/validation/zoo_matrix.py [--scenes a,b] [--cells stiffness=fe,...] [--jobs N] [--coarse]
[--dry-run] [--json]``; ``--dry-run`` only validates each cell's scene (what ``make test`` checks).
"""

from __future__ import annotations

import argparse
import json
import math
import os
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[2]
ZOO = ROOT / "studies" / "zoo"
OUT = ROOT / "out" / "zoo_matrix"
FACTOR = 5.0              #: films and temperatures within this factor of the formula figures
REFUSAL_SECONDS = 30.0    #: CPU seconds: a refusal comes before (long) computing: the CLI's start-up (imports) ~2 s;
#: CPU time, not wall time, so that a loaded machine does not turn a refusal into a late one
FORCE_TOLERANCE = 0.02    #: the path integral of the time-mean load against F_n
MAX_ESTIMATE = 0.02       #: the largest film error estimate (``summary.film.error_estimate_max``) a cell may report
ESTIMATED = ("ehl-line", "tehl")  #: the lubrication levels whose films must carry an error estimate
BEARING_TOLERANCE = 0.01  #: the mean bearing loads of a member against the mean mesh force on it
#: the surface rise read off a friction map may exceed the film peak solved at the position by this factor
MAP_TOLERANCE = 1.02
#: a refusal that only the computed physics can decide (a backlash closed by the thermal growth of the coupled
#: run: the FZG C pair's zero backlash), which is therefore late by nature
PHYSICS_REFUSAL = "the thermal growth closes it"
COARSE = ("numerics.dynamics_cycles=20", "numerics.transient_cycles=10", "numerics.path_points=21")


def scenes() -> dict[str, Path]:
    """name -> scene file: the zoo folder's scenes and the paper's baseline (once)."""
    found = {p.stem: p for p in sorted(ZOO.glob("*.toml"))}
    if not any("baseline" in name for name in found):
        found["paper_baseline"] = ROOT / "studies" / "paper_baseline.toml"
    return found


def _load(path: Path, overrides=()):
    from femgear.scene import load_scene

    return load_scene(path, list(overrides))


def _bind(path: Path, overrides=()):
    """The bound case: the checks that need the pair (the lubrication level's range) run here."""
    from femgear.case import build_case

    return build_case(_load(path, overrides))


def cells(path: Path) -> dict[str, list[str]]:
    """Column name -> overrides of the scene at ``path``."""
    from femgear.scene.levels import AVAILABLE, LEVELS

    scene = _load(path)
    own = scene.physics.model_dump()
    out: dict[str, list[str]] = {"default": []}
    for sub, levels in LEVELS.items():
        for level in levels:
            if level not in AVAILABLE[sub] or level == own[sub]:
                continue
            ov = [f'physics.{sub}="{level}"']
            if sub == "coupling" and level == "bidirectional" and own["dynamics"] == "none":
                ov.append('physics.dynamics="lumped"')
            if sub == "dynamics" and level == "none":
                ov.append('physics.coupling="one-way"')
            out[f"{sub}={level}"] = ov
    out["full"] = full_fidelity(path)
    return out


def full_fidelity(path: Path) -> list[str]:
    """The scene's full fidelity: LTCA, 3-D thermal, and the finest lubrication level its range allows: the point
    TEHL (which hands slender contacts over to face slices of line TEHL), else the line TEHL, else the line EHL."""
    from femgear.errors import SceneError

    base = ['physics.stiffness="ltca"', 'physics.thermal="fe3d"']
    scene = _load(path)
    if scene.physics.dynamics == "none":
        base += ['physics.dynamics="lumped"', 'physics.coupling="bidirectional"']
    crown = [] if scene.modifications.member(1).crowning + scene.modifications.member(2).crowning > 0 \
        else ["modifications.crowning=10e-6"]
    for level, extra in (("tehl-point", crown), ("tehl", []), ("ehl-line", [])):
        try:
            _bind(path, base + extra + [f'physics.lubrication="{level}"'])
            return base + extra + [f'physics.lubrication="{level}"']
        except SceneError:
            continue
    return base


def _check(summary: dict, results: dict, hand: dict) -> list[str]:
    """The invariants of one finished run; returns the broken ones."""
    bad = []
    co = summary.get("coupling")
    if co and not co.get("converged"):
        bad.append("coupling not converged")
    if "dynamics" in summary:
        amp = summary["dynamics"]["amplitudes"]
        bad += _bearing_balance(summary["dynamics"].get("bearing_forces"),
                                [amp["mesh_force.L.mean"], amp["mesh_force.R.mean"]], hand["beta_b"])
    else:                   # the static loads against the static normal force of each loaded helix
        bad += _bearing_balance(summary.get("bearing_forces_static"),
                                [hand["force"], hand["force"] if hand["helices"] == 2 else 0.0], hand["beta_b"])
    path = results["along_path"]
    for key in ("film_central", "film_minimum"):
        if min(path[key]) <= 0 or not all(map(math.isfinite, path[key])):
            bad.append(f"{key} not positive")
    if "temperature_rise" in path and summary["physics"]["lubrication"] not in ("none", "constant"):
        dT = path["temperature_rise"]
        if not all(map(math.isfinite, dT)) or min(dT) < 0:
            bad.append("temperature rise negative or not finite")
        else:
            # the thermal levels' contact temperature is the surface rise; the formula level's figure also holds
            # the sheared film's mean rise, so theirs is held against the film's own peak (and the surface must stay
            # below that peak, to the friction map's interpolation: the `tehl` level reads the surface rise off its
            # map and solves the film at the positions; the mill's path start differs by 1.0 %)
            film = path.get("film_temperature_rise")
            hot = max(film) if film is not None else max(dT)
            if film is not None and max(dT) > MAP_TOLERANCE * max(film) + 1e-9:
                bad.append(f"surface temperature rise {max(dT):.3g} K above the film's peak {max(film):.3g} K")
            if hand["flash"] > 1.0 and not hand["flash"] / FACTOR < hot < hand["flash"] * FACTOR:
                bad.append(f"max temperature rise {hot:.3g} K vs formula {hand['flash']:.3g} K")
    level = summary["physics"]["lubrication"]
    est = (summary.get("film") or {}).get("error_estimate_max")
    if level in ESTIMATED and est is None:
        bad.append(f"{level} film without its error estimate")
    elif est is not None and est > MAX_ESTIMATE:
        bad.append(f"film error estimate {100 * est:.2g} % above {100 * MAX_ESTIMATE:g} %")
    h = path["film_central"][len(path["s"]) // 2]
    if not hand["film"] / FACTOR < h < hand["film"] * FACTOR:
        bad.append(f"mid-path film {h:.3g} m vs formula {hand['film']:.3g} m")
    from femgear.physics.rating.load_factors import SOURCES

    lf = summary.get("load_factors")
    if lf is None or any(k not in lf or lf[k]["source"] not in SOURCES or not lf[k]["value"] >= 1
                         for k in ("K_v", "K_Hbeta", "K_Halpha")):
        bad.append("the rating's load factors K_v, K_Hbeta, K_Halpha with their sources missing")
    elif summary.get("dynamics") and lf["K_v"]["source"] not in ("femgear dynamics", "scene"):
        bad.append(f"K_v from {lf['K_v']['source']!r} although the run has dynamics")
    w, s = path["load_per_length"], path["s"]
    te = summary.get("transmission_error")
    if te is not None:      # ltca: w̄ is the mean over the phases that load u (crowning, reliefs and line-end
        # edge loads leave parts of the lines open), so its path integral is not F_n; the LTCA's own balance is
        shares = te.get("load_share_left", 1.0) + te.get("load_share_right", 0.0)    # one helix: no share
        if abs(te["load_balance_error"]) > 1e-6 or abs(shares - 1) > 1e-6:
            bad.append(f"LTCA load balance error {te['load_balance_error']:.2g}")
        return bad
    if hand["single"] is None:
        carried = hand["force_scale"] * float(np.trapezoid(w, s))
    else:       # spur: one pair carries the mesh force inside the single-contact zone (B, D), away from its bounds
        lo, hi = hand["single"]
        margin = 0.1 * (hi - lo)
        inside = [wi for wi, si in zip(w, s) if lo + margin < si < hi - margin]
        carried = hand["face_width"] * sum(inside) / len(inside)
    force = hand["force"]
    if hand["single"] is not None and "mesh_force_per_phase" in results:
        force = _single_contact_force(results["mesh_force_per_phase"]["left"], hand, [si for si in s if
                                      hand["single"][0] + margin < si < hand["single"][1] - margin])
    if abs(carried / force - 1) > FORCE_TOLERANCE:
        bad.append(f"path load carries {carried:.4g} N, the mesh force per helix {force:.4g} N")
    return bad


def _single_contact_force(force: list[float], hand: dict, positions: list[float]) -> float:
    """The dynamic mesh force (over one mesh period) where the single pair in contact passes the path
    ``positions`` s (from the pitch point) [N], averaged: in single contact that pair carries the whole mesh
    force, and it reaches s = lo + (φ − φ_B) p_bt at the mesh phase φ (φ_B: where single contact begins), so
    the zone's sampled path load equals the mesh force at those phases, whatever the dynamics."""
    f = np.asarray(force, float)
    start, _ = hand["single_phases"]
    x = np.mod(start + (np.asarray(positions) - hand["single"][0]) / hand["p_bt"], 1.0)
    return float(np.mean(np.interp(x, np.arange(f.size) / f.size, f, period=1.0)))


def _bearing_balance(bf: dict | None, N: list[float], beta_b: float) -> list[str]:
    """The mean bearing loads ``bf`` of each member balance the mean normal mesh forces ``N`` (left, right helix) on
    it, to :data:`BEARING_TOLERANCE` of the mesh force: radially |Σ F̄_xy| = Σ_s N̄_s cos β_b (friction acts across
    the line of action in the transverse plane and adds only (μ²/2)), axially |Σ F̄_z| = |N̄_L − N̄_R| sin β_b."""
    if bf is None:
        return ["no bearing forces in the summary"]
    transverse, axial = sum(N) * math.cos(beta_b), abs(N[0] - N[1]) * math.sin(beta_b)
    bad = []
    for member in ("pinion", "gear"):
        F = np.sum([bf[f"{member}_{side}"]["mean"] for side in "LR"], axis=0)
        radial = math.hypot(F[0], F[1])
        if abs(radial - transverse) > BEARING_TOLERANCE * transverse:
            bad.append(f"{member} bearings carry {radial:.5g} N radially, the mesh {transverse:.5g} N")
        if abs(abs(F[2]) - axial) > BEARING_TOLERANCE * sum(N):
            bad.append(f"{member} bearings carry {F[2]:.5g} N axially, the mesh {axial:.5g} N")
    return bad


def hand_figures(path: Path, overrides=()) -> dict:
    """The formula figures a cell with ``overrides`` is held against: F_n per helix, the force scale
    b/(p_bt cos β_b), the single-contact zone (s_B, s_D) of a spur pair (None for helical), the formula film at
    the pitch point and the formula-level contact temperature (Blok's flash of the crowned point contacts
    where the cell solves those, :func:`_point_flash_scale`).  Of the overrides only the geometry's
    (``modifications.*``) apply: the formula level is the reference, whatever level the cell runs."""
    from femgear.case import build_case
    from femgear.levels.contact import contact_pass
    from femgear.levels.lubrication import friction_along_path
    from femgear.physics.contact.sharing import single_contact_bounds

    geometry = [o for o in overrides if o.startswith("modifications.")]
    scene = _load(path, geometry + ['physics.lubrication="formula"'])
    case = build_case(scene)
    pair = case.pair
    contact = contact_pass(case)
    _, dT = friction_along_path(case, contact.line_load)
    if 'physics.lubrication="tehl-point"' in overrides:
        dT = dT * _point_flash_scale(case, contact.line_load)
    u_B, u_D = single_contact_bounds(pair)
    return {"single_phases": _single_phases(pair), "p_bt": pair.p_bt,"force": case.operating.normal_force / pair.n_helices, "beta_b": pair.beta_b, "helices": pair.n_helices,
            "force_scale": pair.b / (pair.p_bt * math.cos(pair.beta_b)), "face_width": pair.b,
            "single": (min(u_B, u_D) - pair.u_pitch, max(u_B, u_D) - pair.u_pitch) if pair.beta_b == 0 else None,
            "film": float(contact.film_central[contact.pitch_index]), "flash": float(max(dT))}


def _point_flash_scale(case, w: np.ndarray) -> np.ndarray | float:
    """Blok's flash of the crowned point contacts over the line contacts' at the path positions (1 for an
    uncrowned pair, which the point level hands to line slices unchanged): along the ellipse's centre line the
    heat source is a Hertzian band of half-width a (the semi-axis across the contact line) and peak p_h, so
    ΔT_fl ∝ μ p_h √a (:func:`femgear.physics.lubrication.flash.blok_flash_temperature` with w' = π p_h a/2), and
    the ratio to the line contact of the same line load is (p_h/p_H) √(a/b).  Not below 1: an ellipse longer
    than the contact line (a light crowning on a wide face) is cut off by the face ends and carries at least
    the line contact's load per length along its middle."""
    from femgear.levels.contact import reduced_modulus_of
    from femgear.physics.contact.crowning import crowned_contact
    from femgear.physics.contact.hertz import hertz_line, hertz_point

    mods = case.scene.modifications
    crowning = (mods.member(1).crowning, mods.member(2).crowning)
    if sum(crowning) <= 0:
        return 1.0
    geo, E_red, R = crowned_contact(case.pair, crowning), reduced_modulus_of(case), case.path.R
    Rx, Ry = geo.radii(R)
    scale = []
    for wi, Ri, rx, ry in zip(np.broadcast_to(w, R.shape), R, Rx, Ry):
        line, point = hertz_line(wi, Ri, E_red), hertz_point(geo.load(wi), rx, ry, E_red)
        scale.append(max(1.0, point.max_pressure / line.max_pressure * math.sqrt(point.a / line.half_width)))
    return np.asarray(scale)


def _single_phases(pair) -> tuple[float, float]:
    """(start, length) of the mesh phases [periods] with one pair in contact (spur; None-like (0, 0) else)."""
    from femgear.physics.geometry import contact_lines

    phase = np.arange(2000) / 2000
    one = np.array([contact_lines(pair, p).count == 1 for p in phase])
    if pair.beta_b != 0 or not one.any() or one.all():
        return 0.0, 0.0
    first = int(np.flatnonzero(one & ~np.roll(one, 1))[0])          # where single contact begins
    return float(phase[first]), float(one.mean())


def run_timed(cmd: list[str], timeout: float, **kwargs) -> tuple[subprocess.CompletedProcess, float]:
    """``cmd`` run as ``subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)`` would, and the CPU
    time of the child and its waited-for descendants [s] (``os.wait4``: user + system, independent of the load)."""
    with tempfile.TemporaryFile("w+") as out, tempfile.TemporaryFile("w+") as err:
        proc = subprocess.Popen(cmd, stdout=out, stderr=err, text=True, **kwargs)
        deadline = time.monotonic() + timeout
        while True:
            pid, status, usage = os.wait4(proc.pid, os.WNOHANG)
            if pid:
                break
            if time.monotonic() > deadline:
                proc.kill()
                os.wait4(proc.pid, 0)
                proc.returncode = -9
                raise subprocess.TimeoutExpired(cmd, timeout)
            time.sleep(0.05)
        proc.returncode = os.waitstatus_to_exitcode(status)
        out.seek(0)
        err.seek(0)
        done = subprocess.CompletedProcess(cmd, proc.returncode, out.read(), err.read())
    return done, usage.ru_utime + usage.ru_stime


def run_cell(name: str, path: Path, column: str, overrides: list[str], coarse: bool, timeout: float) -> dict:
    out = OUT / name / column.replace("=", "_")
    ov = list(overrides) + (list(COARSE) if coarse else [])
    cmd = [sys.executable, "-m", "femgear", "run", str(path), "--out", str(out), "--json", "--no-plots", "--no-vtk"]
    for o in ov:
        cmd += ["--set", o]
    t0 = time.perf_counter()
    try:
        p, cpu = run_timed(cmd, timeout, cwd=ROOT, env={**os.environ, "OPENBLAS_NUM_THREADS": "1"})
    except subprocess.TimeoutExpired:
        return {"scene": name, "cell": column, "verdict": f"FAIL: over the {timeout:.0f} s limit", "seconds": timeout}
    seconds = time.perf_counter() - t0
    err = [line for line in p.stderr.strip().splitlines() if line.startswith("femgear: error")]
    if p.returncode == 2:
        line = err[-1].removeprefix("femgear: error: ") if err else p.stderr.strip()[-200:]
        if len(err) == 1 and PHYSICS_REFUSAL in line:
            verdict = f"refused (physics, after computing it): {line}"
        else:
            verdict = f"refused: {line}" if cpu < REFUSAL_SECONDS and len(err) == 1 else f"FAIL: late or raw: {line}"
    elif p.returncode != 0:
        verdict = f"FAIL: exit {p.returncode}: {(err or [p.stderr.strip()[-200:]])[-1]}"
    else:
        summary = json.loads(p.stdout.strip().splitlines()[-1])
        results = json.loads((out / "results.json").read_text())
        bad = _check(summary, results, hand_figures(path, ov))
        verdict = "ok" if not bad else "FAIL: " + "; ".join(bad)
    return {"scene": name, "cell": column, "verdict": verdict, "seconds": round(seconds, 1)}


def dry_run(name: str, path: Path, column: str, overrides: list[str]) -> dict:
    """Validate the cell's scene only: accepted (``valid``) or refused with one line."""
    from femgear.errors import SceneError

    try:
        _bind(path, overrides)
        return {"scene": name, "cell": column, "verdict": "valid", "seconds": 0.0}
    except SceneError as exc:
        return {"scene": name, "cell": column, "verdict": f"refused: {exc}", "seconds": 0.0}


def setup(argv: list[str] | None = None) -> tuple[argparse.Namespace, list[tuple]]:
    """The command line ``argv`` parsed and the cells it selects: (scene name, scene path, column, overrides)."""
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--scenes", help="comma-separated scene names (default: all)")
    ap.add_argument("--cells", help="comma-separated columns, e.g. default,lubrication=tehl,full (default: all)")
    ap.add_argument("--jobs", type=int, default=max(1, (os.cpu_count() or 2) // 2), help="cells run at once")
    ap.add_argument("--coarse", action="store_true", help="coarse numerics (fewer mesh periods and path points)")
    ap.add_argument("--timeout", type=float, default=900.0, help="seconds per cell")
    ap.add_argument("--dry-run", action="store_true", help="validate every cell's scene, run nothing")
    ap.add_argument("--markdown", type=Path, help="also write the matrix as a Markdown table to this file")
    ap.add_argument("--json", action="store_true", help="print one JSON object as the last line")
    args = ap.parse_args(argv)
    chosen = scenes()
    if args.scenes:
        chosen = {k: chosen[k] for k in args.scenes.split(",")}
    todo = []
    for name, path in chosen.items():
        for column, ov in cells(path).items():
            if args.cells is None or column in args.cells.split(","):
                todo.append((name, path, column, ov))
    return args, todo


def run(args: argparse.Namespace, todo: list[tuple]) -> list[dict]:
    """Each cell validated (``--dry-run``) or run (``args.jobs`` at once), recorded with the earlier cells."""
    if args.dry_run:
        rows = [dry_run(*t) for t in todo]
    else:
        with ThreadPoolExecutor(args.jobs) as pool:
            rows = list(pool.map(lambda t: run_cell(*t, args.coarse, args.timeout), todo))
    return rows if args.dry_run else record(rows)


def main(argv: list[str] | None = None) -> int:
    args, todo = setup(argv)
    rows = run(args, todo)
    width = max(len(r["cell"]) for r in rows)
    for r in rows:
        print(f"{r['scene']:16s} {r['cell']:{width}s} {r['seconds']:7.1f} s  {r['verdict']}")
    failed = [r for r in rows if r["verdict"].startswith("FAIL")]
    print(f"{len(rows)} cells: {sum(r['verdict'] in ('ok', 'valid') for r in rows)} ok, "
          f"{sum(r['verdict'].startswith('refused') for r in rows)} refused, {len(failed)} failed")
    if args.markdown:
        args.markdown.write_text(markdown(rows))
    if args.json:
        print(json.dumps({"cells": rows}))
    return 1 if failed else 0


def record(rows: list[dict]) -> list[dict]:
    """Merge ``rows`` into ``out/zoo_matrix/cells.json`` (later runs of a cell replace earlier ones), so a
    matrix run in parts adds up; returns every recorded row."""
    store = OUT / "cells.json"
    old = json.loads(store.read_text())["cells"] if store.exists() else []
    merged = {(r["scene"], r["cell"]): r for r in old + rows}
    OUT.mkdir(parents=True, exist_ok=True)
    store.write_text(json.dumps({"cells": list(merged.values())}, indent=1))
    return list(merged.values())


def markdown(rows: list[dict]) -> str:
    """The matrix as a Markdown table: one row per cell, one column per scene; refusals as numbered notes."""
    names = sorted({r["scene"] for r in rows})
    columns = list(dict.fromkeys(r["cell"] for r in rows))
    at = {(r["scene"], r["cell"]): r for r in rows}
    notes: list[str] = []
    lines = ["| cell | " + " | ".join(names) + " |", "|---" * (len(names) + 1) + "|"]
    for c in columns:
        entries = []
        for n in names:
            r = at.get((n, c))
            if r is None:
                entries.append("")
            elif r["verdict"] in ("ok", "valid"):
                entries.append(f"{r['verdict']} {r['seconds']:.0f} s")
            else:
                if r["verdict"] not in notes:
                    notes.append(r["verdict"])
                entries.append(f"{r['verdict'].split(':')[0]} [{notes.index(r['verdict']) + 1}]")
        lines.append(f"| `{c}` | " + " | ".join(entries) + " |")
    return "\n".join(lines + [""] + [f"{i}. {v}" for i, v in enumerate(notes, 1)]) + "\n"


if __name__ == "__main__":
    sys.exit(main())
