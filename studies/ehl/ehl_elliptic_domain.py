"""Domain convergence of the elliptic point EHL: Hc on enlarged domains (issue 15, helper h15d).

For each (M, L) and lambda = R_x/R_y, Hc is solved on the default domain
(:func:`femgear.physics.ehl.core.domain.default_domain`) and on domains enlarged k times (inlet and Y
half-width x k, ``default_domain(..., enlarge=(k, k))``, X = 0 kept on a node), each on two
levels (grid convergence), then extrapolated to the unbounded domain from the two largest k
assuming Hc(k) = Hc_inf + c / k: the pressure of a slender contact decays along the contact
line like the load of a local rigid line contact, 1/h(Y) ~ 1/Y^2, so the load beyond the
domain edge, and with it the error of Hc, falls like 1/k (docs/elliptic_regimes.md). The
table puts the result beside Nijenbanning, Venner & Moes (1994, Wear 176:217;
:func:`femgear.physics.contact.film.nvm_central`) and Hamrock & Dowson (1977, J. Lubr. Technol.
99:264, at 2U = 1e-11; :func:`studies.ehl.ehl_elliptic.hd_moes`), and reports where the load
goes: the share of the load upstream of X = -2a, the share outside |Y| <= b and the centre
pressure P(0, 0) (Hertzian units of the circular contact).

Usage: PYTHONPATH=. python studies/ehl/ehl_elliptic_domain.py [--cases 20,10 100,10]
       [--ratios 0.5 0.2 0.1] [--ks 1 2 3] [--levels 3 4] [--method fas]
Writes out/ehl_elliptic_domain.json.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import time

import numpy as np

from femgear.physics.contact.film import nvm_central
from femgear.physics.ehl.core import params as pr
from femgear.physics.ehl.core.domain import default_domain, hertz_ellipse
from femgear.physics.ehl.point import solve_point
from studies.ehl.ehl_elliptic import hd_moes


def load_shares(r, ratio: float) -> dict:
    """Where the load sits: upstream of X = -2a, outside |Y| <= b, and P at the centre."""
    a, b, _ = hertz_ellipse(ratio)
    x, y, P = r.x, r.y, r.P
    W = P.sum()
    return {"inlet_share": float(P[:, x < -2 * a].sum() / W),
            "side_share": float(P[np.abs(y) > b].sum() / W),
            "P00": float(P[int(np.argmin(np.abs(y))), int(np.argmin(np.abs(x)))])}


def one(M: float, L: float, ratio: float, k: float, level: int, method: str) -> dict:
    H = float(nvm_central(M, L, ratio)) / pr.point_h_moes_factor(M)
    dom = default_domain(ratio, H, enlarge=(k, k))
    t0 = time.perf_counter()
    r = solve_point(M, L, ratio=ratio, level=level, method=method, domain=dom)
    ix = int(np.argmin(np.abs(r.x)))
    if abs(r.x[ix]) > 1e-9 * (r.x[1] - r.x[0]):
        raise RuntimeError(f"X = 0 is not a node of {dom}")
    return {"M": M, "L": L, "ratio": ratio, "k": k, "level": level, "Hc": r.Hc, "Hmin": r.Hmin,
            "Pmax": float(r.P.max()), "seconds": time.perf_counter() - t0,
            "fallback": bool(r.history.get("fallback")), **load_shares(r, ratio)}


def extrapolate(rows: list[dict]) -> float | None:
    """Hc_inf from Hc(k) = Hc_inf + c/k on the finest level of the two largest k."""
    top = max(r["level"] for r in rows)
    fine = sorted((r for r in rows if r["level"] == top), key=lambda r: r["k"])
    if len(fine) < 2 or fine[-1]["k"] == fine[-2]["k"]:
        return None
    (k1, h1), (k2, h2) = ((r["k"], r["Hc"]) for r in fine[-2:])
    c = (h1 - h2) / (1 / k1 - 1 / k2)
    return h2 - c / k2


def setup(argv: list[str] | None = None) -> argparse.Namespace:
    """The command line ``argv`` parsed (defaults: the documented study)."""
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cases", nargs="*", default=["20,10", "100,10"])
    ap.add_argument("--ratios", nargs="*", type=float, default=[0.5, 0.2, 0.1])
    ap.add_argument("--ks", nargs="*", type=float, default=[1.0, 2.0, 3.0])
    ap.add_argument("--levels", nargs="*", type=int, default=[3, 4])
    ap.add_argument("--method", default="fas")
    return ap.parse_args(argv)


def run(args: argparse.Namespace) -> list[dict]:
    """Every (case, ratio, enlargement k, level): Hc and the load shares, with Hc(k -> inf) per (case, ratio)."""
    out = []
    print(f"{'M':>4} {'L':>3} {'lam':>5} {'k':>4} {'lev':>3} {'Hc':>7} {'grid%':>6} {'Hmin':>6} "
          f"{'Pmax':>6} {'P00':>6} {'inlet':>6} {'side':>6} {'s':>6}")
    for case in args.cases:
        M, L = (float(v) for v in case.split(","))
        for lam in args.ratios:
            rows = []
            for k in args.ks:
                prev = None
                for lev in args.levels:
                    row = one(M, L, lam, k, lev, args.method)
                    rows.append(row)
                    grid = "" if prev is None else f"{100 * (row['Hc'] / prev - 1):+6.2f}"
                    prev = row["Hc"]
                    print(f"{M:4g} {L:3g} {lam:5g} {k:4g} {lev:3d} {row['Hc']:7.4f} {grid:>6} "
                          f"{row['Hmin']:6.3f} {row['Pmax']:6.3f} {row['P00']:6.3f} "
                          f"{row['inlet_share']:6.3f} {row['side_share']:6.3f} "
                          f"{row['seconds']:6.1f}{' fallback' if row['fallback'] else ''}", flush=True)
            inf, nvm, hd = extrapolate(rows), float(nvm_central(M, L, lam)), hd_moes(M, L, lam)
            hd_pc = f", {100 * (inf / hd - 1):+.1f} % HD" if inf is not None and hd > 0 else ""  # HD: 0 at L = 0
            ext = "-" if inf is None else f"{inf:.3f} ({100 * (inf / nvm - 1):+.1f} % NVM{hd_pc})"
            print(f"  -> ({M:g}, {L:g}) lambda {lam:g}: Hc(k -> inf) {ext}; NVM {nvm:.3f}, HD {hd:.3f}", flush=True)
            out.append({"M": M, "L": L, "ratio": lam, "rows": rows, "Hc_inf": inf, "NVM": nvm, "HD": hd})
    return out


def main(argv: list[str] | None = None) -> int:
    args = setup(argv)
    out = run(args)
    os.makedirs("out", exist_ok=True)
    with open("out/ehl_elliptic_domain.json", "w") as f:
        json.dump(out, f, indent=1)
        f.write("\n")
    print(json.dumps([{k: o[k] for k in ("M", "L", "ratio", "Hc_inf", "NVM", "HD")} for o in out]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
