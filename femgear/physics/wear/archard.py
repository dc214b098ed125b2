"""Archard wear of both flanks by single-point observation, accumulated in stable steps.

Archard's law dh = (K/H) p ds with the dimensionless coefficient K and hardness H
(the paper's "wear rate 10⁻⁶" read as K).  Single-point observation (Flodin &
Andersson, Wear 207 (1997) 16; helical: Wear 249 (2001) 285): a flank point of member
j passes the contact zone of width 2a once per load cycle, in the time 2a/v_j, and
slides |v1 − v2|·2a/v_j against the other flank.  Integrating the pressure across
the band gives ∫p dx = w' (load per unit contact length), so per load cycle

    Δh_j(u) = (K/H) · w̄'(u) · |v1 − v2| / v_j,

w̄'(u) the load intensity averaged over the passages (:mod:`.load_sharing`).  The
paper's eq. for h_{i,j} writes 4 a p; with p the mean Hertz pressure 2 a p̄ = w', so
its form is twice this one — femgear keeps Flodin's.  Zero sliding at the pitch
point gives zero wear there.

``cycles`` count revolutions of the pinion (load cycles of one pinion tooth); a gear
tooth is loaded z1/z2 times per pinion revolution.

With the film known (:mod:`.regime`), the load that wears is the asperity-borne part
f_a(w̄') w̄' of the passage load (``WearSetup.share``; Akbarzadeh & Khonsari, ASME J. Tribol. 131
(2009) 024503): Δh_j = (K/H) f_a w̄' |v1 − v2| / v_j, negligible in full film.  Without it (the
paper's constant-coefficient form) the whole load wears.

Stability rule: a step of ΔN cycles may change the load distribution by at most
``max_relative_change``, i.e. the largest depth increment is capped at that fraction
of the mean elastic approach w̄'/c_l.  Larger steps give the oscillating wear profiles
of explicit schemes (Põdra & Andersson 1999; Flodin & Andersson 1997).
"""

from __future__ import annotations

import os
import tempfile
from collections.abc import Iterator
from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np

from femgear.errors import ConvergenceError
from femgear.perf import Progress
from femgear.physics.geometry import GearPair, PathKinematics
from femgear.physics.wear.load_sharing import ReferenceLoad, load_map, reference_load_map
from femgear.physics.wear.regime import AsperityShare


@dataclass(frozen=True)
class WearSetup:
    """What stays fixed during a wear run."""

    pair: GearPair
    kin: PathKinematics          #: kinematics at the profile positions ``kin.u``
    force: float | np.ndarray    #: normal force of one helix [N], scalar or per mesh phase (``reference``: or per helix)
    c_l: float | np.ndarray      #: stiffness per unit contact-line length [N/m²], or one value per ``kin.u``
    coefficient: float           #: dimensionless Archard K [-]
    hardness: float              #: H [Pa]
    n_phase: int = 64
    #: share the load like this contact analysis (the ``ltca`` level) instead of the Winkler layer c_l alone
    reference: ReferenceLoad | None = None
    #: the asperity-borne share f_a(w', u) of the load (:mod:`.regime`); None: the whole load wears (the paper's
    #: constant-coefficient form)
    share: AsperityShare | None = None


@dataclass(frozen=True)
class WearState:
    """Wear after ``cycles`` pinion revolutions; depths normal to the flank at ``u`` [m]."""

    cycles: float
    h1: np.ndarray
    h2: np.ndarray
    steps: int = 0

    @classmethod
    def zero(cls, n: int) -> WearState:
        return cls(cycles=0.0, h1=np.zeros(n), h2=np.zeros(n))


def wear_rates(setup: WearSetup, state: WearState) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Depth per pinion revolution for pinion and gear [m], and the mean load w̄' [N/m]."""
    k = setup.kin
    if setup.reference is None:
        lm = load_map(setup.pair, k.u, setup.force, state.h1 + state.h2, setup.c_l, setup.n_phase)
    else:
        lm = reference_load_map(setup.pair, k.u, setup.force, state.h1 + state.h2, setup.c_l, setup.reference)
    r1, r2 = archard_rates(setup, lm.mean_load)
    return r1, r2, lm.mean_load


def archard_rates(setup: WearSetup, load: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Depth per pinion revolution of pinion and gear [m] for the passage load intensity ``load`` [N/m]
    at the positions ``setup.kin.u`` (last axis; any leading axes, e.g. helix and face position):
    Δh_j = (K/H) w' |v1 − v2| / v_j, the gear's × z1/z2, w' the asperity-borne part f_a w' with ``setup.share``
    (module docstring)."""
    k = setup.kin
    if setup.share is not None:
        load = load * setup.share(load)
    factor = setup.coefficient / setup.hardness * load * np.abs(k.vs)
    return factor / k.v1, factor / k.v2 * (setup.pair.z1 / setup.pair.z2)


def stable_cycles(setup: WearSetup, rate: float, load: np.ndarray, remaining: float,
                  max_relative_change: float) -> float:
    """The cycles of one update step: ``remaining``, capped so that the largest depth increment (``rate``
    [m per revolution], of h1 + h2) stays below ``max_relative_change`` × the mean elastic approach
    w̄'/c_l of the loaded points of ``load`` (the stability rule of the module docstring)."""
    loaded = load[load > 0]
    if not (rate > 0 and loaded.size):       # nothing wears (full film, or no load in this pass)
        return remaining
    approach = float(np.mean(loaded)) / float(np.mean(setup.c_l))
    return min(remaining, max_relative_change * approach / rate)


def stepped(setup: WearSetup, rates, state, cycles: float, max_relative_change: float = 0.05) -> Iterator:
    """Explicit Archard stepping of any wear ``state`` (``cycles``, ``h1``, ``h2``, ``steps`` fields) to
    ``cycles`` pinion revolutions: ``rates(state)`` → (pinion rate, gear rate, load) per revolution, each
    step as long as :func:`stable_cycles` allows.  Yields the state after each step; a non-finite rate, load
    or depth raises :class:`femgear.errors.ConvergenceError` with the steps' history (no NaN leaves)."""
    if not 0 < max_relative_change <= 1:
        raise ValueError(f"max_relative_change must be in (0, 1] (got {max_relative_change!r})")
    history: dict[str, list] = {"cycles": [], "max_depth": []}
    progress = Progress(f"Archard wear to {cycles:.4g} cycles", None)
    while state.cycles < cycles * (1 - 1e-12):
        r1, r2, w = rates(state)
        if not all(np.all(np.isfinite(a)) for a in (r1, r2, w)):
            raise ConvergenceError("wear", f"non-finite wear rate or load at {state.cycles:.4g} cycles (step "
                                           f"{state.steps + 1})", history)
        dN = stable_cycles(setup, float(np.max(r1 + r2)), w, cycles - state.cycles, max_relative_change)
        state = replace(state, cycles=state.cycles + dN, h1=state.h1 + r1 * dN, h2=state.h2 + r2 * dN,
                        steps=state.steps + 1)
        if not (np.all(np.isfinite(state.h1)) and np.all(np.isfinite(state.h2))):
            raise ConvergenceError("wear", f"the wear depth became non-finite at {state.cycles:.4g} cycles", history)
        history["cycles"].append(float(state.cycles))
        history["max_depth"].append(float(max(np.max(state.h1), np.max(state.h2))))
        progress(state.steps, f"step {state.steps}, {state.cycles:.4g} cycles, largest depth "
                              f"{history['max_depth'][-1] * 1e6:.3g} µm")
        yield state


def wear_steps(setup: WearSetup, cycles: float, state: WearState | None = None,
               max_relative_change: float = 0.05) -> Iterator[WearState]:
    """Yield the state after each update step until ``cycles`` pinion revolutions."""
    state = state or WearState.zero(setup.kin.u.size)
    yield from stepped(setup, lambda s: wear_rates(setup, s), state, cycles, max_relative_change)


def save_state(state: WearState, path: Path, u: np.ndarray) -> None:
    """Write a checkpoint atomically (temporary file + rename)."""
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(dir=path.parent, suffix=".npz")
    os.close(fd)
    np.savez(tmp, cycles=state.cycles, h1=state.h1, h2=state.h2, steps=state.steps, u=u)
    os.replace(tmp, path)


def load_state(path: Path, u: np.ndarray) -> WearState | None:
    """Read a checkpoint written for the same profile grid, or None if there is none."""
    if not path.exists():
        return None
    with np.load(path) as data:
        if data["u"].shape != u.shape or not np.allclose(data["u"], u, rtol=0, atol=1e-12):
            raise ValueError(f"checkpoint {path} belongs to another profile grid; delete it to start again")
        return WearState(cycles=float(data["cycles"]), h1=data["h1"], h2=data["h2"], steps=int(data["steps"]))


def run_wear(setup: WearSetup, cycles: float, checkpoint: str | Path | None = None,
             max_relative_change: float = 0.05) -> WearState:
    """Accumulate wear to ``cycles``; with ``checkpoint`` every step is saved and a rerun resumes."""
    path = Path(checkpoint) if checkpoint else None
    state = load_state(path, setup.kin.u) if path else None
    final = state or WearState.zero(setup.kin.u.size)
    for final in wear_steps(setup, cycles, state, max_relative_change):
        if path:
            save_state(final, path, setup.kin.u)
    return replace(final)
