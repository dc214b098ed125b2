"""Shared operating point: the paper's oil and steel (studies/paper_baseline.toml) at a
contact near the middle of the baseline path."""

from pathlib import Path

from femgear.physics.contact.hertz import reduced_modulus
from femgear.physics.lubrication.oil import OilLaw
from femgear.physics.lubrication.path import solids_of
from femgear.physics.tehl.solver import thermal_props
from femgear.scene import load_scene

SCENE = load_scene(Path(__file__).resolve().parents[2] / "studies" / "paper_baseline.toml")
OIL = OilLaw.from_table(SCENE.oil, SCENE.oil_reference_temperature)
PROPS = thermal_props(solids_of(SCENE.material, SCENE.oil), SCENE.oil.specific_heat, SCENE.material.conductivity)
E_RED = reduced_modulus(SCENE.material.youngs_modulus, SCENE.material.poisson_ratio)
W, R, UE, T0 = 84332.0, 0.0123, 1.09, 313.0
TAU0 = SCENE.oil.eyring_stress
