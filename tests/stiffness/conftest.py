from pathlib import Path

import pytest

from femgear.geometry.gear import GearPair
from femgear.scene import load_scene

BASELINE = Path(__file__).resolve().parents[2] / "studies" / "paper_baseline.toml"


@pytest.fixture(scope="session")
def baseline_scene():
    return load_scene(BASELINE)


@pytest.fixture(scope="session")
def baseline_pair(baseline_scene):
    """The paper's baseline helix (31/34, m_n 3 mm, β 30°, b 17.5 mm per helix)."""
    return GearPair.from_scene(baseline_scene)
