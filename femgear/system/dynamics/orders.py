"""Order analysis of recorded signals: the amplitudes of lines at known frequencies (mesh and shaft orders).

A steady response of the gear-rotor model is a sum of lines at known frequencies: the mesh
orders k f_m, the shaft orders j f_s of each member (f_s = f_m / z) and their combinations
k f_m + j f_s (the sidebands of eccentricity, run-out and pitch errors).  Their amplitudes are
read by a linear least-squares fit of x(t) ≈ x̄ + Re Σ_i X_i e^{2πi f_i t} over the record: exact
for a signal made of the fitted lines (whatever the window), and with no window's scalloping or
leakage between lines whose spacing the record resolves (record length T ≥ 1/Δf).  A line set
that the record does not resolve (two lines closer than 1/T) is refused rather than split
arbitrarily (:func:`resolves`).

The mesh orders alone are fitted over the largest whole number of mesh periods at the end of the
record (:func:`mesh_orders`), where the lines are orthogonal and content between them (a shaft
order) leaks least.
"""

from __future__ import annotations

import math

import numpy as np

#: mesh orders reported by default (1 … ORDERS)
ORDERS = 6


def resolves(t: np.ndarray, frequencies: np.ndarray) -> bool:
    """Whether a record at times ``t`` [s] separates the lines ``frequencies`` [Hz]: every two of them (and
    the mean, f = 0) are at least 1/T apart, T the record length."""
    f = np.sort(np.concatenate([[0.0], np.abs(np.asarray(frequencies, dtype=float))]))
    span = float(t[-1] - t[0])
    return span > 0 and bool(np.all(np.diff(f) * span >= 1.0 - 1e-9))


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
    return t >= t[-1] - periods / frequency - 1e-9 * span


def mesh_orders(x: np.ndarray, t: np.ndarray, mesh_frequency: float, orders: int = ORDERS) -> np.ndarray:
    """Amplitudes |X_k| of the mesh orders k = 1 … ``orders`` of ``x`` (n_t, ...), shape (orders, ...), from
    :func:`line_fit` over the record's last whole mesh periods."""
    sel = whole_periods(t, mesh_frequency)
    return np.abs(line_fit(np.asarray(x)[sel], t[sel], mesh_frequency * np.arange(1, orders + 1))[1])
