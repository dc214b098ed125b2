"""Transmission-error and force excitations, each vectorised over time ``t`` [s].

Every error source has ``value(t)`` and ``rate(t)`` (d/dt) so the mesh damping force
c δ̇ sees the error velocity too.  Sources (paper eq. 1, e_m = e_r sin(2π f_c t + θ1)
+ e_f(t) + e_0(t)):

- :class:`Eccentricity`  geometric eccentricity e of one member: its geometric centre
  orbits the bearing axis, r_e(t) = e (cos θ(t), sin θ(t)), θ = Ω t + φ, rotating with
  the member (Ω signed by the sense of rotation).  The model projects r_e onto each
  mesh normal, which reproduces the paper's term e_r(sin θ_g − sin θ_p) cos ψ cos β
  + e_r(cos θ_g − cos θ_p) sin ψ cos β for any pair of eccentricities and phases.
- :class:`ProfileError`  e_f(t) = Σ_{i=1..M} a sin(2π i (f_m t + φ_0) + φ), the paper's
  eq. for e_f with equal amplitude a in each of the M mesh harmonics.  The mesh phase
  offset φ_0 (in mesh cycles) carries the left/right stagger of a double-helical pair.
- :class:`RandomError`  seeded random single-pitch deviations: each tooth of pinion and
  gear gets a deviation drawn uniformly from [−a, a]; the mesh sees the mean of the
  deviations of the two teeth in contact, linearly interpolated in mesh phase (a
  continuous, piecewise-linear signal repeating with the hunting period).  The paper
  gives no form for e_0; this one is bounded by a and physically a pitch-error pattern.
- :class:`CumulativePitchError`  a once-per-revolution cumulative pitch deviation of one member,
  tooth n of z displaced by A sin(2π n/z + φ) along the line of action, seen tooth by tooth like
  :class:`RandomError` (linear in mesh phase between the teeth): a shaft-order transmission error
  whose tooth-by-tooth sampling puts lines at k f_m ± f_s (amplitude A sinc²(π(k ± 1/z)), sinc x = sin x/x).
- :class:`Unbalance`  rotating force U Ω² (cos θ, sin θ) of a mass unbalance U [kg m].
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np


@dataclass(frozen=True)
class Eccentricity:
    """Rotating geometric eccentricity of one member."""

    amplitude: float      #: e [m]
    omega: float          #: signed angular speed of the member [rad/s]
    phase: float = 0.0    #: θ at t = 0 [rad]

    def offset(self, t: np.ndarray) -> np.ndarray:
        """Centre offset (x, y) [m], shape t.shape + (2,)."""
        th = self.omega * np.asarray(t, dtype=float) + self.phase
        return self.amplitude * np.stack([np.cos(th), np.sin(th)], axis=-1)

    def offset_rate(self, t: np.ndarray) -> np.ndarray:
        """d/dt of :meth:`offset` [m/s]."""
        th = self.omega * np.asarray(t, dtype=float) + self.phase
        return self.amplitude * self.omega * np.stack([-np.sin(th), np.cos(th)], axis=-1)


@dataclass(frozen=True)
class ProfileError:
    """Profile-error harmonics of the mesh frequency along the line of action."""

    amplitude: float          #: a per harmonic [m]
    mesh_frequency: float     #: f_m [Hz]
    orders: int = 3           #: M [-]
    phase: float = 0.0        #: φ [rad]
    mesh_offset: float = 0.0  #: φ_0, mesh-phase offset of this helix [mesh cycles]

    def value(self, t: np.ndarray) -> np.ndarray:
        t = np.asarray(t, dtype=float)
        out = np.zeros_like(t)
        if self.amplitude == 0.0:
            return out
        arg = 2 * math.pi * (self.mesh_frequency * t + self.mesh_offset)
        for i in range(1, self.orders + 1):
            out += np.sin(i * arg + self.phase)
        return self.amplitude * out

    def rate(self, t: np.ndarray) -> np.ndarray:
        t = np.asarray(t, dtype=float)
        out = np.zeros_like(t)
        if self.amplitude == 0.0:
            return out
        w = 2 * math.pi * self.mesh_frequency
        arg = w * t + 2 * math.pi * self.mesh_offset
        for i in range(1, self.orders + 1):
            out += i * w * np.cos(i * arg + self.phase)
        return self.amplitude * out


class _ToothByTooth:
    """A per-tooth error seen by the mesh: the value of the tooth pair of mesh cycle n (``_nodes``: the pair's
    value, the next pair's, the fraction of the cycle), linear in mesh phase between cycles."""

    amplitude: float
    mesh_frequency: float

    def value(self, t: np.ndarray) -> np.ndarray:
        if self.amplitude == 0.0:
            return np.zeros(np.shape(t))
        a, b, frac = self._nodes(t)
        return self.amplitude * (a + (b - a) * frac)

    def rate(self, t: np.ndarray) -> np.ndarray:
        if self.amplitude == 0.0:
            return np.zeros(np.shape(t))
        a, b, _ = self._nodes(t)
        return self.amplitude * (b - a) * self.mesh_frequency


@dataclass(frozen=True)
class RandomError(_ToothByTooth):
    """Seeded random single-pitch deviations of both members, seen by one mesh.

    Each tooth of each member carries a deviation uniform in [−a, a]; the tooth pair in
    mesh k (pinion tooth k mod z1 against gear tooth k mod z2) displaces the mesh by the
    sum of the two (both act along the line of action), so the pair error lies in
    [−2a, 2a]; it is interpolated linearly between mesh cycles.
    """

    amplitude: float          #: bound a of each tooth's deviation [m]
    mesh_frequency: float     #: f_m [Hz]
    z1: int
    z2: int
    seed: int = 0
    mesh_offset: float = 0.0  #: mesh-phase offset of this helix [mesh cycles]
    _dev1: np.ndarray = field(init=False, repr=False, compare=False)
    _dev2: np.ndarray = field(init=False, repr=False, compare=False)

    def __post_init__(self):
        rng = np.random.default_rng(self.seed)
        object.__setattr__(self, "_dev1", rng.uniform(-1.0, 1.0, self.z1))
        object.__setattr__(self, "_dev2", rng.uniform(-1.0, 1.0, self.z2))

    def _nodes(self, t: np.ndarray):
        phase = self.mesh_frequency * np.asarray(t, dtype=float) + self.mesh_offset
        n = np.floor(phase)
        frac = phase - n
        n = n.astype(np.int64)
        def tooth(k):
            return self._dev1[k % self.z1] + self._dev2[k % self.z2]
        return tooth(n), tooth(n + 1), frac



@dataclass(frozen=True)
class CumulativePitchError(_ToothByTooth):
    """Once-per-revolution cumulative pitch deviation of one member, along the line of action.

    Tooth n (counted from the one in mesh at t = 0) of the member's z teeth sits A sin(2π n/z + φ) ahead;
    the tooth pair of mesh cycle n carries it, and between cycles the mesh sees the linear interpolation
    (the form of :class:`RandomError`).  ``lines`` gives the exact Fourier lines of that signal.
    """

    amplitude: float          #: A [m]
    mesh_frequency: float     #: f_m [Hz]
    teeth: int                #: z of the member [-]
    phase: float = 0.0        #: φ [rad]
    mesh_offset: float = 0.0  #: mesh-phase offset of this helix [mesh cycles]

    def _nodes(self, t: np.ndarray):
        u = self.mesh_frequency * np.asarray(t, dtype=float) + self.mesh_offset
        n = np.floor(u)
        theta = 2 * math.pi / self.teeth
        return np.sin(theta * n + self.phase), np.sin(theta * (n + 1) + self.phase), u - n


    def line(self, k: int) -> tuple[float, complex]:
        """(frequency [Hz], complex amplitude X: value ∋ Re X e^{2πi f t}) of the Fourier line at f = (k + 1/z) f_m
        (k = 0: the shaft order; k ≥ 1 the upper, k ≤ −1 the lower sideband of mesh order |k|, read at |f|).

        The linear interpolation of the samples e^{i(θn + φ)} is Σ_k sinc²(θ/2 + πk) e^{i(θ + 2πk)u},
        u = f_m t + offset (the triangle's Fourier transform), so the real signal's line has the amplitude
        A sinc²(π(k + 1/z))."""
        nu = k + 1.0 / self.teeth
        x = math.pi * nu
        w = (math.sin(x) / x) ** 2
        X = self.amplitude * w * np.exp(1j * (self.phase - math.pi / 2 + 2 * math.pi * nu * self.mesh_offset))
        f = nu * self.mesh_frequency
        return abs(f), (X if f > 0 else np.conj(X))


@dataclass(frozen=True)
class Unbalance:
    """Rotating unbalance force of one member."""

    unbalance: float     #: U = m e [kg m]
    omega: float         #: signed angular speed [rad/s]
    phase: float = 0.0   #: [rad]

    def force(self, t: np.ndarray) -> np.ndarray:
        """Force (F_x, F_y) [N], shape t.shape + (2,)."""
        th = self.omega * np.asarray(t, dtype=float) + self.phase
        return self.unbalance * self.omega**2 * np.stack([np.cos(th), np.sin(th)], axis=-1)
