"""Friction and contact temperature along the path of contact (the ``formula`` level)."""

from __future__ import annotations

from femgear.physics.contact.hertz import reduced_modulus
from femgear.physics.contact.path import ContactPath
from femgear.physics.lubrication.flash import thermal_effusivity
from femgear.physics.lubrication.oil import OilLaw
from femgear.physics.lubrication.traction import Solids, TractionResult, line_contact_friction


def solids_of(scene) -> Solids:
    m = scene.material
    B = thermal_effusivity(m.conductivity, m.density, m.specific_heat)
    return Solids(B1=B, B2=B, k_oil=scene.oil.conductivity)


def scene_line_friction(scene, model: str = "eyring", n: int = 48):
    """``(w, R, ue, srr, T) -> TractionResult``: :func:`line_contact_friction` with the scene's
    oil, materials and traction parameters bound (the ``formula`` level); with rough flanks
    (``roughness.rq`` > 0) the mixed-lubrication split of :mod:`femgear.physics.lubrication.mixed`."""
    oil, solids = OilLaw.from_scene(scene), solids_of(scene)
    E_red = reduced_modulus(scene.material.youngs_modulus, scene.material.poisson_ratio)
    kw = dict(model=model, tau0=scene.oil.eyring_stress, limiting_shear=scene.oil.limiting_shear_coeff, n=n)
    rough = scene.roughness
    if rough.rq > 0:
        from femgear.physics.lubrication.mixed import Roughness, mixed_line_friction

        r = Roughness(rough.rq, rough.eta_beta_sigma, rough.sigma_over_beta)

        def mixed(w, R, ue, srr, T) -> TractionResult:
            return mixed_line_friction(w, R, ue, srr, T, oil, E_red, solids, r, scene.friction.boundary_coefficient,
                                       **kw)[0]

        return mixed

    def solve(w, R, ue, srr, T) -> TractionResult:
        return line_contact_friction(w, R, ue, srr, T, oil, E_red, solids, **kw)

    return solve


def friction_along_path(scene, contact: ContactPath, model: str = "eyring", n: int = 48) -> TractionResult:
    """Thermal Eyring traction at every position of a quasi-static contact pass (oil at ambient)."""
    k = contact.kin
    return scene_line_friction(scene, model, n)(contact.load_per_length, k.R, k.ue, k.srr,
                                                scene.operating.ambient_temperature)
