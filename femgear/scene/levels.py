"""The catalogue of fidelity levels: one frozen spec per level of every sub-model, as data.

A scene's ``[physics]`` table names one level per sub-model (and ``[housing]`` its model).  This
catalogue is the one source of those names and of what a caller may branch on: each level's spec
carries its name, its one-line summary, whether it is ``planned`` (part of the design, refused as
"not available yet") and the attributes the schema, the case checks, the driver, the CLI and the
docs read instead of comparing names (``uniform_along_path``, ``contact_lines``, ``sections``,
``is_dynamic``, ``shaft_elements``, ``iterates``, ...).  The factories that compute a level live
above the Case, in :mod:`femgear.levels`, registered under these names (a test holds the two
name sets equal).  A new level is one spec here and one registered factory there.
"""

from __future__ import annotations

from dataclasses import dataclass

from femgear.errors import SceneError


@dataclass(frozen=True)
class LevelSpec:
    """One level of a sub-model: its name, what it computes, whether it is only planned."""

    name: str
    summary: str                 #: one line: what the level computes
    planned: bool = False        #: part of the design, not built yet (refused as "not available yet")


@dataclass(frozen=True)
class StiffnessLevel(LevelSpec):
    """A mesh-stiffness level (``physics.stiffness``)."""

    #: one stiffness along the whole path: the static contact pass shares the load without a k'(u)
    uniform_along_path: bool = False
    #: resolves the load along the contact lines (what the face-resolved wear and the LTCA load maps read)
    contact_lines: bool = False
    #: the FE bodies it solves, named as ``numerics.body_level`` reads them (None: no FE body)
    body: str | None = None
    #: its bodies' elements follow ``numerics.body_elements`` (the LTCA member bodies)
    body_elements: bool = False


@dataclass(frozen=True)
class LubricationLevel(LevelSpec):
    """A lubrication level (``physics.lubrication``)."""

    friction: bool = True        #: False: μ = 0 and no contact heating (no friction or contact temperature to report)
    #: cheap enough for a scene summary (``femgear info``) to compute its μ itself; costlier levels are summarised
    #: with ``formula`` there (``femgear run`` carries every level's own μ)
    summarised: bool = False


@dataclass(frozen=True)
class ThermalLevel(LevelSpec):
    """A thermal level (``physics.thermal``): the flank deviation from tooth growth."""

    grows: bool = True           #: False: no thermal growth (no flank deviation to report)
    sections: bool = False       #: solves the 2-D tooth sections (their temperature and displacement fields)
    body: str | None = None      #: the FE bodies it solves, as ``numerics.body_level`` names them (None: none)


@dataclass(frozen=True)
class WearLevel(LevelSpec):
    """A wear level (``physics.wear``)."""

    wears: bool = True           #: False: the flanks do not wear


@dataclass(frozen=True)
class DynamicsLevel(LevelSpec):
    """A dynamics level (``physics.dynamics``): what it asks of the driver and of the rotor model."""

    is_dynamic: bool = True      #: False: the sub-models run once at the static load (no rotor model)
    shaft_elements: bool = False  #: Timoshenko shaft elements between helix halves and bearings (else rigid members)


@dataclass(frozen=True)
class CouplingLevel(LevelSpec):
    """A coupling level (``physics.coupling``)."""

    iterates: bool = False       #: iterate dynamics ↔ tribology to convergence (else one dynamic pass)


@dataclass(frozen=True)
class SubModel:
    """The levels of one sub-model, cheapest first, and the scene key that names one."""

    name: str
    key: str                                  #: the scene key naming the level (in error messages)
    levels: tuple[LevelSpec, ...]

    @property
    def available(self) -> tuple[str, ...]:
        """The names that run today, cheapest first."""
        return tuple(s.name for s in self.levels if not s.planned)

    @property
    def planned(self) -> tuple[str, ...]:
        """The names of the design not built yet."""
        return tuple(s.name for s in self.levels if s.planned)

    def problem(self, name: str) -> str | None:
        """Why ``<key> = name`` cannot run, or None when it is an available level."""
        if name in self.available:
            return None
        have = ", ".join(self.available)
        if name in self.planned:
            return f"level {name!r} is not available yet (available now: {have})"
        return f"unknown level {name!r}; choose one of {have}"

    def spec(self, name: str) -> LevelSpec:
        """The spec of available level ``name`` (:class:`SceneError` naming :attr:`key` otherwise)."""
        problem = self.problem(name)
        if problem:
            raise SceneError(self.key, problem)
        return next(s for s in self.levels if s.name == name)


_S, _L, _T = StiffnessLevel, LubricationLevel, ThermalLevel
CATALOGUE: dict[str, SubModel] = {sub.name: sub for sub in (
    SubModel("stiffness", "physics.stiffness", (
        _S("constant", "one mesh stiffness per unit face width, constant in time (stiffness.mesh_stiffness_per_width)",
           uniform_along_path=True),
        _S("iso6336", "ISO 6336-1 single-pair stiffness c' and mesh stiffness c_gamma, shared along the contact "
                      "lines", uniform_along_path=True),
        _S("pem", "potential-energy tooth compliance (Hertz, bending, shear, axial, foundation) integrated over the "
                  "contact lines"),
        _S("fe", "2-D finite-element tooth sections (plane strain) integrated over the contact lines", body="fe"),
        _S("ltca", "loaded tooth contact analysis on 3-D FE member bodies with flank modifications",
           contact_lines=True, body="ltca", body_elements=True),
    )),
    SubModel("lubrication", "physics.lubrication", (
        _L("none", "no friction (μ = 0) and no contact heating; the film of the formulas", friction=False,
           summarised=True),
        _L("constant", "a constant friction coefficient (friction.coefficient) and Blok's flash temperature",
           summarised=True),
        _L("formula", "thermal Eyring traction of the Hertzian film (Dowson-Higginson), with the mixed-lubrication "
                      "split on rough flanks", summarised=True),
        _L("ehl-line", "isothermal line-contact EHL (FE Reynolds, Newton-Krylov) with Eyring traction"),
        _L("tehl", "thermal line-contact EHL (Reynolds + energy) tabulated in a friction map over the path"),
        _L("tehl-point", "thermal point-contact EHL (crowned flank, multigrid) along the path"),
        _L("ehl-point", "isothermal point-contact EHL of the crowned flanks", planned=True),
    )),
    SubModel("thermal", "physics.thermal", (
        _T("none", "no thermal growth", grows=False),
        _T("analytic", "free thermal expansion of the tooth from the bulk rise"),
        _T("fe", "2-D FE heat conduction and thermo-elasticity of the tooth section", sections=True),
        _T("fe3d", "3-D FE heat conduction and thermo-elasticity of the member bodies", body="fe3d"),
    )),
    SubModel("wear", "physics.wear", (
        WearLevel("none", "no wear", wears=False),
        WearLevel("archard", "Archard wear along the path (or over the face) with the load updated as the profile "
                             "wears; wear.load: the asperity-borne load (default) or the whole load"),
    )),
    SubModel("dynamics", "physics.dynamics", (
        DynamicsLevel("none", "quasi-static: the sub-models run once at the static load", is_dynamic=False),
        DynamicsLevel("lumped", "the four helical halves tied rigidly per member on their bearings (12 rigid-member "
                                "coordinates)"),
        DynamicsLevel("timoshenko", "helical halves and bearing stations joined by Timoshenko shaft elements "
                                    "(stations condensed)", shaft_elements=True),
    )),
    SubModel("coupling", "physics.coupling", (
        CouplingLevel("one-way", "one dynamic pass with the static sub-model results"),
        CouplingLevel("bidirectional", "the outer loop iterated to convergence between dynamics and tribology",
                      iterates=True),
    )),
    SubModel("housing", "housing.model", (
        LevelSpec("fe", "a parametric gearbox housing meshed by gmsh (quadratic tetrahedra, cast iron by default), "
                        "Craig-Bampton-reduced at the four bearing seats and coupled into the dynamics"),
        LevelSpec("frf", "measured or supplied FRFs from the bearing seats to sensors (UFF 58 or CSV): a receiver of "
                         "the bearing forces, or coupled by LM-FBS where the seat-to-seat block is given"),
    )),
)}
del _S, _L, _T

#: the sub-models a scene's ``[physics]`` table names, in its order
PHYSICS: tuple[str, ...] = ("stiffness", "lubrication", "thermal", "wear", "dynamics", "coupling")
#: every name of the design per ``[physics]`` sub-model, cheapest first (available, then planned)
LEVELS: dict[str, tuple[str, ...]] = {sub: tuple(s.name for s in CATALOGUE[sub].levels) for sub in PHYSICS}
#: the levels that run today
AVAILABLE: dict[str, frozenset[str]] = {sub: frozenset(CATALOGUE[sub].available) for sub in PHYSICS}


def spec(submodel: str, name: str) -> LevelSpec:
    """The spec of level ``name`` of ``submodel`` (:class:`SceneError` naming the key for an unknown one)."""
    return CATALOGUE[submodel].spec(name)


def check_level(submodel: str, level: str) -> str | None:
    """Return an error message for ``physics.<submodel> = level``, or None if it is usable."""
    return CATALOGUE[submodel].problem(level)
