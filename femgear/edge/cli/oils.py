"""``femgear oils [NAME] [--at T] [--json]``: the oil library with its sources.

Lists every named oil of :mod:`femgear.physics.lubrication.library` (``oil.name`` in a scene): base,
ν at 40 and 100 °C, ρ15, α and β_T at 40 °C, the traction parameters and the source of each data group;
a group without a published source is marked "no source".  With NAME, that oil's ``[oil]`` keys as a
scene would get them at ``--at`` (default 313.15 K), ready to paste.
"""

from __future__ import annotations

import argparse

from femgear.errors import ArgumentError


def register(sub) -> None:
    p = sub.add_parser("oils", help="list the oil library (oil.name) with its sources",
                       description="The named oils of femgear's library with their data and sources; "
                                   "oil.name = NAME in a scene fills every [oil] key from it.")
    p.add_argument("name", metavar="NAME", nargs="?", default=None, help="one oil: its [oil] keys at --at")
    p.add_argument("--at", type=float, default=313.15, metavar="T",
                   help="reference temperature of the printed [oil] keys [K] (default 313.15)")
    p.add_argument("--json", action="store_true", help="print the library as one JSON object")
    p.set_defaults(func=_oils)


def _oils(args: argparse.Namespace) -> int:
    from femgear.edge.cli.common import emit_json
    from femgear.physics.lubrication.library import LIBRARY, library_oil, oil_table

    if not 200.0 < args.at < 600.0:
        raise ArgumentError("--at", f"an absolute oil temperature in K (got {args.at:g})")
    if args.name is not None:
        try:
            oil = library_oil(args.name)
        except KeyError as exc:
            raise ArgumentError("NAME", str(exc.args[0])) from None
        table = oil_table(oil, args.at)
        if args.json:
            emit_json({"name": oil.name, "oil": table, "sources": oil.sources, "unsourced": list(oil.unsourced())})
            return 0
        print(f'# {oil.name}: {oil.description}\n[oil]\nname = "{oil.name}"')
        for key, value in table.items():
            print(f"{key} = {value:.6g}")
        _print_sources(oil)
        return 0
    rows = {name: _row(o, oil_table(o, 313.15)) for name, o in LIBRARY.items()}
    if args.json:
        emit_json({"oils": rows})
        return 0
    print(f"{'name':14s} {'base':8s} {'ν40':>7s} {'ν100':>7s} {'ρ15':>6s} {'α40':>6s} {'β40':>7s} {'τ0':>5s} {'Λ':>5s}")
    print(f"{'':14s} {'':8s} {'mm²/s':>7s} {'mm²/s':>7s} {'kg/m³':>6s} {'1/GPa':>6s} {'1/K':>7s} {'MPa':>5s} {'-':>5s}")
    for name, r in rows.items():
        print(f"{name:14s} {r['base']:8s} {r['nu40'] * 1e6:7.1f} {r['nu100'] * 1e6:7.2f} {r['rho15']:6.0f} "
              f"{r['alpha40'] * 1e9:6.1f} {r['beta40']:7.4f} {r['eyring_stress'] / 1e6:5.1f} "
              f"{r['limiting_shear_coeff']:5.2f}")
    print()
    for o in LIBRARY.values():
        print(f"{o.name}: {o.description}")
        _print_sources(o)
    return 0


def _row(oil, table) -> dict:
    return {"base": oil.base, "description": oil.description, "nu40": oil.kinematic_viscosity(313.15),
            "nu100": oil.kinematic_viscosity(373.15), "rho15": oil.rho15, "alpha40": table["pressure_viscosity"],
            "beta40": table["temperature_viscosity"], "eyring_stress": oil.eyring_stress,
            "limiting_shear_coeff": oil.limiting_shear_coeff, "sources": oil.sources, "unsourced": list(oil.unsourced())}


def _print_sources(oil) -> None:
    for group, source in oil.sources.items():
        print(f"  {group:18s} {source if source else 'no source (an estimate: the run says so)'}")
