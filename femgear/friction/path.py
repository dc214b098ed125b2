"""Friction and contact temperature along the path of contact (the ``formula`` level)."""

from __future__ import annotations

from femgear.contact.hertz import reduced_modulus
from femgear.contact.path import ContactPath
from femgear.friction.flash import thermal_effusivity
from femgear.friction.oil import OilLaw
from femgear.friction.traction import Solids, TractionResult, gupta_thermal_factor, hertz_traction


def solids_of(scene) -> Solids:
    m = scene.material
    B = thermal_effusivity(m.conductivity, m.density, m.specific_heat)
    return Solids(B1=B, B2=B, k_oil=scene.oil.conductivity)


def friction_along_path(scene, contact: ContactPath, model: str = "eyring", n: int = 48) -> TractionResult:
    """Thermal Eyring traction at every position of a quasi-static contact pass.

    The film is the Moes central film times Gupta's thermal factor; the oil enters at
    the ambient temperature.
    """
    oil = OilLaw.from_scene(scene)
    E_red = reduced_modulus(scene.material.youngs_modulus, scene.material.poisson_ratio)
    k = contact.kin
    phi = gupta_thermal_factor(contact.hertz_pressure, E_red, k.srr, k.ue, oil.eta0, oil.beta_t, scene.oil.conductivity)
    return hertz_traction(
        contact.load_per_length, contact.hertz_half_width, contact.hertz_pressure, contact.film_central * phi,
        k.v1, k.v2, scene.operating.ambient_temperature, oil, solids_of(scene), model=model,
        tau0=scene.oil.eyring_stress, limiting_shear=scene.oil.limiting_shear_coeff, n=n,
    )
