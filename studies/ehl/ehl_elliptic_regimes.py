"""Elliptic EHL at low M: which Nijenbanning-Venner-Moes (1994) asymptote dominates, and
how much of the film the default domain truncates (issue 15, helper h15c).

For each (M, L) and lambda = R_x/R_y the table prints femgear's Hc (multigrid, default domain
:func:`femgear.physics.ehl.core.domain.default_domain`), optionally Hc on an enlarged domain (inlet x fx,
Y half-width x fy; Newton, which starts where the multigrid's cold start finds no node inside
the Hertz ellipse), NVM's Hc and its four asymptotes
(Nijenbanning, Venner & Moes 1994, Wear 176:217; terms as in
:func:`femgear.physics.contact.film.nvm_central`):

    H_RI = 145 (1 + 0.796 lam^(14/15))^(-15/7) lam^-1 M^-2      rigid-isoviscous
    H_EI = 3.18 c^(-14/25) lam^(-1/15) M^(-2/15)                 elastic-isoviscous
    H_RP = 1.29 (1 + 0.691 lam)^(-2/3) L^(2/3)                   rigid-piezoviscous
    H_EP = 1.48 c^(-7/20) lam^(-1/24) M^(-1/12) L^(3/4)           elastic-piezoviscous
    c = 1 + 0.006 ln lam + 0.63 lam^(4/7)

and the Hertzian-unit film Hh = Hc / (1.5 M)^(2/3) against the Hertz ellipse's X semi-axis
a: Hh >> a^2/2 means the film is much thicker than the Hertzian indentation, i.e. the
contact is close to rigid and its pressure spreads far beyond the ellipse.

Usage: python studies/ehl/ehl_elliptic_regimes.py [--cases 20,10 20,0 50,10]
       [--ratios 0.5 0.3 0.2 0.15 0.1 0.07 0.05 0.035 0.02] [--level 3] [--enlarge 2,4]
Writes out/ehl_elliptic_regimes.json.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import sys

from femgear.physics.contact.film import nvm_central
from femgear.physics.ehl.core import params as pr
from femgear.physics.ehl.core.domain import default_domain, hertz_ellipse
from femgear.physics.ehl.core.grid import Domain
from femgear.physics.ehl.point import solve_point


def nvm_terms(M: float, L: float, lam: float) -> dict:
    """The four NVM asymptotes (see the module docstring) and the blended Hc."""
    c = 1 + 0.006 * math.log(lam) + 0.63 * lam ** (4 / 7)
    return {"RI": 145 * (1 + 0.796 * lam ** (14 / 15)) ** (-15 / 7) / lam / M**2,
            "EI": 3.18 * c ** (-14 / 25) * lam ** (-1 / 15) * M ** (-2 / 15),
            "RP": 1.29 * (1 + 0.691 * lam) ** (-2 / 3) * L ** (2 / 3),
            "EP": 1.48 * c ** (-7 / 20) * lam ** (-1 / 24) * M ** (-1 / 12) * L**0.75,
            "NVM": float(nvm_central(M, L, lam))}


def enlarged(M: float, lam: float, fx: float, fy: float) -> Domain:
    """The default domain with its inlet x fx and its Y half-width x fy, X = 0 kept on a node
    (``default_domain(..., enlarge=)``; until h15d the outlet was kept, which moved the centre
    off the nodes and read Hc up to 1.7 % low)."""
    H = float(nvm_central(M, 10.0, lam)) / pr.point_h_moes_factor(M)
    return default_domain(lam, H, enlarge=(fx, fy))


def one(M: float, L: float, lam: float, level: int, enlarge: tuple[float, float] | None) -> dict:
    row = {"M": M, "L": L, "ratio": lam, **nvm_terms(M, L, lam)}
    r = solve_point(M, L, ratio=lam, level=level, method="fas")
    row.update(Hc=r.Hc, Hmin=r.Hmin)
    a = hertz_ellipse(lam)[0]
    row["Hh_over_a2"] = r.Hc / pr.point_h_moes_factor(M) / (a * a / 2)
    if enlarge:
        try:
            big = solve_point(M, L, ratio=lam, level=level, method="newton", domain=enlarged(M, lam, *enlarge))
            row["Hc_big"] = big.Hc
        except Exception as exc:  # reported in the table: the enlarged grids are coarse
            row["Hc_big"] = None
            row["big_error"] = str(exc)[:120]
    return row


def setup(argv: list[str] | None = None) -> argparse.Namespace:
    """The command line ``argv`` parsed (defaults: the documented study)."""
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cases", nargs="*", default=["20,10", "20,0", "50,10"])
    ap.add_argument("--ratios", nargs="*", type=float,
                    default=[0.5, 0.3, 0.2, 0.15, 0.1, 0.07, 0.05, 0.035, 0.02])
    ap.add_argument("--level", type=int, default=3)
    ap.add_argument("--enlarge", default=None, help="fx,fy: also solve on the enlarged domain")
    ap.add_argument("--plot", action="store_true", help="write out/ehl_elliptic_regimes.png")
    return ap.parse_args(argv)


def run(args: argparse.Namespace) -> list[dict]:
    """Hc against lambda per (M, L) with NVM's regime films (and the enlarged domain with ``--enlarge``)."""
    enl = tuple(float(v) for v in args.enlarge.split(",")) if args.enlarge else None
    rows = []
    print(f"{'M':>4} {'L':>3} {'lam':>6} {'Hc':>6} {'Hc_big':>6} {'NVM':>6} {'dNVM%':>6} "
          f"{'H_RI':>6} {'H_EI':>5} {'H_RP':>5} {'H_EP':>5} {'Hh/(a2/2)':>9}")
    for case in args.cases:
        M, L = (float(v) for v in case.split(","))
        for lam in args.ratios:
            row = one(M, L, lam, args.level, enl)
            rows.append(row)
            big = f"{row['Hc_big']:6.2f}" if row.get("Hc_big") else "     -"
            print(f"{M:4g} {L:3g} {lam:6.3g} {row['Hc']:6.2f} {big} {row['NVM']:6.2f} "
                  f"{100 * (row['Hc'] / row['NVM'] - 1):6.1f} {row['RI']:6.2f} {row['EI']:5.2f} "
                  f"{row['RP']:5.2f} {row['EP']:5.2f} {row['Hh_over_a2']:9.2f}", flush=True)
    return rows


def main(argv: list[str] | None = None) -> int:
    args = setup(argv)
    rows = run(args)
    os.makedirs("out", exist_ok=True)
    with open("out/ehl_elliptic_regimes.json", "w") as f:
        json.dump(rows, f, indent=1)
        f.write("\n")
    if args.plot:
        plot(rows)
    return 0


def plot(rows: list[dict]) -> None:
    """Hc against lambda per (M, L): femgear (default and enlarged domain), NVM, its
    asymptotes and Brewe-Hamrock-Taylor's rigid-isoviscous film."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from femgear.physics.contact.film import rigid_isoviscous_point
    cases = sorted({(r["M"], r["L"]) for r in rows})
    fig, axes = plt.subplots(1, len(cases), figsize=(5 * len(cases), 4), squeeze=False)
    for ax, (M, L) in zip(axes[0], cases):
        rr = [r for r in rows if (r["M"], r["L"]) == (M, L)]
        lam = [r["ratio"] for r in rr]
        ax.loglog(lam, [r["Hc"] for r in rr], "o-", label="femgear (default domain)")
        big = [(r["ratio"], r["Hc_big"]) for r in rr if r.get("Hc_big")]
        if big:
            ax.loglog(*zip(*big), "r^", label="femgear (enlarged domain)")
        ax.loglog(lam, [r["NVM"] for r in rr], "k--", label="NVM 1994")
        for key in ("RI", "EI", "EP") if L else ("RI", "EI"):
            ax.loglog(lam, [r[key] for r in rr], ":", label=f"NVM H_{key}")
        ax.loglog(lam, [rigid_isoviscous_point(v) / M**2 for v in lam], "-.", label="Brewe et al. rigid-iso")
        ax.set(xlabel="lambda = R_x/R_y", ylabel="Hc (Moes)", title=f"M = {M:g}, L = {L:g}")
        ax.grid(True, which="both", alpha=0.3)
    axes[0][0].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig("out/ehl_elliptic_regimes.png", dpi=110)


if __name__ == "__main__":
    sys.exit(main())
