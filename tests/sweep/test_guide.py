"""docs/guide/sweeps.md: its sweep file is valid as printed, and the error lines it quotes are femgear's."""

import re
import shutil
from pathlib import Path

import pytest

from femgear.edge.sweep import parse_sweep
from femgear.edge.sweep.check import check_cases
from femgear.errors import SceneError

ROOT = Path(__file__).resolve().parents[2]
GUIDE = (ROOT / "docs" / "guide" / "sweeps.md").read_text(encoding="utf-8")


def test_the_guides_sweep_file_is_valid_as_printed(tmp_path):
    block = re.search(r"```toml\n(.*?)```", GUIDE, re.S).group(1)
    shutil.copy(ROOT / "studies" / "paper_baseline.toml", tmp_path)
    (tmp_path / "rig.toml").write_text(block)
    spec = parse_sweep(tmp_path / "rig.toml")
    assert len(spec.cases) == 16 and spec.name == "rig15"
    assert spec.outputs == ("friction.mu_mean", "dynamics.amplitudes.dte_rms")
    check_cases(spec)
    grid = parse_sweep(ROOT / "studies" / "rig15_sweep.toml")
    assert set(c.overrides for c in grid.cases) < set(c.overrides for c in spec.cases)


@pytest.mark.parametrize("grid", ['"operating.sped_rpm" = [100.0]', '"operating.torque" = [100.0, -5.0]'])
def test_the_error_lines_the_guide_quotes_are_femgears(tmp_path, grid):
    (tmp_path / "bad.toml").write_text(f'base = "{ROOT / "studies" / "paper_baseline.toml"}"\n[grid]\n{grid}\n')
    with pytest.raises(SceneError) as info:
        check_cases(parse_sweep(tmp_path / "bad.toml"))
    assert f"femgear: error: {info.value}\n" in GUIDE
