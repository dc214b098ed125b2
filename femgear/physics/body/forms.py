"""Weak forms of the gear body: heat conduction and plane thermo-elasticity (scikit-fem).

Small pure forms; material constants are bound by the factory arguments.

Plane stress (thin disc, free faces — the thermal expansion problem) and plane strain
(wide teeth — the compliance problem) differ only in the in-plane Lamé constant and
the thermal modulus (Timoshenko & Goodier, *Theory of Elasticity*, 3rd ed., §§13, 150):

    plane stress: λ* = Eν/(1−ν²),      β_T = E λ_T/(1−ν)
    plane strain: λ  = Eν/((1+ν)(1−2ν)), β_T = E λ_T/(1−2ν)

σ = 2μ ε + λ* tr ε I − β_T ΔT I, with λ_T the linear expansion coefficient.
"""

from __future__ import annotations

from skfem import BilinearForm, LinearForm
from skfem.helpers import ddot, div, dot, eye, grad, sym_grad, trace


def lame(youngs_modulus: float, poisson_ratio: float, plane: str) -> tuple[float, float]:
    """In-plane Lamé constants (λ*, μ) for ``plane`` = 'stress' or 'strain'."""
    E, nu = youngs_modulus, poisson_ratio
    mu = E / (2 * (1 + nu))
    if plane == "stress":
        return E * nu / (1 - nu**2), mu
    if plane == "strain":
        return E * nu / ((1 + nu) * (1 - 2 * nu)), mu
    raise ValueError(f"plane must be 'stress' or 'strain', got {plane!r}")


def thermal_modulus(youngs_modulus: float, poisson_ratio: float, expansion: float, plane: str) -> float:
    """β_T such that the thermal stress is −β_T ΔT I [Pa/K]."""
    lam, mu = lame(youngs_modulus, poisson_ratio, plane)
    if plane == "stress":
        return 2 * (lam + mu) * expansion          # = E λ_T/(1−ν)
    return (3 * lam + 2 * mu) * expansion          # = E λ_T/(1−2ν)


def conduction(k: float) -> BilinearForm:
    """∫ k ∇T·∇v."""

    @BilinearForm
    def form(u, v, w):
        return k * dot(grad(u), grad(v))

    return form


def elasticity(lam: float, mu: float) -> BilinearForm:
    """∫ σ(u) : ε(v) with σ = 2μ ε + λ tr ε I."""

    @BilinearForm
    def form(u, v, w):
        eps = sym_grad(u)
        return ddot(2 * mu * eps + lam * eye(trace(eps), 2), sym_grad(v))

    return form


@LinearForm
def thermal_load(v, w):
    """∫ β_T ΔT div v  (``w.beta_T`` constant, ``w.dT`` the temperature rise field)."""
    return w.beta_T * w.dT * div(v)


@LinearForm
def traction(v, w):
    """∫ t·v ds on a facet basis (``w.tx``, ``w.ty``: traction components)."""
    return w.tx * v[0] + w.ty * v[1]


@BilinearForm
def normal_penalty(u, v, w):
    """∫ κ (u·n)(v·n) ds: a roller (zero normal displacement) by penalty, κ = ``w.kappa``."""
    return w.kappa * dot(u, w.n) * dot(v, w.n)
