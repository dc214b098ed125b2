"""The driver's rating figures: ``[rating]`` table → ISO 6336-2 rating; power loss of the run's own μ; ``femgear info``."""

import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from femgear.case import build_case
from femgear.levels.contact import contact_pass
from femgear.rate import pitting_of, power_loss
from femgear.scene import load_scene

FZG = Path(__file__).resolve().parents[2] / "studies" / "fzg_c14.toml"


def test_rating_inputs_reach_the_factors():
    fixed = ["rating.dynamic_factor=1.0", "rating.face_load_factor=1.0", "rating.transverse_load_factor=1.0"]
    scene = load_scene(FZG, ["rating.application_factor=1.25", "rating.life_hours=100", *fixed])
    base = pitting_of(build_case(load_scene(FZG, fixed)))
    r = pitting_of(build_case(scene))
    assert r.stress.sigma_H[0] == pytest.approx(base.stress.sigma_H[0] * 1.25**0.5, rel=1e-12)
    assert r.N_L[0] == pytest.approx(60 * 2175 * 100) and r.Z_NT[0] > 1
    assert base.Z_L < 1 and base.Z_R != 1   # ν40 = 95 mm²/s and R_z given in the scene


def test_power_loss_constant_mu_is_ohlendorf_on_any_grid():
    """Constant μ: the loss is μ P_in H_V whatever grid the contact pass used (the B, D jumps are added)."""
    scene = load_scene(FZG, ["physics.lubrication=constant", "friction.coefficient=0.05"])
    case = build_case(scene)
    loss = power_loss(case, contact_pass(case), lambda u: np.full(np.shape(u), 0.05))
    assert loss.equivalent_mu == pytest.approx(0.05, rel=1e-6)
    assert loss.efficiency == pytest.approx(1 - 0.05 * loss.ohlendorf_HV, rel=1e-9)


def test_info_json_has_rating_and_power_loss():
    out = subprocess.run([sys.executable, "-m", "femgear", "info", str(FZG), "--json"], capture_output=True, text=True,
                         check=True)
    d = json.loads(out.stdout.strip().splitlines()[-1])
    assert d["rating"]["method"].startswith("ISO 6336-2") and len(d["rating"]["S_H"]) == 2
    assert 0.99 < d["power_loss"]["efficiency"] < 1
    assert d["contact"]["single_contact"]["B"]["hertz_pressure"] > d["contact"]["pitch"]["hertz_pressure"]
