"""Half-space (Boussinesq) and Hertz line-contact formulas of the local contact compliance.

- Boussinesq point load P on an elastic half-space, normal displacement at depth z and
  horizontal distance r (Johnson, *Contact Mechanics*, 1985, §3.2, eq. 3.22):
  u_z = P/(4πG) · [2(1−ν)/R + z²/R³],  R² = r² + z²,  G = E/(2(1+ν)).
  At z = 0 this is (1−ν²)P/(πE r).
- Uniform pressure p on a rectangle 2a × 2c, surface displacement at its centre
  (Love 1929; Johnson §3.3): u = (1−ν²)p/(πE) · 4[a asinh(c/a) + c asinh(a/c)].
- Hertz line contact (Johnson §4.3): b_H = √(8wR/(πE′)), p_H = √(wE′/(2πR)), with w the
  load per unit length, R the reduced radius and 2/E′ = Σ(1−ν_i²)/E_i.
  A Hertz strip of half-width b_H is represented by a uniform rectangle of half-width
  a = 0.824 b_H, which gives the same centre displacement for c ≫ b_H
  (the elliptic-pressure centre value equals the uniform one when ln(4c/a) terms match:
  a/b_H = e^{1/2}/2 = 0.824; notes ltca_methods §3).
"""

from __future__ import annotations

import math

import numpy as np

HERTZ_TO_UNIFORM = math.exp(0.5) / 2      #: a / b_H of the equivalent uniform strip


def boussinesq_depth(r: np.ndarray, depth: np.ndarray, youngs_modulus: float, poisson_ratio: float) -> np.ndarray:
    """Normal displacement per unit point load at depth ``depth`` and horizontal distance ``r`` [m/N]."""
    G = youngs_modulus / (2 * (1 + poisson_ratio))
    R = np.sqrt(np.asarray(r, float) ** 2 + np.asarray(depth, float) ** 2)
    return (2 * (1 - poisson_ratio) / R + np.asarray(depth, float) ** 2 / R**3) / (4 * math.pi * G)


def surface_green(r: np.ndarray, youngs_modulus: float, poisson_ratio: float) -> np.ndarray:
    """Surface normal displacement per unit point load at distance r > 0: (1−ν²)/(πE r) [m/N]."""
    return (1 - poisson_ratio**2) / (math.pi * youngs_modulus * np.asarray(r, float))


def strip_self_compliance(half_width: np.ndarray, half_length: np.ndarray, youngs_modulus: float,
                          poisson_ratio: float) -> np.ndarray:
    """Centre displacement per unit force of a uniform 2a × 2c rectangle load [m/N] (Love)."""
    a = np.asarray(half_width, float)
    c = np.asarray(half_length, float)
    per_pressure = (1 - poisson_ratio**2) / (math.pi * youngs_modulus) * 4 * (a * np.arcsinh(c / a) + c * np.arcsinh(a / c))
    return per_pressure / (4 * a * c)


def hertz_half_width(load_per_length: np.ndarray, radius: np.ndarray, reduced_modulus: float) -> np.ndarray:
    """b_H = √(8 w R/(π E′)) [m]."""
    return np.sqrt(8 * np.asarray(load_per_length, float) * np.asarray(radius, float) / (math.pi * reduced_modulus))


def hertz_pressure(load_per_length: np.ndarray, radius: np.ndarray, reduced_modulus: float) -> np.ndarray:
    """p_H = √(w E′/(2π R)) [Pa]."""
    return np.sqrt(np.asarray(load_per_length, float) * reduced_modulus / (2 * math.pi * np.asarray(radius, float)))


def reduced_modulus(youngs_modulus: float, poisson_ratio: float) -> float:
    """E′ of two bodies of the same material: 2/E′ = 2(1−ν²)/E [Pa]."""
    return youngs_modulus / (1 - poisson_ratio**2)
