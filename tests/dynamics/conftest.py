"""Fixtures of the dynamics tests: baseline models at both levels."""

import pytest

from femgear.case import build_case


@pytest.fixture(scope="module")
def lumped(baseline_scene):
    from femgear.system.dynamics import build_model

    return build_model(build_case(baseline_scene), "lumped", stiffness="contact-line")


@pytest.fixture(scope="module")
def timoshenko(baseline_scene):
    from femgear.system.dynamics import build_model

    return build_model(build_case(baseline_scene), "timoshenko", stiffness="contact-line")
