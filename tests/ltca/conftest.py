"""A coarse LTCA model of the baseline pair (3-tooth P1 segments, 5 × 5 flank grid), cached on disk."""

import pytest


@pytest.fixture(scope="session")
def coarse_model(baseline_pair):
    from femgear.physics.ltca.analysis import build_model

    return build_model(baseline_pair, 210e9, 0.3, level=0, order=1, n_rho=5, n_z=5, n_teeth=3)


@pytest.fixture(scope="session")
def baseline_force(baseline_pair):
    from femgear.physics.ltca.analysis import normal_force

    return normal_force(baseline_pair, 200.0)
