"""femgear's oil library: named oils with their sources (``oil.name`` in a scene; ``femgear oils``).

Each :class:`LibraryOil` holds what a data sheet and the literature give, each group with its
source (``None``: no published source: the run says so):

- viscosity–temperature: two measured points (T, ν), through which ASTM D341 (Ubbelohde–Walther,
  :mod:`femgear.physics.lubrication.walther`) carries ν to any temperature; η = ν ρ;
- density: ρ at 15 °C and the expansion ε of ρ(T) = ρ15 (1 − ε (T − 288.15 K));
- pressure–viscosity: Roelands' pressure index z0, α(T) = z0 · 5.1e−9 (ln η(T) + 9.67) 1/Pa (Roelands
  1966): for paraffinic mineral oils z0 = 0.67 (the mean of the nine points, 0.60–0.72, of the three
  paraffinic oils of the Tribology Handbook (IMechE, ed. Neale), Table 25: α 2.2/1.9/1.4, 2.4/2.1/1.6,
  3.4/2.8/2.2 e−8 1/Pa at 30/60/100 °C for η30 = 42, 153, 810 mPa s: z0 is constant per oil within
  ±5 %, as Roelands' law assumes);
- thermal: specific heat and conductivity from Cragoe's relations for petroleum oils (US Bureau of
  Standards Misc. Publ. 97, 1929): c = (1.685 + 0.00339 θ)/√s kJ/(kg K), k = 0.1172 (1 − 0.00054 θ)/s
  W/(m K), θ in °C, s the relative density at 15 °C;
- traction: the Eyring stress τ0 and the limiting shear coefficient Λ (τ_L = Λ p).

:func:`oil_table` evaluates an oil at a reference temperature as the keys of a scene's ``[oil]``
table, so that ``oil.name = "…"`` fills every oil key (each can still be given).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from femgear.physics.lubrication.walther import walther_slope, walther_through, walther_viscosity

T15 = 288.15
_P_ROELANDS = 5.1e-9

ISO3448 = "ISO 3448:1992, viscosity grade mid-point ν40 [mm²/s]"
GEARPIE = "GEARpie library (C. Fernandes, FEUP; github cfernandesFEUP/GEARpie, CLASSES/LUBRICANT_LIBRARY.py)"
GEARPIE_MINERAL = (f"ν100 of ISO VG mineral gear oils (VI ≈ 95–100): the ASTM D341 lines M32–M460 of the {GEARPIE} "
                   "at 100 °C")
GEARPIE_MINERAL_DENSITY = f"ρ15 902 kg/m³, ε 5.8e-4 1/K of mineral oils in the {GEARPIE}"
IMECHE_Z = ("Roelands z0 = 0.67 from the Tribology Handbook (IMechE), Table 25, paraffinic oils "
            "(α at 30/60/100 °C)")
CRAGOE = "Cragoe, US Bureau of Standards Misc. Publ. 97 (1929): c_p and k of petroleum oils from ρ15"
MANJUNATH = ("Manjunath, Fauconnier, Ost & De Baets, Machines 11 (2023) 801 (open access), Table 3 'Oil FVA 3A "
             "properties', measured")
#: FVA 3A's pressure–viscosity coefficients of Manjunath et al.'s Table 3 [1/Pa] at 25 and 80 °C ("at 200 MPa";
#: the table prints 2.16 and 1.58 with the unit "× 10^3 bar⁻¹" as the stored text reads it, whose only physical
#: reading is × 10⁻³ bar⁻¹ = 21.6 and 15.8 GPa⁻¹)
FVA3A_ALPHA = ((298.15, 2.16e-8), (353.15, 1.58e-8))


@dataclass(frozen=True)
class LibraryOil:
    """One named oil (SI units; temperatures in K)."""

    name: str
    base: str                                   #: "mineral", "pao", "pag" (ISO/TS 6336-20 X_L types)
    description: str
    points: tuple[tuple[float, float], tuple[float, float]]   #: two (T [K], ν [m²/s]) viscosity points
    rho15: float                                #: density at 15 °C [kg/m³]
    expansion: float                            #: ε of ρ(T) = ρ15 (1 − ε (T − 288.15)) [1/K]
    z0: float                                   #: Roelands pressure index [-]
    eyring_stress: float = 5.0e6                #: τ0 [Pa]
    limiting_shear_coeff: float = 0.0           #: Λ [-]
    specific_heat: float | None = None          #: [J/(kg K)] (None: Cragoe's relation)
    conductivity: float | None = None           #: [W/(m K)] (None: Cragoe's relation)
    sources: dict[str, str | None] = field(default_factory=dict)
    """source of each group: viscosity, density, pressure_viscosity, thermal, traction (None: no source)"""

    def unsourced(self) -> tuple[str, ...]:
        """The data groups without a published source."""
        return tuple(k for k in GROUPS if self.sources.get(k) is None)

    def density(self, T: float) -> float:
        """ρ(T) at ambient pressure [kg/m³]."""
        return self.rho15 * (1 - self.expansion * (T - T15))

    def kinematic_viscosity(self, T: float) -> float:
        """ν(T) [m²/s] (ASTM D341 through the two points)."""
        (t1, n1), (t2, n2) = self.points
        return walther_viscosity(*walther_through(t1, n1, t2, n2), T)

    def viscosity(self, T: float) -> float:
        """η(T) = ν ρ at ambient pressure [Pa s]."""
        return self.kinematic_viscosity(T) * self.density(T)


#: the data groups of a library oil, in the order ``femgear oils`` prints them
GROUPS = ("viscosity", "density", "pressure_viscosity", "thermal", "traction")

_VG_MINERAL = {32: 5.38, 46: 6.48, 68: 8.47, 100: 10.95, 150: 14.45, 220: 18.91, 320: 22.23, 460: 29.86}


def _mineral(vg: int, **over) -> LibraryOil:
    traction = over.pop("traction", None)
    return LibraryOil(
        name=over.pop("name", f"mineral-vg{vg}"), base="mineral",
        description=over.pop("description", f"paraffinic mineral gear oil, ISO VG {vg}"),
        points=((313.15, vg * 1e-6), (373.15, _VG_MINERAL[vg] * 1e-6)), rho15=902.0, expansion=5.8e-4, z0=0.67,
        sources={"viscosity": f"{ISO3448}; {GEARPIE_MINERAL}", "density": GEARPIE_MINERAL_DENSITY,
                 "pressure_viscosity": IMECHE_Z, "thermal": CRAGOE, "traction": traction}, **over)


LIBRARY: dict[str, LibraryOil] = {o.name: o for o in [
    *(_mineral(vg) for vg in _VG_MINERAL),
    _mineral(100, name="min100-fzg", description="FZG's mineral reference oil MIN100 (ISO VG 100), data of "
             "mineral-vg100 with the Eyring stress of Lohner et al. 2016", eyring_stress=6.0e6,
             traction="Lohner, Ziegltrum, Stemplinger, Stahl, Adv. Tribol. 2016, 6507203: Eyring stress τc = 6 MPa "
                      "of MIN100 (no limiting shear stress)"),
    LibraryOil(
        name="fva3a", base="mineral",
        description="FVA reference oil 3A, a paraffin-based solvent raffinate (VI 97), as Manjunath et al. 2023 "
                    "measured it",
        points=((313.15, 90.02e-6), (373.15, 10.41e-6)), rho15=884.1, expansion=5.8e-4, z0=0.546,
        sources={"viscosity": f"{MANJUNATH}: ν40 90.02, ν100 10.41 mm²/s (VI 97)",
                 "density": f"{MANJUNATH}: ρ 884.1 kg/m³ (its temperature not stated; taken as ρ15); ε 5.8e-4 1/K "
                            f"of mineral oils in the {GEARPIE}",
                 "pressure_viscosity": f"{MANJUNATH}: α 21.6 / 15.8 GPa⁻¹ at 25 / 80 °C (2.16 / 1.58e-3 1/bar): "
                                       "Roelands z0 = 0.546, the mean of 0.529 and 0.564 at the two temperatures",
                 "thermal": CRAGOE, "traction": None}),
    LibraryOil(
        name="pao-vg100", base="pao", description="polyalphaolefin gear oil, ISO VG 100 (VI ≈ 150)",
        points=((313.15, 99.4e-6), (373.15, 14.46e-6)), rho15=859.0, expansion=5.5e-4, z0=0.67,
        sources={"viscosity": f"the ASTM D341 line P100 of the {GEARPIE}",
                 "density": f"ρ15 859 kg/m³, ε 5.5e-4 1/K of PAO in the {GEARPIE}",
                 "pressure_viscosity": None, "thermal": CRAGOE, "traction": None}),
    LibraryOil(
        name="pag-eo-po", base="pag",
        description="polyalkylene glycol (ethylene oxide–propylene oxide copolymer), ≈ ISO VG 120",
        points=((303.15, 0.204 / 1054.0), (373.15, 0.0225 / 1009.3)), rho15=1059.0, expansion=7.1e-4, z0=0.427,
        specific_heat=None, conductivity=None,
        sources={"viscosity": "Stachowiak & Batchelor, Engineering Tribology, Table 2.3 (adapted from its ref. 12): η 204 / "
                              "62.5 / 22.5 mPa s at 30 / 60 / 100 °C (ν = η/ρ)",
                 "density": f"ρ15 1059 kg/m³, ε 7.1e-4 1/K of PAG in the {GEARPIE}",
                 "pressure_viscosity": "Stachowiak & Batchelor, Table 2.3: α 17.6 GPa⁻¹ at 30 °C, z0 = 0.427",
                 "thermal": None, "traction": None}),
]}


def library_oil(name: str) -> LibraryOil:
    """The library oil ``name``; ``KeyError`` naming the known ones."""
    try:
        return LIBRARY[name]
    except KeyError:
        raise KeyError(f"unknown oil {name!r}; the library holds {', '.join(LIBRARY)} (femgear oils)") from None


def oil_table(oil: LibraryOil, temperature: float) -> dict[str, float]:
    """The keys of a scene's ``[oil]`` table for ``oil`` at the reference ``temperature`` [K]: η0, ρ0, α, β_T
    (the local ASTM D341 slope of η = ν ρ), ε of ρ about ``temperature``, c_p, k, τ0, Λ."""
    T = float(temperature)
    rho = oil.density(T)
    eta = oil.viscosity(T)
    (t1, n1), (t2, n2) = oil.points
    shrink = 1 - oil.expansion * (T - T15)
    beta = walther_slope(*walther_through(t1, n1, t2, n2), T) + oil.expansion / shrink
    s = oil.rho15 / 999.0
    theta = T - 273.15
    cp = oil.specific_heat or (1.685 + 0.00339 * theta) / math.sqrt(s) * 1e3
    k = oil.conductivity or 0.1172 * (1 - 0.00054 * theta) / s
    return {"viscosity": eta, "density": rho, "specific_heat": cp, "conductivity": k,
            "pressure_viscosity": oil.z0 * _P_ROELANDS * (math.log(eta) + 9.67), "temperature_viscosity": beta,
            "reference_temperature": T, "thermal_expansion": oil.expansion / shrink,
            "eyring_stress": oil.eyring_stress, "limiting_shear_coeff": oil.limiting_shear_coeff}
