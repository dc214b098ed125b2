"""Shared fixtures: the paper's baseline scene."""

from pathlib import Path

import pytest

from femgear.case.pair import pair_from_scene

ROOT = Path(__file__).resolve().parents[1]
BASELINE = ROOT / "studies" / "paper_baseline.toml"


@pytest.fixture(scope="session")
def baseline_path() -> Path:
    return BASELINE


@pytest.fixture(scope="session")
def baseline_scene():
    from femgear.scene import load_scene

    return load_scene(BASELINE)


@pytest.fixture(scope="session")
def baseline_pair(baseline_scene):

    return pair_from_scene(baseline_scene)
