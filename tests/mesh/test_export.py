"""meshes/export.py: the member bodies the LTCA solves, with their named regions, as .vtu for ParaView."""

import importlib.util
import json
from pathlib import Path

import numpy as np

from femgear.case import build_case
from femgear.case.pair import pair_from_scene
from femgear.levels.stiffness import body_options

ROOT = Path(__file__).resolve().parents[2]


def _export_module():
    spec = importlib.util.spec_from_file_location("femgear_meshes_export", ROOT / "meshes" / "export.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def test_export_writes_the_member_bodies_with_named_regions(tmp_path):
    """Coarse level: both bodies and both sections load with meshio; the regions (bore, the flanks of both
    helices per tooth and side, ...) carry facets and partition each body's boundary."""
    import meshio

    from femgear.physics.mesh.segment import default_spec, member_body
    from femgear.scene import load_scene

    written = _export_module().main([str(ROOT / "studies" / "paper_baseline.toml"), "--level", "0",
                                     "--out", str(tmp_path)])
    assert sorted(p.name for p in written) == ["gear_body.vtu", "gear_section.vtu", "pinion_body.vtu",
                                               "pinion_section.vtu"]
    scene = load_scene(ROOT / "studies" / "paper_baseline.toml")
    pair, body = pair_from_scene(scene), body_options(build_case(scene))
    for member, name in ((1, "pinion"), (2, "gear")):
        mesh = meshio.read(tmp_path / f"{name}_body.vtu")
        info = json.loads((tmp_path / f"{name}_body_regions.json").read_text())
        tags = {n: v["tag"] for n, v in info["region_tag"].items()}
        region = np.concatenate(mesh.cell_data["region"])
        counts = {n: int(np.sum(region == t)) for n, t in tags.items()}
        for n in ("bore", "end0", "end1", "fillet", "tip", "rim", "flank_left_t+0_drive", "flank_right_t+0_drive",
                  "flank_left_t+0_coast", "flank_right_t-1_drive"):
            assert counts[n] > 0, n
            assert counts[n] == info["region_tag"][n]["facets"]
        assert counts == {n: v["facets"] for n, v in info["region_tag"].items()}
        spec = default_spec(pair, member, 0, r_bore=body["bore_radius"][member - 1], groove=body["groove_width"],
                            stagger=body["stagger"])
        ref = member_body(pair, member, spec)
        assert mesh.points.shape[0] == ref.p.shape[1]
        assert mesh.get_cells_type("tetra").shape[0] == ref.t.shape[1] == int(np.sum(region == 0))
        assert sum(counts.values()) == ref.boundary_facets().size          # every boundary facet once
        assert counts["flank_left_t+0_drive"] == ref.boundaries["loaded_flank"].size   # the LTCA's loaded flanks
        assert counts["flank_right_t+0_drive"] == ref.boundaries["loaded_flank_right"].size
        assert np.ptp(mesh.points[:, 2]) == np.ptp(ref.p[2])                        # both helices
        sec = meshio.read(tmp_path / f"{name}_section.vtu")
        sec_info = json.loads((tmp_path / f"{name}_section_regions.json").read_text())
        sec_region = np.concatenate(sec.cell_data["region"])
        assert np.sum(sec_region == sec_info["region_tag"]["bore"]["tag"]) > 0


def test_flank_regions_split_the_flank_per_helix_tooth_and_side(pair):
    """The flank of a staggered, grooved body: the per-tooth regions partition it, mirror-symmetric in number."""
    from femgear.physics.mesh.segment import default_spec, flank_regions, member_body

    spec = default_spec(pair, 2, 0, n_teeth=3, r_bore=0.02, groove=4e-3, stagger=0.3)
    body = member_body(pair, 2, spec)
    regions = flank_regions(body, pair, 2, spec)
    assert len(regions) == 2 * 3 * 2
    allf = np.concatenate(list(regions.values()))
    assert np.unique(allf).size == allf.size == body.boundaries["flank"].size
    assert np.array_equal(regions["flank_right_t+0_drive"], body.boundaries["loaded_flank_right"])
    for k in (-1, 0, 1):
        for side in ("drive", "coast"):
            assert regions[f"flank_left_t{k:+d}_{side}"].size == regions[f"flank_right_t{k:+d}_{side}"].size
