"""The Stribeck-type curve μ(λ) of femgear's mixed lubrication (issue 38, item 2): the figure of docs/models/lubrication.md.

    PYTHONPATH=$PWD python studies/validation/stribeck.py [--coarse]      # writes docs/figures/stribeck.svg, out/stribeck.json

One rough line contact at gear conditions: w' = 300 N/mm, R = 10 mm (p_H 1.05 GPa), SRR 0.3, bulk 60 °C,
the library's mineral ISO VG 100 (``mineral-vg100``, τ0 5 MPa), composite σ = 0.3 µm, boundary μ_b = 0.1, the
entrainment speed swept from 1 mm/s to 20 m/s; λ = h_c/σ with h_c the smooth contact's thermal central film
(:func:`femgear.physics.lubrication.traction.thermal_central_film`).  μ of the ``formula`` level with the
Johnson–Greenwood–Poon load sharing (:mod:`femgear.physics.lubrication.mixed`), the scene's asperity statistics
ηβσ 0.04, σ/β 3e-3: Greenwood–Tripp asperities with the fluid film the mean gap (femgear's default) and the
separation (the split before, bounded by p_C(0)), Greenwood–Williamson asperities (Gelinck & Schipper's law), and
Greenwood–Tripp with rougher statistics 0.1, 0.03, and the load share of λ alone of Zhou & Hoeprich (1991),
exp(−B λ^C) with Wingertszahn et al.'s B 1.90, C 0.99 (``roughness.contact = "zhou-hoeprich"``), beside the smooth
film.
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[2]
W, R, SRR, T_BULK, SIGMA, MU_B = 3.0e5, 0.010, 0.3, 333.15, 0.3e-6, 0.1
#: (label, contact law, fluid film, ηβσ, σ/β)
ASPERITIES = (("Greenwood–Tripp, mean gap (default)", "greenwood-tripp", "mean-gap", 0.04, 3e-3),
              ("Greenwood–Tripp, film = separation (before)", "greenwood-tripp", "separation", 0.04, 3e-3),
              ("Greenwood–Williamson, mean gap", "greenwood-williamson", "mean-gap", 0.04, 3e-3),
              ("Greenwood–Tripp, mean gap, ηβσ 0.1, σ/β 0.03", "greenwood-tripp", "mean-gap", 0.1, 0.03),
              ("Zhou–Hoeprich, W_C/W = exp(−1.90 λ^0.99)", "zhou-hoeprich", "mean-gap", 0.04, 3e-3))


def setup(coarse: bool = False) -> np.ndarray:
    """The entrainment speeds [m/s]."""
    return np.geomspace(1e-3, 20.0, 9 if coarse else 41)


def _parts():
    from femgear.physics.contact.hertz import reduced_modulus
    from femgear.physics.lubrication.flash import thermal_effusivity
    from femgear.physics.lubrication.library import library_oil, oil_table
    from femgear.physics.lubrication.oil import OilLaw
    from femgear.physics.lubrication.path import Solids

    t = oil_table(library_oil("mineral-vg100"), T_BULK)
    law = OilLaw(eta0=t["viscosity"], alpha=t["pressure_viscosity"], beta_t=t["temperature_viscosity"], T0=T_BULK,
                 rho0=t["density"], expansion=t["thermal_expansion"])
    B = thermal_effusivity(44.0, 7850.0, 470.0)
    return law, reduced_modulus(206e9, 0.3), Solids(B1=B, B2=B, k_oil=t["conductivity"]), t["eyring_stress"]


def run(coarse: bool = False) -> dict:
    from femgear.physics.lubrication.mixed import Roughness, mixed_line_friction
    from femgear.physics.lubrication.traction import line_contact_friction, thermal_central_film

    law, E, solids, tau0 = _parts()
    ue = setup(coarse)
    h = thermal_central_film(np.full(ue.shape, W), R, ue, SRR, T_BULK, law, E, solids)[0]
    smooth = line_contact_friction(W, R, ue, SRR, T_BULK, law, E, solids, tau0=tau0)
    curves = []
    for label, contact, film, ebs, sb in ASPERITIES:
        res, split = mixed_line_friction(W, R, ue, SRR, T_BULK, law, E, solids, Roughness(SIGMA, ebs, sb, contact, film),
                                         MU_B, tau0=tau0)
        curves.append({"label": label, "contact": contact, "fluid_film": film, "eta_beta_sigma": ebs,
                       "sigma_over_beta": sb, "mu": res.mu.tolist(),
                       "asperity_fraction": split.asperity_fraction.tolist(), "flash_max": res.flash_max.tolist()})
    return {"ue": ue.tolist(), "lambda": (h / SIGMA).tolist(), "mu_smooth": smooth.mu.tolist(), "curves": curves,
            "inputs": {"w": W, "R": R, "srr": SRR, "T_bulk": T_BULK, "sigma": SIGMA, "mu_b": MU_B, "oil": "mineral-vg100",
                       "eta0": law.eta0, "alpha": law.alpha, "tau0": tau0, "E_red": E}}


def plot(res: dict, path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    lam = np.array(res["lambda"])
    fig, ax = plt.subplots(figsize=(6.4, 4.0))
    ax.semilogx(lam, res["mu_smooth"], "k--", label="smooth flanks (full film)")
    for c, colour in zip(res["curves"], ("C0", "C1", "C2", "C3", "C4"), strict=True):
        ax.semilogx(lam, c["mu"], colour, label=c["label"])
        ax.semilogx(lam, np.array(c["asperity_fraction"]) * MU_B, colour, ls=":", lw=1)
    ax.axhline(MU_B, color="grey", lw=0.8)
    ax.text(lam[-1], MU_B, " μ_b", va="center", ha="left", color="grey")
    ax.set_xlabel("λ = h_c / σ (smooth thermal central film over the composite roughness)")
    ax.set_ylabel("μ  (dotted: asperity part μ_b W_C/W)")
    ax.set_title("femgear formula level, w' 300 N/mm, R 10 mm, SRR 0.3, VG 100 at 60 °C, σ 0.3 µm", fontsize=9)
    ax.set_ylim(0, 0.11)
    ax.legend(fontsize=8)
    fig.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, metadata={"Date": None})
    plt.close(fig)


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--coarse", action="store_true")
    args = p.parse_args(argv)
    res = run(args.coarse)
    for n, c in enumerate(res["curves"], 1):
        print(f"curve {n}: {c['label']}")
    print(" λ        μ smooth   " + "   ".join(f"μ({n})  W_C/W" for n in range(1, len(res["curves"]) + 1)))
    for i, lam in enumerate(res["lambda"]):
        print(f"{lam:7.3f}  {res['mu_smooth'][i]:9.4f}   " + "   ".join(
            f"{c['mu'][i]:6.4f}  {c['asperity_fraction'][i]:5.3f}" for c in res["curves"]))
    out = ROOT / "out"
    out.mkdir(exist_ok=True)
    (out / "stribeck.json").write_text(json.dumps(res, indent=1))
    plot(res, ROOT / "docs" / "figures" / "stribeck.svg")
    return 0


if __name__ == "__main__":
    sys.exit(main())
