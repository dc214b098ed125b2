"""The coupling loop with the face-resolved LTCA wear (``wear.field = "face"``) on the crowned baseline."""

import numpy as np
import pytest

from tests.conftest import BASELINE

COARSE = ["numerics.path_points=31", "numerics.dynamics_cycles=20", "numerics.transient_cycles=10",
          'physics.stiffness="ltca"', "modifications.crowning=5e-6", "wear.cycles=1e6"]


@pytest.mark.slow
def test_the_coupling_loop_carries_a_face_resolved_wear_field():
    """One dynamic pass each, path and face (≈ 2 min): the path wear of the state is the face mean of its face field over both
    helices; with 5 µm crowning the middle of the face wears more than its ends (the face-uniform model
    cannot); the LTCA re-run on the face field reaches the dynamics (loaded TE of the worn flanks differs
    from the face-uniform run's); ``wear_anchor = "pass"`` is refused with the face field."""
    from dataclasses import replace

    from femgear.case import build_case
    from femgear.scene import load_scene
    from femgear.system.coupling import CouplingSetup, run_coupled

    runs = {}
    for field in ("path", "face"):
        setup = CouplingSetup.from_case(build_case(load_scene(BASELINE, COARSE + [f'wear.field="{field}"'])),
                                        n_phase=64)
        runs[field] = (setup, run_coupled(setup, one_way=True).state)
    setup, state = runs["face"]
    assert runs["path"][1].wear_face is None and runs["path"][0].face is None
    z = setup.face.grid
    mean = np.trapezoid(state.wear_face, z, axis=-1).mean(axis=1) / z[-1]
    assert np.allclose(state.wear, mean, rtol=1e-12, atol=0)
    f = state.wear_face[0]                                    # pinion, (helix, u, ζ)
    inner = slice(f.shape[1] // 4, 3 * f.shape[1] // 4)
    mid = z.size // 2
    assert np.mean(f[:, inner, mid]) > 1.2 * np.mean(f[:, inner][:, :, [0, -1]])
    assert state.lte_peak_to_peak != runs["path"][1].lte_peak_to_peak
    assert np.isfinite(state.lte_peak_to_peak)
    with pytest.raises(ValueError, match="wear_anchor"):
        replace(setup, wear_anchor="pass")
