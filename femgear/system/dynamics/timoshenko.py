"""Timoshenko (shear-deformable) 3-D beam element and Guyan condensation.

12×12 stiffness and consistent mass of a uniform beam element with 6 DOF per node,
from Przemieniecki, *Theory of Matrix Structural Analysis* (1968), §5 and §11 (shear
parameter Φ = 12 E I / (κ G A L²)); the same matrices follow from the interdependent
interpolation of Friedman & Kosmatka, Comput. Struct. 47:473 (1993).  Rotary inertia
is included.  Shear coefficient of a solid circle κ = 6(1+ν)/(7+6ν) (Cowper 1966).

The element's local x axis is the beam axis.  femgear's shafts run along the global z
axis, DOFs per node ordered (x, y, z, θx, θy, θz); :func:`shaft_element` rotates the
element there (local x, y, z = global z, x, y).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class ShaftSection:
    """A solid circular shaft section and its material."""

    diameter: float          #: [m]
    youngs_modulus: float    #: E [Pa]
    poisson_ratio: float     #: ν [-]
    density: float           #: ρ [kg/m^3]

    def __post_init__(self):
        for name in ("diameter", "youngs_modulus", "density"):
            if not getattr(self, name) > 0:
                raise ValueError(f"ShaftSection.{name} must be positive (got {getattr(self, name)!r})")
        if not 0 <= self.poisson_ratio < 0.5:
            raise ValueError(f"ShaftSection.poisson_ratio must be in [0, 0.5) (got {self.poisson_ratio!r})")

    @property
    def area(self) -> float:
        return math.pi * self.diameter**2 / 4

    @property
    def second_moment(self) -> float:
        """I = π d⁴/64 about a diameter [m^4]."""
        return math.pi * self.diameter**4 / 64

    @property
    def shear_modulus(self) -> float:
        return self.youngs_modulus / (2 * (1 + self.poisson_ratio))

    @property
    def shear_coefficient(self) -> float:
        """Cowper's κ for a solid circle."""
        nu = self.poisson_ratio
        return 6 * (1 + nu) / (7 + 6 * nu)


def _bending(EI: float, phi: float, L: float, sign: float) -> np.ndarray:
    """4×4 bending stiffness on (v1, θ1, v2, θ2); sign = +1 for the x-y plane, −1 for x-z."""
    s = sign
    c = EI / ((1 + phi) * L**3)
    return c * np.array([
        [12, s * 6 * L, -12, s * 6 * L],
        [s * 6 * L, (4 + phi) * L**2, -s * 6 * L, (2 - phi) * L**2],
        [-12, -s * 6 * L, 12, -s * 6 * L],
        [s * 6 * L, (2 - phi) * L**2, -s * 6 * L, (4 + phi) * L**2],
    ])


def _bending_mass(rhoA: float, rhoI: float, phi: float, L: float, sign: float) -> np.ndarray:
    """4×4 consistent mass (translational + rotary inertia) on (v1, θ1, v2, θ2)."""
    s, p = sign, phi
    m = rhoA * L / (1 + p) ** 2
    a = 13 / 35 + 7 * p / 10 + p**2 / 3
    b = (11 / 210 + 11 * p / 120 + p**2 / 24) * L
    c = 9 / 70 + 3 * p / 10 + p**2 / 6
    d = (13 / 420 + 3 * p / 40 + p**2 / 24) * L
    e = (1 / 105 + p / 60 + p**2 / 120) * L**2
    f = (1 / 140 + p / 60 + p**2 / 120) * L**2
    mt = m * np.array([
        [a, s * b, c, -s * d],
        [s * b, e, s * d, -f],
        [c, s * d, a, -s * b],
        [-s * d, -f, -s * b, e],
    ])
    r = rhoI / ((1 + p) ** 2 * L)
    g = (1 / 10 - p / 2) * L
    h = (2 / 15 + p / 6 + p**2 / 3) * L**2
    k = (-1 / 30 - p / 6 + p**2 / 6) * L**2
    mr = r * np.array([
        [6 / 5, s * g, -6 / 5, s * g],
        [s * g, h, -s * g, k],
        [-6 / 5, -s * g, 6 / 5, -s * g],
        [s * g, k, -s * g, h],
    ])
    return mt + mr


def beam_element_local(section: ShaftSection, length: float) -> tuple[np.ndarray, np.ndarray]:
    """(K, M), 12×12, in local axes: per node (u, v, w, θx, θy, θz), x = beam axis."""
    if not length > 0:
        raise ValueError(f"beam element length must be positive (got {length!r})")
    E, G, A, I = section.youngs_modulus, section.shear_modulus, section.area, section.second_moment
    J = 2 * I
    rho, L = section.density, length
    phi = 12 * E * I / (section.shear_coefficient * G * A * L**2)
    K = np.zeros((12, 12))
    M = np.zeros((12, 12))
    ax = [0, 6]
    K[np.ix_(ax, ax)] = E * A / L * np.array([[1, -1], [-1, 1]])
    M[np.ix_(ax, ax)] = rho * A * L / 6 * np.array([[2, 1], [1, 2]])
    tor = [3, 9]
    K[np.ix_(tor, tor)] = G * J / L * np.array([[1, -1], [-1, 1]])
    M[np.ix_(tor, tor)] = rho * J * L / 6 * np.array([[2, 1], [1, 2]])
    xy = [1, 5, 7, 11]   # v, θz: bending in the x-y plane
    K[np.ix_(xy, xy)] = _bending(E * I, phi, L, +1.0)
    M[np.ix_(xy, xy)] = _bending_mass(rho * A, rho * I, phi, L, +1.0)
    xz = [2, 4, 8, 10]   # w, θy: bending in the x-z plane
    K[np.ix_(xz, xz)] = _bending(E * I, phi, L, -1.0)
    M[np.ix_(xz, xz)] = _bending_mass(rho * A, rho * I, phi, L, -1.0)
    return K, M


#: rows: local axes (x_l, y_l, z_l) expressed in global (x, y, z): x_l = z, y_l = x, z_l = y
_R = np.array([[0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]])


def shaft_element(section: ShaftSection, length: float) -> tuple[np.ndarray, np.ndarray]:
    """(K, M), 12×12, of a shaft element along global z, per node (x, y, z, θx, θy, θz)."""
    K, M = beam_element_local(section, length)
    T = np.kron(np.eye(4), _R)
    return T.T @ K @ T, T.T @ M @ T


def guyan(K: np.ndarray, M: np.ndarray, keep: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Static (Guyan 1965) condensation onto the DOFs ``keep``.

    Returns (K_r, M_r, T) with full = T @ reduced; exact for statics, for the mass it is
    the usual approximation (good while the condensed DOFs carry little inertia).
    """
    n = K.shape[0]
    keep = np.asarray(keep)
    drop = np.setdiff1d(np.arange(n), keep)
    T = np.zeros((n, keep.size))
    T[keep, np.arange(keep.size)] = 1.0
    if drop.size:
        T[drop] = -np.linalg.solve(K[np.ix_(drop, drop)], K[np.ix_(drop, keep)])
    return T.T @ K @ T, T.T @ M @ T, T
