"""REXS carries what femgear knows (issue 37, item 8): the export and re-import of every zoo scene reproduce
``femgear info``'s safety factors exactly, with the rating, the lubrication method and the physics levels back;
the oil data are written at the temperatures their attributes name.

Before, K_A, the life, the lubrication method and the levels were lost (marine: S_H 1.35 → 1.51, S_F 2.64 →
3.31; automotive: S_H 1.05 → 0.94), α at the reference temperature was written under the 38 °C attribute, and a
module of 4.5 mm came back as 0.0045000000000000005 m (S_H of FZG C off in the 16th digit).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from femgear.case import build_case
from femgear.physics.lubrication.oil import OilLaw
from femgear.rate import scene_info
from femgear.rexs.importer import scene_from_rexs
from femgear.rexs.read import read_model
from femgear.scene import load_scene

ROOT = Path(__file__).resolve().parents[2]
ZOO = sorted((ROOT / "studies" / "zoo").glob("*.toml"))


def _safety_factors(scene) -> dict:
    sf = scene_info(build_case(scene, warn=False)).rating.safety_factors
    return {k: (tuple(v) if isinstance(v, (list, tuple, np.ndarray)) else v) for k, v in sf.items()
            if k.startswith("S_")}


@pytest.mark.parametrize("suffix", [".rexs", ".rexsj"])
@pytest.mark.parametrize("scene_path", ZOO, ids=lambda p: p.stem)
def test_every_zoo_scene_comes_back_with_the_same_safety_factors(scene_path, suffix, cli, tmp_path):
    out = tmp_path / f"pair{suffix}"
    rc, _, err = cli("rexs", "--export", scene_path, "-o", out)
    assert rc == 0, err
    original, back = load_scene(scene_path), scene_from_rexs(out, warn=False)
    assert _safety_factors(back) == _safety_factors(original)          # exactly, every digit
    assert back.rating == original.rating
    assert back.physics.model_dump(exclude={"preset"}) == original.physics.model_dump(exclude={"preset"})


def test_a_changed_rating_survives_the_round_trip(cli, tmp_path):
    marine = ROOT / "studies" / "zoo" / "marine.toml"
    sets = ["rating.application_factor=1.75", "rating.life_hours=2e4", 'rating.lubrication_method="spray"',
            "rating.roughness_ra=[3e-7, 5e-7]", "rating.root_roughness_rz=[8e-6, 1.2e-5]", 'rating.finishing="honed"',
            "rating.oil_viscosity_40=150.0", 'physics.lubrication="constant"', 'physics.stiffness="iso6336"']
    out = tmp_path / "pair.rexs"
    rc, _, err = cli("rexs", "--export", marine, "-o", out, *[a for s in sets for a in ("--set", s)])
    assert rc == 0, err
    original, back = load_scene(marine, sets), scene_from_rexs(out, warn=False)
    assert back.rating == original.rating and back.physics.lubrication == "constant"
    assert _safety_factors(back) == _safety_factors(original)


def test_oil_data_are_written_at_the_temperatures_their_attributes_name(cli, tmp_path):
    """turbo's oil holds at 50 °C: its density at 15 °C and α at 38 °C follow from the oil's own laws (density
    ρ0 (1 − ε (T − T0)); α = ∂ln η/∂p at p = 0 of the Roelands law, here by a finite difference of ln η)."""
    turbo = ROOT / "studies" / "zoo" / "turbo.toml"
    out = tmp_path / "pair.rexs"
    rc, _, err = cli("rexs", "--export", turbo, "-o", out)
    assert rc == 0, err
    model = read_model(out)
    lub = model.of_type("lubricant")[0]
    scene = load_scene(turbo)
    law = OilLaw.from_table(scene.oil, scene.oil_reference_temperature)
    rho15 = model.value(lub, "density_at_15_degree_celsius")
    assert rho15 == pytest.approx(float(law.density(0.0, 288.15)), rel=1e-12) and rho15 > scene.oil.density
    dp = 1e3
    slope = float(law.log_viscosity_ratio(dp, 311.15) - law.log_viscosity_ratio(0.0, 311.15)) / dp
    alpha38 = model.value(lub, "pressure_viscosity_coefficient_at_38_degrees_celsius")
    assert alpha38 == pytest.approx(slope, rel=1e-4)
    assert alpha38 > scene.oil.pressure_viscosity          # colder than the 50 °C reference: a larger α
    assert scene_from_rexs(out, warn=False).oil.pressure_viscosity == pytest.approx(scene.oil.pressure_viscosity,
                                                                                     rel=1e-12)
