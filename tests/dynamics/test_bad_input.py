"""Bad input is refused with a message naming the argument or scene key."""

import numpy as np
import pytest

from femgear.case import build_case
from femgear.errors import SceneError
from femgear.scene import load_scene


@pytest.mark.parametrize("override, key", [("pinion.mass=-1.0", "pinion.mass"), ("gear.mass=0.0", "gear.mass"),
                                           ("gear.support_stiffness=0.0", "gear.support_stiffness"),
                                           ("stiffness.mesh_stiffness_per_width=-1", "stiffness.mesh_stiffness_per_width")])
def test_non_positive_scene_values_refused(baseline_path, override, key):
    with pytest.raises(SceneError) as err:
        load_scene(baseline_path, [override])
    assert err.value.key == key


def test_non_positive_values_refused_by_the_assembly(baseline_scene):
    """Scenes built around the loader (model_copy) are checked again by build_model."""
    from femgear.system.dynamics import build_model

    bad = baseline_scene.model_copy(update={"pinion": baseline_scene.pinion.model_copy(update={"mass": -1.0})})
    with pytest.raises(SceneError, match="pinion.mass"):
        build_model(build_case(bad))
    bad = baseline_scene.model_copy(update={"gear": baseline_scene.gear.model_copy(update={"support_stiffness": 0.0})})
    with pytest.raises(SceneError, match="gear.support_stiffness"):
        build_model(build_case(bad))


def test_bad_mesh_stiffness_refused():
    from femgear.system.dynamics import StiffnessTable

    with pytest.raises(ValueError, match="positive"):
        StiffnessTable(np.array([1e8, -1.0]), np.array([1e8, 1e8]))


def test_step_above_the_rk4_stability_limit_refused(lumped):
    from femgear.system.dynamics import simulate, stability_limit

    limit = stability_limit(lumped)
    assert 1e-5 < limit < 1e-3
    with pytest.raises(ValueError, match="dt"):
        simulate(lumped, 1e-3, 1.2 * limit, "rk4")
    simulate(lumped, 20 * limit, 0.95 * limit, "rk4")        # just below: runs


def test_bad_integrator_arguments(lumped):
    from femgear.system.dynamics import simulate

    with pytest.raises(ValueError, match="method"):
        simulate(lumped, 1e-3, 1e-5, "euler")
    with pytest.raises(ValueError, match="dt"):
        simulate(lumped, 1e-3, -1e-5)
    with pytest.raises(ValueError, match="alpha"):
        simulate(lumped, 1e-3, 1e-5, "newmark", alpha=0.5)
