"""What a compliant housing does to the baseline pair: natural frequencies, bearing and mesh forces, the receiver.

    python studies/dynamics/housing_effect.py [--coarse]

The baseline (lumped dynamics, contact-line stiffness, no friction) on a rigid housing and on the default FE housing
(``[housing] model = "fe"``: cast iron, 10 mm walls, quadratic tetrahedra of 15 mm, 60 fixed-interface modes;
``--coarse``: 30 mm elements, 24 modes), the linear response per mesh order 1–6 over 100–1500 rpm:

- the natural frequencies with the housing against the rigid housing (Shock and Vibration 2017, art. 4846532:
  housing compliance lowers them), the lowest mode that strains the mesh in particular;
- the relative change of the bearing loads and of the mesh forces per line (the same paper: the bearing forces
  change significantly, the mesh force little), median, 90th percentile and largest;
- the receiver (sensor = the housing's own FRFs × the rigid-housing bearing forces) against the coupled housing, at
  the housing's stiffness and 1000 times stiffer (the stiff-housing limit);
- the Craig–Bampton frequencies against the unreduced housing's in the retained band.
Writes ``out/housing_effect/housing_effect.json``.
"""

from __future__ import annotations

import sys
import time
from dataclasses import replace

import numpy as np

try:
    from studies import _common as C
except ImportError:
    import pathlib

    sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2]))
    from studies import _common as C

SPEEDS = np.linspace(100.0, 1500.0, 29)


def setup(coarse: bool = False) -> list[str]:
    """The housing's scene keys."""
    return ['housing.model="fe"', "housing.check_reduction=true"] + \
        (["housing.mesh_size=0.03", "housing.modes=24"] if coarse else [])


def _stats(x: np.ndarray) -> dict:
    return {"median": float(np.median(x)), "p90": float(np.percentile(x, 90)), "max": float(np.max(x))}


def run(coarse: bool = False) -> dict:
    from femgear.levels import housing as housing_levels
    from femgear.physics.housing.fe import housing_frf, modal_damping
    from femgear.system.dynamics import build_model
    from femgear.system.dynamics.housing import couple_housing
    from femgear.system.dynamics.modal import RESONANCE_MESH_ENERGY, modal_analysis
    from femgear.system.dynamics.nvh import housing_sweep

    t0 = time.perf_counter()
    case = C.case(setup(coarse), static=True)
    layer = housing_levels.of(case)
    rigid = build_model(case, "lumped", stiffness="contact-line", friction=0.0, rigid_housing=True)
    red = layer.reduced

    def lowest_mesh_mode(model):
        m = modal_analysis(model)
        return float(m.frequencies[(m.frequencies > 1.0) & (m.energy["mesh"] >= RESONANCE_MESH_ENERGY)][0])

    out = {"housing_mass": red.mass, "full_dofs": layer.full_dofs, "fixed_interface_modes": int(red.fixed_interface_hz.size),
           "reduction_check": {"band_hz": layer.check.band, "max_error": layer.check.max_error,
                               "modes": int(layer.check.full.size)}}
    for label, h in (("housing", red), ("stiff_1000x", replace(red, K=1e3 * red.K,
                                                               C=modal_damping(1e3 * red.K, red.M, red.damping_ratio)))):
        coupled = couple_housing(rigid, h)
        sweep = housing_sweep(coupled, replace(layer, reduced=h), SPEEDS, 6)
        frf = housing_frf(h, np.unique(sweep.frequency), layer.sensors)
        rec = housing_sweep(rigid, replace(layer, coupling="receiver", frf=frf, reduced=None), SPEEDS, 6)
        change = sweep.force_change()
        a = np.abs(sweep.sensor_acceleration)
        out[label] = {
            "natural_frequencies": np.array(coupled.flexible_modes_hz[:10]),
            "lowest_mesh_mode_hz": lowest_mesh_mode(coupled),
            "bearing_force_change": _stats(change["bearing"]), "mesh_force_change": _stats(change["mesh"]),
            "receiver_error": float(np.max(np.abs(rec.sensor_acceleration - sweep.sensor_acceleration)) / a.max()),
            "max_sensor_acceleration": float(a.max())}
    out["rigid"] = {"natural_frequencies": np.array(rigid.flexible_modes_hz[:10]),
                    "lowest_mesh_mode_hz": lowest_mesh_mode(rigid)}
    out["seconds"] = time.perf_counter() - t0
    return out


def table(res: dict) -> str:
    h, s, r = res["housing"], res["stiff_1000x"], res["rigid"]
    pct = lambda d: f"median {100 * d['median']:.1f} %, 90th percentile {100 * d['p90']:.0f} %, max {100 * d['max']:.0f} %"  # noqa: E731
    c = res["reduction_check"]
    return "\n".join([
        f"FE housing: {res['housing_mass']:.1f} kg, {res['full_dofs']} DOF, {res['fixed_interface_modes']} fixed-interface "
        f"modes; Craig-Bampton vs unreduced: {c['modes']} modes below {c['band_hz']:.0f} Hz within "
        f"{100 * c['max_error']:.2f} %",
        "natural frequencies [Hz], rigid housing: " + " ".join(f"{f:.0f}" for f in r["natural_frequencies"][:6]),
        "                        on the housing:  " + " ".join(f"{f:.0f}" for f in h["natural_frequencies"][:6]),
        f"lowest mode straining the mesh: {r['lowest_mesh_mode_hz']:.0f} Hz rigid -> {h['lowest_mesh_mode_hz']:.0f} Hz "
        f"({100 * (h['lowest_mesh_mode_hz'] / r['lowest_mesh_mode_hz'] - 1):+.1f} %); 1000x stiffer housing "
        f"{s['lowest_mesh_mode_hz']:.0f} Hz",
        f"over 100-1500 rpm x orders 1-6: bearing loads change {pct(h['bearing_force_change'])}; "
        f"mesh forces {pct(h['mesh_force_change'])}",
        f"receiver (rigid-housing bearing forces x the housing's FRFs) vs coupled: {100 * h['receiver_error']:.0f} % of "
        f"the largest sensor line; 1000x stiffer housing: {100 * s['receiver_error']:.2f} %"])


def main(argv: list[str]) -> int:
    opts = C.parse_args(argv)
    res = run(opts["coarse"])
    print(f"housing effect on the baseline ({'coarse' if opts['coarse'] else 'default'} housing), {res['seconds']:.0f} s")
    print(table(res))
    print("json:", C.write_results("housing_effect", res))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
