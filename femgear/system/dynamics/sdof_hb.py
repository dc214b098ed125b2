"""The Kahraman–Singh oscillator by harmonic balance (AFT) and pseudo-arclength continuation.

The single-DOF backlash oscillator of :mod:`femgear.system.dynamics.sdof` (Kahraman & Singh,
JSV 142:49, 1990), x'' + 2ζ x' + f(x) = F_m + F_a cos Ωτ with the dead zone f of half-width 1,
as a :class:`~femgear.system.dynamics.aft.PeriodicProblem`: one channel, the contact stiffness
(1) moved into the structure, receptance R_k = 1/(1 − (kΩ)² + 2iζkΩ).  Continuation in Ω traces
the whole frequency response, through the two folds of the softening resonance: the branch the
up-sweep follows ends at the upper fold (it jumps up there), the resonant one the down-sweep
follows ends at the lower fold (it jumps down); between them the middle branch is unstable.
Stability: the Floquet multipliers of the linearised equation z' = [[0, 1], [−f'(x(τ)), −2ζ]] z
over one period (its monodromy, exact for the piecewise-constant f' on the AFT grid).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from femgear.docfields import document_fields
from femgear.physics.excitation import contact_indicator, gap_function
from femgear.physics.geometry.gear import GearPair
from femgear.system.dynamics.aft import (
    PeriodicProblem,
    continuation,
    harmonics_of,
    solutions_at,
    time_signal,
    unknowns_of,
)
from femgear.system.dynamics.mesh import periodic_interp

#: samples of the reconstructed period for amplitudes and contact fractions
READ_SAMPLES = 4096


def ks_problem(zeta: float, mean_load: float, alternating_load: float, harmonics: int = 32, samples: int = 512,
               backlash: float = 1.0, stiffness: np.ndarray | None = None) -> PeriodicProblem:
    """The oscillator x'' + 2ζx' + κ(φ) f(x; ``backlash``) = F_m + F_a cos Ωτ as a harmonic-balance problem (lengths
    over a reference length, time over 1/ω_n); ``stiffness``: κ over one excitation period at the phases i/n (mean 1;
    default 1: Kahraman–Singh's time-invariant mesh, lengths over the backlash, ``backlash`` = 1)."""
    H = int(harmonics)
    kappa = None if stiffness is None else np.asarray(stiffness, dtype=float)

    def receptance(omega: float):
        k = np.arange(H + 1)
        R = 1.0 / (1.0 - (k * omega) ** 2 + 2j * zeta * k * omega)
        F = np.zeros(H + 1, dtype=complex)
        F[0], F[1] = mean_load, 0.5 * alternating_load
        return R[:, None, None], (R * F)[:, None]

    def law(y, v, phase):
        k = 1.0 if kappa is None else periodic_interp(kappa, phase)
        return k * gap_function(y, backlash), k * contact_indicator(y, backlash), np.zeros_like(y)

    return PeriodicProblem(channels=1, harmonics=H, samples=samples, receptance=receptance, law=law,
                           mean_stiffness=np.ones(1), mean_damping=np.zeros(1))


def _expm2(a: np.ndarray, zeta: float, h: float) -> np.ndarray:
    """(…, 2, 2) e^{Ah} of A = [[0, 1], [−a, −2ζ]] in closed form: e^{−ζh} [cosh(sh) I + sinh(sh)/s (A + ζI)],
    s = √(ζ² − a) (the limit h at s = 0)."""
    s = np.sqrt(zeta**2 - np.asarray(a, dtype=float) + 0j)
    sh = np.where(np.abs(s) * h > 1e-8, np.sinh(s * h) / np.where(s == 0, 1, s), h)
    ch = np.cosh(s * h)
    e = np.exp(-zeta * h)
    out = np.empty(np.shape(a) + (2, 2))
    out[..., 0, 0] = (e * (ch + zeta * sh)).real
    out[..., 0, 1] = (e * sh).real
    out[..., 1, 0] = (-a * e * sh).real
    out[..., 1, 1] = (e * (ch - zeta * sh)).real
    return out


def ks_stability(problem: PeriodicProblem, zeta: float, x: np.ndarray, omega: float) -> float:
    """Largest Floquet multiplier modulus of the periodic solution ``x`` at Ω = ``omega`` [-] (< 1: stable): the
    monodromy of z' = [[0, 1], [−∂N/∂x, −2ζ]] z with ∂N/∂x of the law at the AFT intervals' midpoints (exact for
    that piecewise-constant stiffness)."""
    n = problem.samples
    y = time_signal(harmonics_of(problem, x), 2 * n)[:, 1::2]            # interval midpoints
    stiff = problem.law(y, np.zeros_like(y), (np.arange(n) + 0.5) / n)[1][0]
    steps = _expm2(stiff, zeta, 2 * math.pi / omega / n)
    phi = np.eye(2)
    for E in steps:
        phi = E @ phi
    return float(np.abs(np.linalg.eigvals(phi)).max())


@document_fields
@dataclass(frozen=True)
class KSBranch:
    """The frequency response of the Kahraman–Singh oscillator traced by continuation."""

    frequency: np.ndarray
    """Ω along the branch (not monotonic: it turns back at the folds) [-]"""
    amplitude: np.ndarray
    """half peak-to-peak of x over the period, over the backlash b [-]"""
    contact_loss: np.ndarray
    """fraction of the period with |x| ≤ 1 [-]"""
    multiplier: np.ndarray
    """largest Floquet multiplier modulus (< 1: stable) [-]"""
    folds: tuple[float, ...]
    """Ω of the turning points, in the order the branch meets them [-]"""
    harmonics: int
    """harmonics H of the balance [-]"""
    at: np.ndarray
    """the frequencies Ω asked for by ``at`` of :func:`kahraman_singh_hb` [-]"""
    stable_at: np.ndarray
    """(len(at), 2) amplitudes of the stable solutions at ``at``, ascending (NaN where fewer), over b [-]"""

    @property
    def stable(self) -> np.ndarray:
        return self.multiplier < 1.0


def _trace(prob: PeriodicProblem, zeta: float, backlash: float, omega0: float, omega1: float, guess: np.ndarray,
           ds: float, at, omega_min: float | None = None) -> KSBranch:
    """Continue ``prob`` from its solution near ``guess`` at ``omega0`` to ``omega1`` (turning back no lower than
    ``omega_min``); the stable solutions at ``at``."""
    br = continuation(prob, omega0, omega1, unknowns_of(prob, guess), ds=ds, ds_max=0.05, x_scale=1.0,
                      omega_min=omega_min)
    x_t = time_signal(np.array([harmonics_of(prob, x)[0] for x in br.x]), READ_SAMPLES)
    at = np.asarray([] if at is None else at, dtype=float)
    stable_at = np.full((at.size, 2), np.nan)
    for i, om in enumerate(at):
        amps = sorted(_amplitude(prob, x) for x in solutions_at(prob, br, om) if ks_stability(prob, zeta, x, om) < 1)
        stable_at[i, :len(amps[:2])] = amps[:2]
    return KSBranch(frequency=br.omega, amplitude=0.5 * np.ptp(x_t, axis=1),
                    contact_loss=np.mean(np.abs(x_t) <= backlash, axis=1),
                    multiplier=np.array([ks_stability(prob, zeta, x, w) for x, w in zip(br.x, br.omega)]),
                    folds=tuple(float(br.omega[i]) for i in br.folds), harmonics=prob.harmonics, at=at,
                    stable_at=stable_at)


def _amplitude(problem: PeriodicProblem, x: np.ndarray) -> float:
    return float(0.5 * np.ptp(time_signal(harmonics_of(problem, x), READ_SAMPLES)))


def kahraman_singh_hb(omega0: float = 0.6, omega1: float = 1.3, zeta: float = 0.05, mean_load: float = 0.1,
                      alternating_load: float = 0.02, harmonics: int = 32, samples: int = 512,
                      ds: float = 0.01, at=None) -> KSBranch:
    """Trace the oscillator's response from Ω = ``omega0`` to ``omega1`` (defaults: those of
    :func:`femgear.system.dynamics.sdof.kahraman_singh_sweep` and ``femgear dynamics --kahraman-singh``);
    ``at``: frequencies at which the stable solutions are solved exactly (:func:`~femgear.system.dynamics.aft.solutions_at`)."""
    if not (0 < omega0 < omega1 and zeta > 0 and mean_load > 0 and alternating_load >= 0):
        raise ValueError("need 0 < omega0 < omega1, zeta > 0, mean_load > 0 and alternating_load ≥ 0")
    prob = ks_problem(zeta, mean_load, alternating_load, harmonics, samples)
    Y = np.zeros((1, prob.harmonics + 1), dtype=complex)
    Y[0, 0] = 1.0 + mean_load                                   # drive-flank contact, linear guess
    Y[0, 1] = 0.5 * alternating_load / (1 - omega0**2 + 2j * zeta * omega0)
    return _trace(prob, zeta, 1.0, omega0, omega1, Y, ds, at)


def spur_torsional_hb(pair: GearPair, k_mesh: np.ndarray, I1: float, I2: float, pinion_torque: float, backlash: float,
                      ratio0: float = 0.6, ratio1: float = 1.3, damping_ratio: float = 0.05, harmonics: int = 32,
                      samples: int = 512, ds: float = 0.01, at=None) -> KSBranch:
    """The spur pair's dynamic transmission error of :func:`femgear.system.dynamics.one_mesh.torsional_sweep`,
    m_e ẍ + c ẋ + k(f_m t) f(x; b0) = F_bn with the pair's own mesh stiffness over one period, by continuation
    in f_m/f_n from ``ratio0`` to ``ratio1``: lengths over the static deflection x_s = F_bn/k̄ (the amplitudes are
    those the study ``spur_jump`` prints), time over 1/ω_n, ω_n = √(k̄/m_e) (the torsional mode on rigid supports)."""
    if pair.beta_b != 0:
        raise ValueError("spur_torsional_hb reduces a spur pair (β_b = 0) to its transmission error")
    k = np.asarray(k_mesh, dtype=float)
    if not (I1 > 0 and I2 > 0 and pinion_torque > 0 and backlash >= 0 and np.all(k > 0) and 0 < ratio0 < ratio1):
        raise ValueError("need I1, I2, pinion_torque > 0, backlash ≥ 0, a positive stiffness and 0 < ratio0 < ratio1")
    x_s = pinion_torque / pair.rb1 / float(k.mean())
    beta = backlash / x_s
    prob = ks_problem(damping_ratio, 1.0, 0.0, harmonics, samples, backlash=beta, stiffness=k / k.mean())
    Y = np.zeros((1, prob.harmonics + 1), dtype=complex)
    Y[0, 0] = 1.0 + beta
    # the impacting resonance bends far below f_n (both flanks): let the branch turn again below ratio0
    return _trace(prob, damping_ratio, beta, ratio0, ratio1, Y, ds, at, omega_min=0.25 * ratio0)
