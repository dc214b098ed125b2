"""Thin rims, pinions cut on their shafts and narrow tips in the FE meshes (issue 39 items 1 and 3).

- A rim down to ISO 6336-3's s_R = 0.5 h_t meshes (2-D section and 3-D body) with three elements through it;
  below that the section refuses naming ``bore_radius`` and the thinnest rim that runs, and the scene refuses
  up front naming ``gear.bore_radius`` (exit 2, nothing written).
- A member without a bore (cut on its shaft) is clamped at its shaft radius, at least 1.2 h_t below the root.
- The FZG A pinion's 0.59 mm (0.13 m_n) tip meshes at the ``fe`` level's m_n/4 with two elements across it.
"""

from __future__ import annotations

import math
import tomllib
from pathlib import Path

import numpy as np
import pytest

from femgear.edge.cli import main
from femgear.physics.geometry.gear import GearPair
from femgear.physics.geometry.profile import tooth_profile
from femgear.physics.mesh.section import (
    MIN_RIM,
    RIM_ELEMENTS,
    check_rim,
    gear_section,
    rim_limit,
    shaft_clamp_radius,
    tip_width,
)

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def baseline():
    return GearPair.from_parameters(z1=31, z2=34, m_n=3e-3, alpha_n=math.radians(20), beta=math.radians(30),
                                    b=17.5e-3, x1=0.0, x2=0.0)


def test_the_thinnest_rim_meshes_with_three_elements_through_it(baseline):
    p = baseline
    h_t = p.ra2 - p.rf2
    bore = rim_limit(p, 2)
    assert p.rf2 - bore == pytest.approx(MIN_RIM * h_t, rel=1e-12)
    sec = gear_section(p, 2, p.m_n / 4, n_teeth=None, bore_radius=bore, refine_at=(0.0, 0.5 * (p.rf2 + p.ra2)),
                       refine_ratio=0.5, refine_radius=1.2 * h_t, grade=(0.35, 1.0 * p.m_n, 3))
    r = np.hypot(*sec.p[:, sec.t].mean(axis=1))
    rim = r < p.rf2 - 0.1 * h_t                        # triangles of the rim below the fillets
    edges = np.hypot(*(sec.p[:, sec.t[[0, 1, 2]]] - sec.p[:, sec.t[[1, 2, 0]]]))
    assert rim.any() and edges[:, rim].max() <= 1.35 * (p.rf2 - bore) / RIM_ELEMENTS


def test_a_rim_below_half_the_tooth_depth_is_refused_naming_the_bore(baseline):
    p = baseline
    with pytest.raises(ValueError, match=r"bore_radius=.*0\.45 h_t.*thinnest rim that runs has bore_radius ≤ "):
        check_rim(p, 2, p.rf2 - 0.45 * (p.ra2 - p.rf2))


def test_the_scene_refuses_a_thin_rim_up_front_in_one_line(tmp_path, capsys):
    data = tomllib.loads((ROOT / "studies" / "paper_baseline.toml").read_text())
    scene = tmp_path / "thin.toml"
    text = (ROOT / "studies" / "paper_baseline.toml").read_text()
    rf2 = 0.5 * 34 * 3e-3 / math.cos(math.radians(data["pair"]["helix_angle_deg"])) - 1.25 * 3e-3
    bore = rf2 - 0.4 * 2.25 * 3e-3
    scene.write_text(text.replace("[gear]", f"[gear]\nbore_radius = {bore:.6f}", 1))
    out = tmp_path / "run"
    rc = main(["run", str(scene), "--out", str(out)])
    err = capsys.readouterr().err.strip().splitlines()
    assert rc == 2 and len(err) == 1 and err[0].startswith("femgear: error: gear.bore_radius: ")
    assert "0.5 h_t" in err[0] and not out.exists()
    thinnest = float(err[0].split("the thinnest rim that runs has bore_radius ≤ ")[1].split(" mm")[0]) * 1e-3
    scene.write_text(text.replace("[gear]", f"[gear]\nbore_radius = {thinnest!r}", 1))
    assert main(["info", str(scene)]) == 0                    # the figure the message names runs


def test_a_pinion_cut_on_its_shaft_is_clamped_at_least_a_thick_rim_deep():
    """The zoo's automotive pinion (Ø30 mm shaft, r_f 19.66 mm, h_t 6.09 mm): its shaft would leave 0.77 h_t;
    the solid pinion is clamped 1.2 h_t below its root.  A shaft far inside the root keeps its own radius."""
    p = GearPair.from_parameters(z1=16, z2=37, m_n=2.75e-3, alpha_n=math.radians(20), beta=0.0, b=0.02, x1=0.4,
                                 x2=0.15, kind="spur")
    h_t = p.ra1 - p.rf1
    assert shaft_clamp_radius(p, 1, 0.015) == pytest.approx(p.rf1 - 1.2 * h_t, rel=1e-12)
    assert shaft_clamp_radius(p, 1, 0.008) == 0.008


def test_a_narrow_tip_gets_two_elements_across_it():
    """The FZG A pinion (x 0.8532, d_a 88.77 mm): a 0.59 mm tip at h = m_n/4 = 1.125 mm; before, the section
    refused ('needs two elements across').  The tip's own size leaves the rest of the mesh in module units."""
    p = GearPair(z1=16, z2=24, m_n=4.5e-3, alpha_n=math.radians(20), beta=0.0, b=0.02, x1=0.8532, x2=-0.5,
                 kind="spur", tip_radius1=88.77e-3 / 2, tip_radius2=112.5e-3 / 2)
    prof = tooth_profile(p, 1)
    width = tip_width(prof)
    assert width == pytest.approx(0.590e-3, abs=2e-6)
    sec = gear_section(p, 1, p.m_n / 4, n_teeth=3, bore_radius=0.015)
    tip = sec.boundaries["tip"]
    length = np.linalg.norm(sec.p[:, sec.facets[0, tip]] - sec.p[:, sec.facets[1, tip]], axis=0)
    assert length.max() <= width / 2
    fillet = sec.boundaries["fillet"]
    flen = np.linalg.norm(sec.p[:, sec.facets[0, fillet]] - sec.p[:, sec.facets[1, fillet]], axis=0)
    assert flen.max() > 0.8 * p.m_n / 4 > 1.5 * width     # the fillets keep their m_n/4
