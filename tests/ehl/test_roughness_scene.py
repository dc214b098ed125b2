"""The scene's [roughness] keys reach the EHL film along the gear path (studies/ehl/roughness_scene.py)."""

from __future__ import annotations

import pytest


@pytest.mark.slow
def test_scene_peak_along_the_path():
    """Stationary peak (the paper's model) at the contact centre: flattened, so h_min moves by
    < 2 % while p_max rises by > 10 % at every position; the same peak carried through the
    contact in rolling thins the pitch-point film by > 5 %."""
    from studies.ehl import roughness_scene

    res = roughness_scene.run(positions=3)
    for r in res["rows"]:
        assert abs(r["hmin_peak"] / r["hmin"] - 1) < 0.02
        assert r["pmax_peak"] > 1.10 * r["pmax"]
    pitch = min(res["rows"], key=lambda r: abs(r["s_mm"]))
    assert res["pitch"]["hmin_moving_peak"] < 0.95 * pitch["hmin"]
