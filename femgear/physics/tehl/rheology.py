"""Temperature field in the dimensionless EHL rheology: the thermal hook of the Reynolds operator.

:class:`ThermalRheology` is a :class:`femgear.physics.ehl.core.rheology.Rheology` that also knows a
temperature field (held in ``state``: ``"node"`` values on the EHL nodes, ``"quad"``
values at the quadrature points of the Reynolds assembly).  The Reynolds operator calls
``log_eta``/``density`` with nodal arrays (1-D) or quadrature arrays (2-D, elements x
points); the matching field is chosen by the number of dimensions.  Temperatures are
frozen during one EHL Newton solve (the thermal loop is outside Newton, Habchi 2008,
Habchi 2018 "Finite element modeling of elastohydrodynamic lubrication problems" ch. 5).

Roelands with temperature (Roelands 1966; Houpert 1985; the seed paper's §3.1.3), written
about the bulk temperature T_b of the solve, where η(0, T_b) = η_b is the EHL's η0:

    ln(η/η_b) = (ln η_b + 9.67) [(1 + p/p0)^z ((T − 138)/(T_b − 138))^(−S0) − 1],

which is the paper's law referred to T0 exactly (ln η + 9.67 is a product of a pressure and
a temperature factor).  Barus: ln(η/η_b) = α p − β_T (T − T_b).  Density (only when the
Dowson–Higginson law is on): ρ/ρ_b = DH(p) (1 − ε (T − T_ref))/(1 − ε (T_b − T_ref)).
With T ≡ T_b every expression reduces bit for bit to the isothermal one (tested).

The generalised Reynolds equation (:mod:`femgear.physics.tehl.generalised`) enters as two nodal factors
frozen during a Newton solve (``state["eps_factor"]``, ``state["wedge_factor"]``, set by the thermal
loop from the layer temperatures): the Poiseuille coefficient is the reduced one at the film-mean
temperature times ``eps_factor`` = ε / ε_reduced, and the density of the wedge term (the only other
use of :meth:`density` in the FD line operator) is ρ times ``wedge_factor`` = q_c / (ρ u_ref h), which
may change sign (opposite sliding).  Their pressure dependence, which nearly cancels in the ratios, is
lagged by one thermal iteration; the fixed point is the generalised equation's solution.  Absent, both
are 1 and nothing changes.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np

from femgear.physics.ehl.core.rheology import ROELANDS_P0, Rheology


@dataclass(frozen=True)
class ThermalRheology(Rheology):
    """Rheology with a frozen temperature field [K] (``state["node"]``, ``state["quad"]``)."""

    T_bulk: float = 313.0   #: temperature of η0 in the dimensionless law [K]
    s0: float = 0.0         #: Roelands temperature index S0 [-]
    beta_t: float = 0.0     #: Barus temperature-viscosity coefficient [1/K]
    expansion: float = 0.0  #: density-temperature coefficient ε [1/K]
    T_ref: float = 313.0    #: reference temperature of the density law [K]
    state: dict = field(default_factory=dict, compare=False, repr=False)

    def _temperature(self, P: np.ndarray):
        T = self.state.get("quad" if np.ndim(P) == 2 else "node")
        if T is not None and np.shape(T) != np.shape(P):
            raise ValueError(f"temperature field of shape {np.shape(T)} does not match {np.shape(P)}")
        return T

    def log_eta(self, P: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        T = self._temperature(P)
        if T is None:
            return super().log_eta(P)
        Pc = np.maximum(P, 0.0)
        pos = P > 0.0
        if self.viscosity == "barus":
            return self.alpha_bar * Pc - self.beta_t * (T - self.T_bulk), np.where(pos, self.alpha_bar, 0.0)
        ratio = self.ph / ROELANDS_P0
        c = self.alpha_bar / (ratio * self.z)  # = ln(eta_b) + 9.67
        base = 1.0 + ratio * Pc
        th = ((T - 138.0) / (self.T_bulk - 138.0)) ** (-self.s0)
        val = c * (base**self.z * th - 1.0)
        der = c * self.z * ratio * base ** (self.z - 1.0) * th
        return val, np.where(pos, der, 0.0)

    def density(self, P: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        rho, drho = super().density(P)
        T = self._temperature(P)
        if T is not None and self.compressible:
            f = (1.0 - self.expansion * (T - self.T_ref)) / (1.0 - self.expansion * (self.T_bulk - self.T_ref))
            rho, drho = rho * f, drho * f
        w = self._factor("wedge_factor", P)
        return (rho, drho) if w is None else (rho * w, drho * w)

    def epsilon(self, P: np.ndarray, H: np.ndarray, lam_bar: float):
        """The Poiseuille coefficient at the film-mean temperature (with the density of the film, not the wedge's),
        times the generalised equation's ``eps_factor``."""
        f = self._factor("eps_factor", P)
        w = self._factor("wedge_factor", P)
        if f is None and w is None:
            return super().epsilon(P, H, lam_bar)
        plain = replace(self, state={k: v for k, v in self.state.items() if k in ("node", "quad")})
        eps, dP, dH = plain.epsilon(P, H, lam_bar)
        return (eps, dP, dH) if f is None else (eps * f, dP * f, dH * f)

    def _factor(self, key: str, P: np.ndarray):
        """The nodal factor ``key`` of the generalised equation (None: absent, or a quadrature-point call)."""
        if np.ndim(P) != 1:
            return None
        f = self.state.get(key)
        if f is not None and np.shape(f) != np.shape(P):
            raise ValueError(f"{key} of shape {np.shape(f)} does not match {np.shape(P)}")
        return f
