"""Friction and contact temperature of line contacts from operating data (the ``formula`` level).

:class:`LineFriction` binds an oil, the solids and the traction parameters to
:func:`femgear.physics.lubrication.traction.line_contact_friction` (thermal Eyring traction
of the Hertzian film), with rough flanks the mixed-lubrication split of
:mod:`femgear.physics.lubrication.mixed`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from femgear.physics.contact.path import ContactPath
from femgear.physics.lubrication.flash import thermal_effusivity
from femgear.physics.lubrication.mixed import Roughness
from femgear.physics.lubrication.oil import OilLaw
from femgear.physics.lubrication.traction import Solids, TractionResult, line_contact_friction


def solids_of(material, oil) -> Solids:
    """Effusivities of two members of one steel (``material``: conductivity, density, specific_heat)
    and the oil conductivity (``oil.conductivity``)."""
    B = thermal_effusivity(material.conductivity, material.density, material.specific_heat)
    return Solids(B1=B, B2=B, k_oil=oil.conductivity)


@dataclass(frozen=True)
class LineFriction:
    """``(w, R, ue, srr, T) -> TractionResult``: the friction of line contacts with one oil, solids and
    traction law bound (the ``formula`` level); with ``roughness`` the mixed-lubrication split."""

    oil: OilLaw
    """viscosity and density laws of the oil"""
    E_red: float
    """reduced modulus E' [Pa]"""
    solids: Solids
    """effusivities of the members and the oil conductivity"""
    tau0: float
    """Eyring stress τ0 [Pa]"""
    limiting_shear: float = 0.0
    """limiting shear stress coefficient Λ (τ_L = Λ p; 0: none) [-]"""
    roughness: Roughness | None = None
    """composite roughness of the flanks (None: smooth, full film)"""
    boundary_coefficient: float = 0.1
    """boundary friction coefficient μ_b of the asperity contacts (with ``roughness``) [-]"""
    model: str = "eyring"
    """traction law ("eyring" or "newtonian")"""
    n: int = 48
    """integration points across the Hertzian band [-]"""

    def __call__(self, w, R, ue, srr, T) -> TractionResult:
        kw = dict(model=self.model, tau0=self.tau0, limiting_shear=self.limiting_shear, n=self.n)
        if self.roughness is not None:
            from femgear.physics.lubrication.mixed import mixed_line_friction

            return mixed_line_friction(w, R, ue, srr, T, self.oil, self.E_red, self.solids, self.roughness,
                                       self.boundary_coefficient, **kw)[0]
        return line_contact_friction(w, R, ue, srr, T, self.oil, self.E_red, self.solids, **kw)

    def along(self, contact: ContactPath, T: float | np.ndarray) -> TractionResult:
        """Friction at every position of a contact pass at its mean load per length, oil at ``T`` [K]."""
        k = contact.kin
        return self(contact.load_per_length, k.R, k.ue, k.srr, T)
