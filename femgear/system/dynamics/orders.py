"""Order analysis of recorded signals: the amplitudes of lines at known frequencies (mesh and shaft orders).

A steady response of the gear-rotor model is a sum of lines at known frequencies: the mesh
orders k f_m, the shaft orders j f_s of each member (f_s = f_m / z) and their combinations
k f_m + j f_s (the sidebands of eccentricity, run-out and pitch errors).  Their amplitudes are
read by a linear least-squares fit of x(t) ≈ x̄ + Re Σ_i X_i e^{2πi f_i t} over the record: exact
for a signal made of the fitted lines (whatever the window), and with no window's scalloping or
leakage between lines whose spacing the record resolves (record length T ≥ 1/Δf).  A line set
that the record does not resolve (two lines closer than 1/T) is refused rather than split
arbitrarily (:func:`resolves`).

:func:`sidebands` reads the mesh orders with their sidebands k f_m ± j f_s of one member over its whole
revolutions (the signature of eccentricity, run-out and once-per-revolution pitch errors).

The mesh orders alone are fitted over the largest whole number of mesh periods at the end of the
record (:func:`mesh_orders`), where the lines are orthogonal and content between them (a shaft
order) leaks least.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from femgear.docfields import document_fields

#: mesh orders reported by default (1 … ORDERS)
ORDERS = 6


def resolves(t: np.ndarray, frequencies: np.ndarray) -> bool:
    """Whether a record at times ``t`` [s] separates the lines ``frequencies`` [Hz]: every two of them (and
    the mean, f = 0) are at least 1/T apart, T the record length (n uniform samples: n steps), to one sample (a
    window of whole periods that the time step does not divide, :func:`whole_periods`, is up to one step short)."""
    f = np.sort(np.concatenate([[0.0], np.abs(np.asarray(frequencies, dtype=float))]))
    span = float(t[-1] - t[0]) * t.size / max(t.size - 1, 1)      # n samples cover n steps
    return span > 0 and bool(np.all(np.diff(f) * span >= 1.0 - 1.0 / t.size))


def line_fit(x: np.ndarray, t: np.ndarray, frequencies: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(mean, complex amplitudes X_i) of the least-squares fit x ≈ mean + Re Σ_i X_i exp(2πi f_i t).

    ``x``: (n_t, ...) samples at times ``t`` [s] (any trailing shape); ``frequencies`` [Hz], distinct,
    positive and resolved by the record (:func:`resolves`; ValueError otherwise).  |X_i| is the
    line's amplitude (half its peak-to-peak), arg X_i its phase at t = 0.  Returns mean (...) and
    X (len(frequencies), ...).
    """
    f = np.asarray(frequencies, dtype=float)
    x = np.asarray(x, dtype=float)
    if f.size and (np.any(f <= 0) or not resolves(t, f)):
        raise ValueError(f"line_fit: the record of {t[-1] - t[0]:.4g} s does not resolve the lines {f} Hz "
                         "(each needs f > 0 and a spacing ≥ 1/record length)")
    if t.size < 2 * f.size + 1:
        raise ValueError(f"line_fit: {t.size} samples cannot fit {f.size} lines")
    tc = t - t[0]
    arg = 2 * math.pi * np.outer(tc, f)
    A = np.column_stack([np.ones(t.size), np.cos(arg), -np.sin(arg)])
    coef, *_ = np.linalg.lstsq(A, x.reshape(t.size, -1), rcond=None)
    n = f.size
    X = (coef[1:n + 1] + 1j * coef[n + 1:]) * np.exp(-2j * math.pi * f * t[0])[:, None]   # phase at t = 0
    shape = x.shape[1:]
    return coef[0].reshape(shape), X.reshape((n,) + shape)


def whole_periods(t: np.ndarray, frequency: float) -> np.ndarray:
    """Mask of the samples in the largest whole number of periods of ``frequency`` [Hz] at the end of the
    record (all samples when the record is shorter than one period)."""
    span = float(t[-1] - t[0])
    periods = math.floor(span * frequency + 1e-6)
    if periods < 1:
        return np.ones(t.size, bool)
    dt = span / max(t.size - 1, 1)
    return t > t[-1] - periods / frequency + 0.5 * dt          # the window's first sample is its last, once


def mesh_orders(x: np.ndarray, t: np.ndarray, mesh_frequency: float, orders: int = ORDERS) -> np.ndarray:
    """Amplitudes |X_k| of the mesh orders k = 1 … ``orders`` of ``x`` (n_t, ...), shape (orders, ...), from
    :func:`line_fit` over the record's last whole mesh periods."""
    sel = whole_periods(t, mesh_frequency)
    return np.abs(line_fit(np.asarray(x)[sel], t[sel], mesh_frequency * np.arange(1, orders + 1))[1])


#: sidebands reported by default: mesh orders 1 … SIDEBAND_ORDERS, sidebands ±1 … ±SIDEBANDS shaft orders
SIDEBAND_ORDERS, SIDEBANDS = 3, 2


@document_fields
@dataclass(frozen=True)
class Sidebands:
    """The lines k f_m + j f_s of one member (f_s its shaft frequency) in recorded signals, over whole revolutions."""

    member: str
    """the member whose shaft frequency f_s the lines are of ("pinion", "gear") [-]"""
    shaft_frequency: float
    """f_s = f_m / z of the member [Hz]"""
    revolutions: int
    """whole revolutions of the member fitted (0: the record is shorter than one, nothing is reported) [-]"""
    mesh_orders: tuple
    """mesh orders k = 1 … K of the rows [-]"""
    sides: tuple
    """sideband orders j = −J … J of the columns (0: the mesh order itself) [-]"""
    lines: dict
    """signal name → (K, 2J + 1) amplitudes (half peak-to-peak) of the lines k f_m + j f_s [unit of the signal]"""
    shaft_orders: dict
    """signal name → (J,) amplitudes of the shaft orders j f_s, j = 1 … J [unit of the signal]"""


def sidebands(signals: dict[str, np.ndarray], t: np.ndarray, mesh_frequency: float, teeth: int, member: str,
              orders: int = SIDEBAND_ORDERS, sides: int = SIDEBANDS) -> Sidebands:
    """The mesh orders, their sidebands ±1 … ±``sides`` shaft orders and the shaft orders 1 … ``sides`` of
    ``member`` (``teeth`` z) in each of ``signals`` (name → (n_t,) samples at ``t``), fitted together
    (:func:`line_fit`) over the record's last whole revolutions of the member.  Every line of a signal that
    repeats once per revolution is a multiple of f_s, so over whole revolutions the fit separates them
    exactly; lines of the other member leak in only as far as its revolutions do not close."""
    f_s = mesh_frequency / teeth
    j = np.arange(-sides, sides + 1)
    k = np.arange(1, orders + 1)
    span = float(t[-1] - t[0])
    revolutions = math.floor(span * f_s + 1e-6)
    empty = Sidebands(member, f_s, 0, tuple(int(x) for x in k), tuple(int(x) for x in j), {}, {})
    if revolutions < 1 or sides >= teeth / 2:
        return empty
    sel = whole_periods(t, f_s)
    freqs = np.concatenate([(k[:, None] * teeth + j[None, :]).ravel(), np.arange(1, sides + 1)]) * f_s
    names = list(signals)
    _, X = line_fit(np.column_stack([signals[n] for n in names])[sel], t[sel], freqs)
    amp = np.abs(X)
    n_side = k.size * j.size
    return Sidebands(member, f_s, revolutions, empty.mesh_orders, empty.sides,
                     {n: amp[:n_side, i].reshape(k.size, j.size) for i, n in enumerate(names)},
                     {n: amp[n_side:, i] for i, n in enumerate(names)})
