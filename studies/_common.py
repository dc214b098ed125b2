"""Helpers shared by the paper-comparison studies: one case through the pipeline, a process pool, the paper's tables.

A *case* is a list of scene overrides of ``studies/paper_baseline.toml``, bound once
(:func:`case`) and run by the pipeline's :func:`femgear.pipeline.run_case` (:func:`run`); a study
reads the typed :class:`femgear.results.RunResult` (``result.tribology``, ``result.coupled.state``,
``result.case.path``), with the few derived tables here (:func:`deviation_tables`,
:func:`bearing_accelerations`, :func:`series`).  RunResults pickle, so cases run in worker processes.

The study protocol (ARCHITECTURE.md, "Studies"; the Devito habit): each study has ``setup()`` (what to run),
``run(coarse=...)`` (compute, return a dict of results) and ``main(argv)`` behind
``if __name__ == "__main__"`` (print, plot, write under out/); tests call ``run(coarse=True)``.

Resolution levels: ``coarse`` (CI) = 20 mesh periods with 10 dropped (the scene's integrator),
31 path positions and one dynamic pass (``physics.coupling = "one-way"``); ``static`` stops at the
quasi-static pass (``physics.dynamics = "none"``); the full level = the scene's numerics (100/50
mesh periods), 61 positions, iterated to the scene's tolerance.
"""

from __future__ import annotations

import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import json
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
BASELINE = ROOT / "studies" / "paper_baseline.toml"
OUT = ROOT / "out"
COARSE = ("numerics.dynamics_cycles=20", "numerics.transient_cycles=10")

#: Wang et al. 2026, Table 4: cycles [1e6] -> (x [µm], y [µm], v_x [m/s], v_y [m/s])
PAPER_TABLE4 = {
    "gear": {0: (0.402, 0.282, 0.040, 0.033), 1: (0.406, 0.289, 0.044, 0.053),
             2: (0.410, 0.298, 0.049, 0.059), 3: (0.419, 0.307, 0.055, 0.066)},
    "pinion": {0: (0.192, 0.306, 0.028, 0.037), 1: (0.197, 0.311, 0.037, 0.039),
               2: (0.202, 0.317, 0.041, 0.044), 3: (0.207, 0.325, 0.046, 0.049)},
}
#: Wang et al. 2026, Table 7: (rpm, N m) -> (point 1 theory, point 1 test, point 2 theory, point 2 test) [m/s²]
PAPER_TABLE7 = {
    (100, 100): (0.08474, 0.0809, 0.0576, 0.0519), (100, 150): (0.0882, 0.0863, 0.0599, 0.0503),
    (100, 200): (0.0871, 0.0831, 0.0592, 0.0549), (200, 100): (0.1249, 0.1221, 0.0844, 0.0717),
    (200, 150): (0.1351, 0.1481, 0.0913, 0.0778), (200, 200): (0.1283, 0.1389, 0.0867, 0.0809),
    (300, 100): (0.2392, 0.2351, 0.1605, 0.1481), (300, 150): (0.2585, 0.2931, 0.1734, 0.1496),
    (300, 200): (0.2456, 0.2305, 0.1648, 0.1374), (400, 100): (0.4578, 0.4396, 0.2890, 0.2855),
    (400, 150): (0.4819, 0.4473, 0.3042, 0.2549), (400, 200): (0.4699, 0.4687, 0.2966, 0.2564),
    (500, 100): (0.7731, 0.8625, 0.4849, 0.5374), (500, 150): (0.7358, 0.7236, 0.4959, 0.5297),
    (500, 200): (0.6795, 0.6564, 0.2674, 0.2992),
}
AMPLITUDE_KEYS = [(m, q, ax) for m in ("gear", "pinion") for q in ("displacement", "velocity") for ax in "xy"]


def case(overrides: list[str] | tuple[str, ...] = (), coarse: bool = False, static: bool = False,
         base: str | Path = BASELINE):
    """The bound :class:`femgear.case.Case` of ``overrides`` of ``base`` at the study's resolution."""
    from femgear.case import build_case
    from femgear.scene import load_scene

    levels = ["numerics.path_points=31"] if coarse else ["numerics.path_points=61"]
    levels += list(overrides)
    if coarse:
        levels += [*COARSE, 'physics.coupling="one-way"']
    if static:
        levels += ['physics.coupling="one-way"', 'physics.dynamics="none"']
    return build_case(load_scene(base, levels))


def run(overrides: list[str] | tuple[str, ...] = (), coarse: bool = False, static: bool = False,
        base: str | Path = BASELINE, timed: bool = False):
    """:func:`femgear.pipeline.run_case` of :func:`case`; with ``timed`` also the wall time of each
    coupling pass's parts (``CouplingState.timings``, passes 1, 2, ...) as ``(result, timings)``."""
    from femgear.pipeline import run_case

    passes: list[dict] = []
    result = run_case(case(overrides, coarse, static, base),
                      progress=(lambda s: passes.append(dict(s.timings)) if s.iteration else None) if timed else None)
    return (result, passes) if timed else result


def wear(result) -> np.ndarray:
    """(2, n) wear depth of pinion and gear along the path [m] (zeros without a wear level)."""
    w = result.tribology.wear
    return np.zeros((2, result.case.path.u.size)) if w is None else w


def thermal_deviation(result) -> np.ndarray:
    """(2, n) thermal flank deviation ζ_T of pinion and gear along the path [m] (zeros without a thermal level)."""
    z = result.tribology.thermal_deviation
    return np.zeros((2, result.case.path.u.size)) if z is None else z


def deviation_tables(result, n_phase: int = 128) -> tuple[np.ndarray, np.ndarray]:
    """(drive, coast) deviation tables (2 helices, ``n_phase``) of the run's wear and thermal deviation [m]."""
    from femgear.system.coupling.profile import mesh_deviation

    c = result.case
    dev = mesh_deviation(c.pair, c.path.u, wear(result).sum(axis=0), thermal_deviation(result).sum(axis=0),
                         c.stagger, n_phase)
    zero = np.zeros((2, n_phase))
    return (zero, zero) if dev is None else (dev.drive, dev.coast)


def response(result):
    """The last dynamic pass's :class:`femgear.system.dynamics.response.Response` (None without dynamics)."""
    st = None if result.coupled is None else result.coupled.state
    return None if st is None or st.dynamics is None else st.dynamics.response


def bearing_accelerations(result) -> dict[str, float]:
    """Time max of the radial bearing-housing acceleration [m/s²] at point 1 (pinion stations) and point 2
    (gear stations), raw and after the rig's 5 kHz filter (``_lp5k``)."""
    r = response(result)
    out = {}
    for suffix, a in (("", r.bearing_acceleration[:, :, :2]), ("_lp5k", rig_filter(r.t, r.bearing_acceleration[:, :, :2]))):
        acc = np.linalg.norm(a, axis=2)                                    # radial |a| per station
        out["acc_point1" + suffix] = float(acc[:, :2].max())              # pinion bearing housing
        out["acc_point2" + suffix] = float(acc[:, 2:].max())              # gear bearing housing
    return out


def series(result, periods: int = 10) -> dict[str, np.ndarray]:
    """The last ``periods`` mesh periods: time from 0, total mesh force, gear and pinion x-y displacement and velocity."""
    r = response(result)
    keep = r.t >= r.t[-1] - periods / r.mesh_frequency
    return {"t": r.t[keep] - r.t[keep][0], "mesh_force": r.mesh_force[keep].sum(axis=1),
            **{f"{m}.{k}": r.member(m, k)[keep, :2] for m in ("gear", "pinion") for k in ("displacement", "velocity")}}


def rig_filter(t: np.ndarray, a: np.ndarray, cutoff: float = 5000.0) -> np.ndarray:
    """The rig's measurement chain (paper §5.1): 4th-order Butterworth low-pass at 5 kHz, causal,
    started in its steady state for the first sample; along axis 0."""
    from scipy import signal

    fs = 1.0 / float(t[1] - t[0])
    if cutoff >= 0.5 * fs:
        return a
    sos = signal.butter(4, cutoff, fs=fs, output="sos")
    zi = signal.sosfilt_zi(sos)
    zi = zi.reshape(zi.shape + (1,) * (a.ndim - 1)) * a[:1]
    return signal.sosfilt(sos, a, axis=0, zi=zi)[0]


def _case(args):
    return run(*args[:3], **args[3])


def run_cases(cases: list[list[str]], coarse: bool = False, static: bool = False, workers: int = 2,
              **kw) -> list:
    """:func:`run` for every override list, on a pool of ``workers`` processes (order kept): RunResults
    (``(result, timings)`` pairs with ``timed=True``)."""
    jobs = [(list(c), coarse, static, kw) for c in cases]
    if workers <= 1 or len(jobs) == 1:
        return [_case(j) for j in jobs]
    with ProcessPoolExecutor(max_workers=min(workers, len(jobs))) as pool:
        return list(pool.map(_case, jobs))


def amplitude(result, member: str, quantity: str, axis: str) -> float:
    """Half peak-to-peak amplitude of the run's last dynamic pass in µm (displacement) or m/s (velocity)."""
    v = result.coupled.state.amplitudes[f"{member}.{quantity}.{axis}"]
    return v * 1e6 if quantity == "displacement" else v


def amplitude_table(cases: list[dict], labels: list[str], paper: dict | None = None) -> str:
    """Gear and pinion x, y displacement [µm] / velocity [m/s] per case, the paper's beside."""
    head = f"{'member':6s} {'case':>12s} | " + " | ".join(
        f"{('x' if ax == 'x' else 'y') + ('[µm]' if q == 'displacement' else '_v[m/s]'):>10s} {'paper':>6s}"
        for _, q, ax in AMPLITUDE_KEYS[:4])
    lines = [head, "-" * len(head)]
    for member in ("gear", "pinion"):
        for c, lab in zip(cases, labels):
            cells = []
            for i, (_, q, ax) in enumerate(AMPLITUDE_KEYS[:4]):
                p = paper[member].get(lab) if paper else None
                cells.append(f"{amplitude(c, member, q, ax):10.4g} " + (f"{p[i]:6.3f}" if p else f"{'-':>6s}"))
            lines.append(f"{member:6s} {str(lab):>12s} | " + " | ".join(cells))
    return "\n".join(lines)


def jsonable(obj):
    """numpy arrays and scalars → lists and floats, recursively."""
    if isinstance(obj, dict):
        return {str(k): jsonable(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [jsonable(v) for v in obj]
    if isinstance(obj, np.ndarray):
        return obj.tolist()
    if isinstance(obj, np.generic):
        return obj.item()
    return obj


def write_results(study: str, results: dict, name: str | None = None) -> Path:
    path = OUT / study / f"{name or study}.json"
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(jsonable(results), indent=1), encoding="utf-8")
    return path


def figure(nrows: int = 1, ncols: int = 2, size: tuple[float, float] = (11, 4)):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt.subplots(nrows, ncols, figsize=size, squeeze=False)


def save(fig, study: str, name: str) -> Path:
    import matplotlib.pyplot as plt

    path = OUT / study / name
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def parse_args(argv: list[str]) -> dict:
    """``--coarse``, ``--workers=N`` and other ``--key[=value]`` flags."""
    opts = {a.split("=")[0].lstrip("-"): (a.split("=", 1)[1] if "=" in a else True) for a in argv if a.startswith("--")}
    opts["coarse"] = bool(opts.get("coarse", False))
    opts["workers"] = int(opts.get("workers", 2))
    return opts


#: the paper's wear: its constant-coefficient Archard form on the whole load (the baseline scene's too; the studies of
#: the paper say so themselves, so that their figures do not move with the default, the asperity-borne load)
PAPER_WEAR = 'wear.load="total"'

#: the paper's Figs 4–5 cases: label → overrides (wear 1e6 cycles, flank temperature rise 30 K)
FLANK_CASES = {
    "none": ["wear.cycles=0.0", 'physics.thermal="none"', PAPER_WEAR],
    "wear": ["wear.cycles=1e6", 'physics.thermal="none"', PAPER_WEAR],
    "thermal": ["wear.cycles=0.0", "thermal.flank_temperature_rise=30.0", PAPER_WEAR],
    "wear+thermal": ["wear.cycles=1e6", "thermal.flank_temperature_rise=30.0", PAPER_WEAR],
}


def flank_cases(coarse: bool = False, workers: int = 2) -> dict:
    """The four flank-deviation cases (RunResults); coarse = the quasi-static pass (no dynamics), else converged."""
    cases = run_cases(list(FLANK_CASES.values()), coarse=coarse, static=coarse, workers=workers)
    return dict(zip(FLANK_CASES, cases))
