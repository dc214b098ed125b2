"""Fixtures of the housing tests: a coarse FE housing around the baseline pair and the baseline's lumped model."""

import pytest

from femgear.case import build_case

#: a coarse housing for the quick tests: the default quadratic elements at 30 mm (the checks compare femgear's
#: reduction and couplings with the same discretisation), 24 fixed-interface modes
COARSE = {"size": 0.03, "order": 2, "modes": 24}


def housing_geometry(model, pair, size=COARSE["size"], **kw):
    from femgear.physics.mesh.housing import HousingGeometry

    return HousingGeometry(centre_distance=pair.a_w, tip_radius=(pair.ra1, pair.ra2), station_z=tuple(model.bearings.z),
                           bore_radius=(0.04, 0.04), bearing_width=(0.02, 0.02), size=size, **kw)


@pytest.fixture(scope="session")
def rigid_model(baseline_scene):
    """The baseline's lumped model without friction (the frequency-domain model leaves friction out)."""
    from femgear.system.dynamics import build_model

    return build_model(build_case(baseline_scene), "lumped", stiffness="contact-line", friction=0.0)


@pytest.fixture(scope="session")
def housing_mesh(rigid_model, baseline_pair):
    from femgear.physics.mesh.housing import housing_mesh as mesh

    return mesh(housing_geometry(rigid_model, baseline_pair))


@pytest.fixture(scope="session")
def structure(housing_mesh):
    from femgear.physics.housing.fe import HousingMaterial, housing_structure

    return housing_structure(housing_mesh, HousingMaterial(1.1e11, 0.26, 7200.0), COARSE["order"])


@pytest.fixture(scope="session")
def sensors(rigid_model, baseline_pair, housing_mesh):
    from femgear.levels.housing import default_sensors

    return default_sensors(housing_mesh.geometry)


@pytest.fixture(scope="session")
def reduced(structure, sensors):
    import numpy as np

    return structure.reduce(COARSE["modes"], np.array(sensors), np.array([(0.0, 1.0, 0.0)] * len(sensors)))
