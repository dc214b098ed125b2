"""Cost of the FE stages per gear pair and body level: DOF, peak memory, cold time (issue 26).

    python studies/benchmarks/cost.py [--levels 0,1 | --levels "baseline=0,1,2,3/marine=0,1,2"]
                                      [--pairs baseline,marine] [--skip ltca,fe,refusal,fidelity]
                                      [--elements p1 | p2-bending] [--reference DIR]

Pairs: the paper's baseline and every scene of ``studies/zoo/*.toml``.  Per pair and
``numerics.body_level``: the member bodies' DOF and tetrahedra; the ``ltca`` stiffness cold
(empty cache: meshes, kernels, one mesh cycle with its resolution check), its peak resident
memory, CPU time, mean mesh stiffness and LTE p-p (the mesh-convergence figures: change
against the finest level run); per pair the ``fe`` stiffness cold at the default level;
the refusal of a memory estimate over the budget (``FEMGEAR_MEMORY_GB=0.05``: time to the
one-line exit 2); the paper's full fidelity on the baseline (``ltca`` + ``tehl-point`` +
``fe3d``, crowning 10 µm) cold, as a failed row with its message if it fails.

Every measurement runs in its own child process (peak RSS by ``getrusage`` of that process,
address space capped at ``--cap-gb``), with a fresh cache folder.  The baseline's level-1 LTCA
is the reference of the ratios, measured in the same run.  Prints a table and one JSON line
(also written to ``out/benchmarks/cost.json``).  Timings are wall clock on a shared machine:
compare the ratios and the CPU times, not the absolute seconds of a loaded run.
``--elements``: the ``numerics.body_elements`` of every run (the LTCA bodies' elements; unset: the
scene's default, p2-bending; the DOF column shows the bodies' actual DOF from the ``ltca`` run); the JSON
goes to ``out/benchmarks/cost-ELEMENTS.json`` when it is given.  The ``fe`` stiffness and the full
fidelity run at the scene's default body levels (``numerics.body_level`` unset).
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from femgear.case import build_case
from femgear.case.pair import pair_from_scene
from femgear.levels import stiffness as stiffness_levels
from femgear.levels.stiffness import body_options

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
ROOT = Path(__file__).resolve().parents[2]
FIDELITY = ["--set", "physics.stiffness=\"ltca\"", "--set", "physics.lubrication=\"tehl-point\"",
            "--set", "modifications.crowning=10e-6", "--set", "physics.thermal=\"fe3d\""]


def scenes() -> dict[str, Path]:
    out = {"baseline": ROOT / "studies" / "paper_baseline.toml"}
    out.update({p.stem: p for p in sorted((ROOT / "studies" / "zoo").glob("*.toml"))})
    return out


def _usage() -> dict:
    """Peak RSS and CPU of this process and its children (the body stages run in forked children,
    :func:`femgear.perf.interruptible`)."""
    r, c = resource.getrusage(resource.RUSAGE_SELF), resource.getrusage(resource.RUSAGE_CHILDREN)
    return {"peak_rss_MiB": max(r.ru_maxrss, c.ru_maxrss) / 1024,
            "cpu_s": r.ru_utime + r.ru_stime + c.ru_utime + c.ru_stime}


def one(kind: str, scene_path: str, level: int | None, elements: str | None = None) -> dict:
    """One measurement in this (child) process (``level``, ``elements`` None: the scene's defaults)."""
    from femgear.scene import load_scene

    sets = [] if level is None else [f"numerics.body_level={level}"]
    if elements is not None:        # (a reference tree may not know the key)
        sets.append(f'numerics.body_elements="{elements}"')
    if kind == "size":
        from femgear.physics.mesh.segment import body_size, default_spec

        scene = load_scene(scene_path, sets)
        pair, body = pair_from_scene(scene), body_options(build_case(scene))
        out = {}
        for m in (1, 2):
            spec = default_spec(pair, m, level, r_bore=body["bore_radius"][m - 1], groove=body["groove_width"],
                                stagger=body["stagger"])
            nodes, tets = body_size(pair, m, spec)
            out[f"member{m}_dofs"], out[f"member{m}_tets"] = 3 * nodes, tets
            out["flank_h_tooth_mn"] = spec.h_tooth / pair.m_n
            out["flank_dz_mn"] = pair.b / spec.layers / pair.m_n
        return out
    if kind in ("ltca", "fe"):

        scene = load_scene(scene_path, sets)
        t0 = time.perf_counter()
        ms = stiffness_levels.of(build_case(scene), kind)
        out = {"seconds": time.perf_counter() - t0, "k_mean": ms.mean}
        if kind == "ltca":
            out["lte_pp_um"] = ms.ltca.lte_peak_to_peak * 1e6
            out["resolved_orders"] = ms.resolved_orders
            out["dofs"] = [int(k.ndofs) for k in ms.ltca.model.kernels.values()]
        else:
            out["dofs"] = [int(n) for n in ms.fe.ndofs]
        return {**out, **_usage()}
    if kind == "fidelity":
        from femgear.edge.cli import main as cli

        t0 = time.perf_counter()
        with tempfile.TemporaryDirectory() as out_dir:
            rc = cli(["run", scene_path, "--out", out_dir, "--no-plots", "--no-vtk", *FIDELITY,
                      *[a for x in sets for a in ("--set", x)]])
            seconds = time.perf_counter() - t0
            answer = _answer(Path(out_dir) / "results.json") if rc == 0 else {}
        return {"seconds": seconds, "rc": rc, "answer": answer, **_usage()}
    raise ValueError(f"unknown kind {kind!r}")


def _answer(path: Path) -> dict:
    """The figures of a full-fidelity run that its shortcuts could move (compared with the reference tree)."""
    s = json.loads(path.read_text())["summary"]
    amps = s["dynamics"].get("amplitudes", {})
    return {"mu_mean": s["friction"]["mu_mean"], "mu_max": s["friction"]["mu_max"],
            "max_temperature_rise": s["friction"]["max_temperature_rise"],
            "flank_temperature_rise": s["thermal"]["flank_temperature_rise"],
            "gear_velocity_y": amps.get("gear.velocity.y"), "gear_displacement_y": amps.get("gear.displacement.y"),
            "mesh_force_L_amplitude": amps.get("mesh_force.L.amplitude"),
            "coupling_passes": s["coupling"]["iterations"]}


def child(kind: str, scene_path: Path, level: int | None, cap_gb: float, env: dict | None = None,
          elements: str | None = None) -> dict:
    """Run :func:`one` in a child process with a fresh cache and an address-space cap."""
    def limit():
        cap = int(cap_gb * 1024**3)
        resource.setrlimit(resource.RLIMIT_AS, (cap, cap))

    with tempfile.TemporaryDirectory() as cache:
        e = {**os.environ, "FEMGEAR_CACHE": cache, "PYTHONPATH": str(ROOT), **(env or {})}
        load0 = os.getloadavg()
        t0 = time.perf_counter()
        run = subprocess.run([sys.executable, __file__, "--one", kind, str(scene_path), _arg(level), _arg(elements)],
                             env=e, capture_output=True, text=True, preexec_fn=limit)
        wall = time.perf_counter() - t0
        load = [round(x, 2) for x in (*load0, *os.getloadavg())]
    last = run.stdout.strip().splitlines()[-1] if run.stdout.strip() else ""
    if run.returncode != 0 or not last.startswith("{"):
        err = [ln for ln in run.stderr.strip().splitlines() if ln.strip()]
        return {"failed": True, "rc": run.returncode, "wall_s": wall, "message": err[-1] if err else "no output"}
    out = json.loads(last)
    out["wall_s"], out["load_before_after"] = wall, load
    notices = [ln for ln in run.stderr.splitlines() if ln.startswith("femgear:")]
    if notices:
        out["stderr"] = notices
    return out


def _arg(value) -> str:
    """A ``--one`` argument: ``-`` for None (the scene's default)."""
    return "-" if value is None else str(value)


def refusal(scene_path: Path) -> dict:
    """``femgear run`` with ltca and a 0.05 GB budget: the time to the one-line exit 2."""
    with tempfile.TemporaryDirectory() as tmp:
        env = {**os.environ, "FEMGEAR_CACHE": tmp, "FEMGEAR_MEMORY_GB": "0.05", "PYTHONPATH": str(ROOT)}
        t0 = time.perf_counter()
        c0 = resource.getrusage(resource.RUSAGE_CHILDREN)
        run = subprocess.run([sys.executable, "-m", "femgear", "run", str(scene_path), "--out", f"{tmp}/out",
                              "--set", "physics.stiffness=\"ltca\""], env=env, capture_output=True, text=True)
        wall = time.perf_counter() - t0
        c1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    lines = run.stderr.strip().splitlines()
    return {"rc": run.returncode, "wall_s": wall, "cpu_s": (c1.ru_utime + c1.ru_stime) - (c0.ru_utime + c0.ru_stime),
            "lines": len(lines), "message": lines[-1] if lines else ""}


def parse_levels(text: str, pairs: list[str]) -> dict[str, list[int]]:
    """``"0,1"`` (every pair) or ``"baseline=0,1,2/marine=0,1"`` → {pair: levels}."""
    if "=" not in text:
        return {p: [int(x) for x in text.split(",")] for p in pairs}
    spec = dict(part.split("=") for part in text.split("/"))
    return {p: [int(x) for x in spec.get(p, "1").split(",")] for p in pairs}


def run(pairs: list[str], levels: dict[str, list[int]], skip: set[str], cap_gb: float,
        reference: Path | None = None, elements: str | None = None) -> dict:
    paths = scenes()
    out: dict = {"levels": levels, "elements": elements, "pairs": {}}
    for name in pairs:
        rec: dict = {"scene": str(paths[name].relative_to(ROOT)), "levels": levels[name]}
        for level in levels[name]:
            try:
                rec[f"size_{level}"] = one("size", str(paths[name]), level)
            except (ValueError, ArithmeticError) as exc:     # a body femgear cannot mesh: a failed row
                rec[f"size_{level}"] = {"failed": True, "message": f"{type(exc).__name__}: {exc}"}
                continue
            if "ltca" not in skip:
                rec[f"ltca_{level}"] = child("ltca", paths[name], level, cap_gb, elements=elements)
                print(f"{name} level {level}: ltca {json.dumps(rec[f'ltca_{level}'])}", file=sys.stderr, flush=True)
        if "fe" not in skip:
            rec["fe"] = child("fe", paths[name], None, cap_gb)
            print(f"{name}: fe {json.dumps(rec['fe'])}", file=sys.stderr, flush=True)
        if "refusal" not in skip:
            rec["refusal"] = refusal(paths[name])
        rec["richardson"] = mesh_errors(rec)
        out["pairs"][name] = rec
    if "fidelity" not in skip:
        out["fidelity"] = child("fidelity", paths["baseline"], None, cap_gb, elements=elements)
        if reference is not None:    # the same job with another checkout's femgear, right after (same load)
            out["fidelity_reference"] = child("fidelity", paths["baseline"], None, cap_gb,
                                              env={"PYTHONPATH": str(reference)})
            out["fidelity_reference"]["tree"] = str(reference)
    return out


def mesh_errors(rec: dict) -> dict | None:
    """Richardson-extrapolated error of every level run (:func:`femgear.physics.ltca.level.richardson` on the three
    finest levels, h = the flank element size), on the mean stiffness and the LTE p-p; None for a
    quantity not in its asymptotic range, and None with fewer than three levels."""
    from femgear.physics.ltca.level import richardson

    done = [lv for lv in rec["levels"] if "k_mean" in rec.get(f"ltca_{lv}", {})][-3:]
    if len(done) < 3:
        return None
    h = [rec[f"size_{lv}"]["flank_h_tooth_mn"] for lv in done]
    out: dict = {"levels": done, "h_mn": h}
    for key in ("k_mean", "lte_pp_um"):
        r = richardson(h, [rec[f"ltca_{lv}"][key] for lv in done])
        if r is not None:    # the coarser levels' errors against the same extrapolation
            r["errors_all"] = {str(lv): rec[f"ltca_{lv}"][key] / r["extrapolated"] - 1
                               for lv in rec["levels"] if "k_mean" in rec.get(f"ltca_{lv}", {})}
        out[key] = r
    return out


def _richardson_rows(r: dict) -> list[str]:
    rows = []
    for name, rec in r["pairs"].items():
        m = rec.get("richardson")
        if not m:
            continue
        for key, label in (("k_mean", "mean stiffness"), ("lte_pp_um", "LTE p-p")):
            x = m[key]
            if x is None:
                rows.append(f"- {name}, {label}: levels {m['levels']} not in the asymptotic range (differences grow "
                            "or change sign): no Richardson estimate")
                continue
            errs = ", ".join(f"level {lv} {100 * e:+.2f} %{' FLAGGED' if abs(e) > 0.02 else ''}"
                             for lv, e in x["errors_all"].items())
            rows.append(f"- {name}, {label}: Richardson from levels {m['levels']} (order {x['order']:.2f}, "
                        f"extrapolated {x['extrapolated']:.5g}): {errs}")
    return rows


def _fmt(x, spec=".3g") -> str:
    return "—" if x is None else format(x, spec)


def table(r: dict) -> list[str]:
    rows = ["| pair | level | DOF pinion / gear | tets | flank h, dz [m_n] | ltca cold [s] (CPU) | peak [MiB] | "
            "k mean [N/m] | LTE p-p [µm] | Δk / ΔLTE vs finest |", "|" + "---|" * 10]
    ref = r["pairs"].get("baseline", {})
    ref_dofs = sum(ref.get("size_1", {}).get(f"member{m}_dofs", 0) for m in (1, 2)) or None
    for name, rec in r["pairs"].items():
        finest = max((lv for lv in rec["levels"] if "k_mean" in rec.get(f"ltca_{lv}", {})), default=None)
        for lv in rec["levels"]:
            s, lt = rec[f"size_{lv}"], rec.get(f"ltca_{lv}", {})
            if s.get("failed"):
                rows.append(f"| {name} | {lv} | failed: {s['message'][:90]} | | | | | | | |")
                continue
            conv = "—"
            if finest is not None and "k_mean" in lt:
                f = rec[f"ltca_{finest}"]
                conv = (f"{100 * (lt['k_mean'] / f['k_mean'] - 1):+.2f} % / "
                        f"{100 * (lt['lte_pp_um'] / f['lte_pp_um'] - 1):+.2f} %")
            cost = (f"{lt['seconds']:.0f} ({lt['cpu_s']:.0f})" if "seconds" in lt
                    else f"failed: {lt.get('message', '')[:60]}" if lt else "—")
            dofs = lt.get("dofs") or [s["member1_dofs"], s["member2_dofs"]]
            rows.append(f"| {name} | {lv} | {dofs[0] / 1e3:.0f} k / {dofs[1] / 1e3:.0f} k | "
                        f"{(s['member1_tets'] + s['member2_tets']) / 1e3:.0f} k | "
                        f"{s['flank_h_tooth_mn']:.3f}, {s['flank_dz_mn']:.3f} | {cost} | "
                        f"{_fmt(lt.get('peak_rss_MiB'), '.0f')} | {_fmt(lt.get('k_mean'), '.4e')} | "
                        f"{_fmt(lt.get('lte_pp_um'), '.4f')} | {conv} |")
        if ref_dofs and name != "baseline":
            ok = "size_1" in rec and not rec["size_1"].get("failed")
            d = sum(rec["size_1"][f"member{m}_dofs"] for m in (1, 2)) if ok else None
            rows.append(f"| {name} / baseline DOF at level 1 | | {_fmt(d / ref_dofs if d else None, '.2f')} × | "
                        "| | | | | | |")
    rows.append("")
    rows.extend(_richardson_rows(r))
    for name, rec in r["pairs"].items():
        fe = rec.get("fe")
        if fe:
            rows.append(f"- {name}, `fe` stiffness cold: " + (
                f"{fe['seconds']:.1f} s (CPU {fe['cpu_s']:.0f} s), peak {fe['peak_rss_MiB']:.0f} MiB, "
                f"DOF {fe['dofs']}, k mean {fe['k_mean']:.4e} N/m" if "seconds" in fe else f"failed: {fe}"))
        ref_ = rec.get("refusal")
        if ref_:
            rows.append(f"- {name}, refusal at FEMGEAR_MEMORY_GB=0.05: exit {ref_['rc']} after {ref_['wall_s']:.2f} s "
                        f"(CPU {ref_['cpu_s']:.2f} s, imports included), "
                        f"{ref_['lines']} line(s): `{ref_['message']}`")
    for key, label in (("fidelity", ""), ("fidelity_reference", " (reference tree)")):
        rows.extend(_fidelity_row(r.get(key), label))
    a, b = (r.get(k, {}).get("answer") for k in ("fidelity", "fidelity_reference"))
    if a and b:
        rows.append("- full fidelity, this tree against the reference: " + ", ".join(
            f"{k} {100 * (a[k] / b[k] - 1):+.4f} %" for k in a if a[k] and b.get(k)))
    return rows


def _fidelity_row(fid: dict | None, label: str) -> list[str]:
    rows: list[str] = []
    if fid:
        failed = fid.get("failed") or fid.get("rc", 0) != 0
        why = fid.get("message") or (fid.get("stderr") or [""])[-1]
        rows.append("- baseline, full fidelity (ltca + tehl-point + fe3d, crowning 10 µm) cold: " + (
            f"{'FAILED ' if failed else ''}{fid.get('seconds', fid['wall_s']):.0f} s"
            + (f" (CPU {fid['cpu_s']:.0f} s), peak {fid['peak_rss_MiB']:.0f} MiB" if "cpu_s" in fid else "")
            + f", exit {fid['rc']}" + (f": `{why[:300]}`" if failed else "")
            + f"{label}; load average before/after (1, 5, 15 min) {fid.get('load_before_after')}"))
    return rows


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--one", nargs=4, metavar=("KIND", "SCENE", "LEVEL", "ELEMENTS"), help=argparse.SUPPRESS)
    ap.add_argument("--elements", default=None, choices=("p1", "p2-bending"),
                    help="numerics.body_elements of every run (the LTCA member bodies; default: the scene's)")
    ap.add_argument("--levels", default="0,1")
    ap.add_argument("--pairs", default=",".join(scenes()))
    ap.add_argument("--skip", default="", help="comma list of ltca, fe, refusal, fidelity")
    ap.add_argument("--cap-gb", type=float, default=8.0, help="address-space cap of each child [GiB]")
    ap.add_argument("--reference", type=Path, default=None,
                    help="another checkout (e.g. `git archive COMMIT | tar -x -C DIR`): the fidelity job with its "
                         "femgear too, right after this one's")
    a = ap.parse_args(argv)
    if a.one:
        level, elements = (None if x == "-" else x for x in a.one[2:])
        print(json.dumps(one(a.one[0], a.one[1], None if level is None else int(level), elements)))
        return
    pairs = a.pairs.split(",")
    r = run(pairs, parse_levels(a.levels, pairs), set(filter(None, a.skip.split(","))), a.cap_gb, a.reference,
            a.elements)
    print("\n".join(table(r)))
    out = ROOT / "out" / "benchmarks"
    out.mkdir(parents=True, exist_ok=True)
    (out / ("cost.json" if a.elements is None else f"cost-{a.elements}.json")).write_text(json.dumps(r, indent=1))
    print(json.dumps(r))


if __name__ == "__main__":
    main()
