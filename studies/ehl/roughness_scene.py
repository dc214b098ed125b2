"""The scene's [roughness] table along the gear path: what the paper's single peak does to the film.

    python studies/ehl/roughness_scene.py [--positions=9] [KEY=VALUE ...]

The baseline scene (studies/paper_baseline.toml) gets a ``[roughness.peak]`` (defaults below;
any scene override may be appended, e.g. ``roughness.peak.amplitude=0.2e-6``) and a
``[roughness.synthetic]`` surface. At each path position (Hertz line contact of the load
sharing, Roelands + Dowson–Higginson oil at the ambient temperature, isothermal FE line EHL
at level 6, as the ``ehl-line`` level solves it) the film is solved smooth and with the
peak fixed at x0 in the contact (the paper's model: ``moving = false``), and, at the pitch
point, with the synthetic surface and with the peak carried through the contact by its
flank (``moving = true``, transient, c = 1 +- SRR/2). The peak is given in metres and
converted per position with the local R and b (:func:`femgear.physics.ehl.core.surface.scene_features`).

Prints a table of h_min and p_max with and without roughness and one JSON line; writes
out/roughness/roughness_scene.{json,png}. This is the path-level effect of the scene keys;
the lubrication levels (``ehl-line``, ``tehl``, ``tehl-point``) do not read them yet.
"""

from __future__ import annotations

import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import json
import sys
import time
from pathlib import Path

import numpy as np

from femgear.case import build_case
from femgear.levels.contact import contact_pass
from femgear.levels.lubrication import oil_law
from femgear.physics.contact.hertz import reduced_modulus
from femgear.physics.ehl.core.surface import scene_features, surface_speed
from femgear.physics.ehl.dimensional import EHLOil, solve_line_dimensional
from femgear.physics.ehl.fe.line import X0_DEFAULT
from femgear.physics.ehl.transient import solve_line_transient
from femgear.scene.load import read_toml, scene_from_dict

ROOT = Path(__file__).resolve().parents[2]
OUT = ROOT / "out" / "roughness"
DEFAULTS = ("roughness.peak.amplitude=0.1e-6", "roughness.peak.wavelength=15e-6", "roughness.peak.x0=0.0",
            "roughness.synthetic.rq=0.05e-6", "roughness.synthetic.correlation_length=10e-6",
            "roughness.synthetic.seed=1")
LEVEL = 6


def _oil(scene, T: float) -> EHLOil:
    law = oil_law(build_case(scene))
    return EHLOil(eta0=float(law.viscosity(0.0, T)), alpha=law.alpha, viscosity="roelands", compressible=True)


def position(scene, w, R, ue, E_red, oil) -> dict:
    smooth = solve_line_dimensional(w, R, ue, E_red, oil, level=LEVEL)
    b = smooth.a
    h = (1.5 - X0_DEFAULT) / (16 * 2**LEVEL)
    feats = scene_features(scene.roughness, R, b, extent=(X0_DEFAULT - 20.0, 1.5), h=h)
    peak = solve_line_dimensional(w, R, ue, E_red, oil, level=LEVEL, surface=feats[0][0])
    return {"b": b, "hmin": smooth.hmin, "hc": smooth.hc, "pmax": smooth.pmax, "hmin_peak": peak.hmin,
            "pmax_peak": peak.pmax, "feats": feats, "smooth": smooth, "peak": peak}


def pitch_extras(scene, w, R, ue, srr, E_red, oil, base: dict) -> dict:
    """Synthetic surface (stationary) and the moving peak at the pitch point."""
    feats = base["feats"]
    syn = solve_line_dimensional(w, R, ue, E_red, oil, level=LEVEL, surface=feats[1][0])
    sm = base["smooth"]
    res = sm.result
    hs = base["b"] ** 2 / R
    pk = scene.roughness.peak
    c = surface_speed(float(srr), pk.member)
    start = -3.0  # the peak starts in the inlet, 3 b upstream of the centre
    moving = feats[0][0]
    shift = start - pk.x0 / base["b"]

    def feature(xi):
        return moving(xi - shift)

    rheology = {"viscosity": "roelands", "compressible": True, "ph": sm.ph, "z": oil.roelands_z()}
    tr = solve_line_transient(res.M, res.L, feature, speed=c, T_end=(1.5 - start) / c, level=5,
                              rheology=rheology)
    return {"hmin_synthetic": syn.hmin, "pmax_synthetic": syn.pmax, "hmin_moving_peak": float(tr.Hmin.min() * hs),
            "pmax_moving_peak": float(tr.Pmax.max() * sm.ph), "speed": c,
            "x": (sm.x / base["b"]).tolist(), "h_smooth": sm.h.tolist(), "h_peak": base["peak"].h.tolist(),
            "h_synthetic": syn.h.tolist(), "p_smooth": sm.p.tolist(), "p_peak": base["peak"].p.tolist(),
            "p_synthetic": syn.p.tolist()}


def setup(overrides: tuple[str, ...] = ()):
    """The baseline scene with the study's roughness (DEFAULTS) and ``overrides``."""
    return scene_from_dict(read_toml(ROOT / "studies" / "paper_baseline.toml"), [*DEFAULTS, *overrides], warn=False)


def run(positions: int = 9, overrides: tuple[str, ...] = ()) -> dict:
    scene = setup(overrides)
    cp = contact_pass(build_case(scene), n=positions)
    E_red = reduced_modulus(scene.material.youngs_modulus, scene.material.poisson_ratio)
    w = cp.line_loads()
    T = scene.operating.ambient_temperature
    oil = _oil(scene, T)
    rows, extras = [], {}
    for i in range(cp.kin.u.size):
        if not (w[i] > 0 and cp.kin.R[i] > 0):
            continue
        r = position(scene, float(w[i]), float(cp.kin.R[i]), float(cp.kin.ue[i]), E_red, oil)
        rows.append({"s_mm": float(cp.kin.s[i] * 1e3), "w": float(w[i]), "srr": float(cp.kin.srr[i]),
                     **{k: float(v) for k, v in r.items() if k in ("b", "hmin", "hc", "pmax", "hmin_peak", "pmax_peak")}})
        if i == cp.pitch_index:
            extras = pitch_extras(scene, float(w[i]), float(cp.kin.R[i]), float(cp.kin.ue[i]), float(cp.kin.srr[i]),
                                  E_red, oil, r)
    return {"peak": scene.roughness.peak.model_dump(), "synthetic": scene.roughness.synthetic.model_dump(),
            "rows": rows, "pitch": extras}


def plot(res: dict, path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    s = [r["s_mm"] for r in res["rows"]]
    fig, ax = plt.subplots(1, 3, figsize=(15, 4.5))
    ax[0].plot(s, [r["hmin"] * 1e6 for r in res["rows"]], "o-", label="smooth")
    ax[0].plot(s, [r["hmin_peak"] * 1e6 for r in res["rows"]], "s-", label="with the peak at x0 (steady)")
    ax[0].set(xlabel="distance from the pitch point s [mm]", ylabel="h_min [µm]", title="minimum film along the path")
    ax[0].legend(fontsize=8)
    ax[1].plot(s, [r["pmax"] / 1e9 for r in res["rows"]], "o-", label="smooth")
    ax[1].plot(s, [r["pmax_peak"] / 1e9 for r in res["rows"]], "s-", label="with the peak")
    ax[1].set(xlabel="s [mm]", ylabel="p_max [GPa]", title="maximum pressure along the path")
    ax[1].legend(fontsize=8)
    p = res["pitch"]
    x = np.array(p["x"])
    for key, lab in (("smooth", "smooth"), ("peak", "peak (steady)"), ("synthetic", "synthetic surface")):
        ax[2].plot(x, np.array(p[f"h_{key}"]) * 1e6, label=lab)
    hc = float(np.interp(0.0, x, np.array(p["h_smooth"]))) * 1e6
    ax[2].set(xlim=(-1.5, 1.5), ylim=(0, 2.0 * hc), xlabel="x / b", ylabel="h [µm]", title="film at the pitch point")
    ax[2].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def main(argv: list[str]) -> dict:
    positions = next((int(a.split("=")[1]) for a in argv if a.startswith("--positions=")), 9)
    overrides = tuple(a for a in argv if not a.startswith("--"))
    t0 = time.perf_counter()
    res = run(positions, overrides)
    print(f"{'s [mm]':>7} {'SRR':>6} {'hmin':>7} {'+peak':>7} {'pmax':>6} {'+peak':>6}   (µm, GPa)")
    for r in res["rows"]:
        print(f"{r['s_mm']:7.2f} {r['srr']:6.2f} {r['hmin'] * 1e6:7.3f} {r['hmin_peak'] * 1e6:7.3f} "
              f"{r['pmax'] / 1e9:6.3f} {r['pmax_peak'] / 1e9:6.3f}")
    p = res["pitch"]
    print(f"pitch point: synthetic surface hmin {p['hmin_synthetic'] * 1e6:.3f} µm, pmax {p['pmax_synthetic'] / 1e9:.3f} "
          f"GPa; moving peak (c = {p['speed']:.2f}) hmin {p['hmin_moving_peak'] * 1e6:.3f} µm, "
          f"pmax {p['pmax_moving_peak'] / 1e9:.3f} GPa")
    OUT.mkdir(parents=True, exist_ok=True)
    (OUT / "roughness_scene.json").write_text(json.dumps(res))
    plot(res, OUT / "roughness_scene.png")
    summary = {"rows": res["rows"], **{k: v for k, v in p.items() if not isinstance(v, list)},
               "seconds": time.perf_counter() - t0}
    print(json.dumps(summary))
    return summary


if __name__ == "__main__":
    main(sys.argv[1:])
