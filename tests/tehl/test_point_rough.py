"""The scene's stationary roughness in the thermal point EHL (the paper's model: a single
peak, its eq. 22, fixed at x0 in the contact): it enters the film of the thermal solve,
a feature that moves with its flank is refused with the key that asks for it."""

import pytest

from femgear.errors import SceneError
from femgear.physics.tehl.point import solve_tehl_point
from femgear.scene.schema import SurfaceRoughness

from ._case import E_RED, OIL, PROPS, TAU0

KW = dict(oil=OIL, E_red=E_RED, props=PROPS, tau0=TAU0, level=1)
ARGS = (100.0, 0.0123, 1.09, 0.3, 313.0)


def _peak(moving=False, x0=0.0):
    return SurfaceRoughness.model_validate(
        {"peak": {"amplitude": 0.1e-6, "wavelength": 100e-6, "x0": x0, "moving": moving}})


def test_stationary_peak_at_the_centre_is_flattened_and_raises_the_pressure():
    """A 0.1 um peak at the centre of the Hertzian zone (a ~ 200 um here, l_b = 0.5 a: three cells of grid level 1): the
    film over it keeps only part of the peak (elastic flattening: 0 < drop < A_b) and the
    pressure rises over it (Johnson's wavy-surface ripple)."""
    smooth = solve_tehl_point(*ARGS, **KW)
    rough = solve_tehl_point(*ARGS, roughness=_peak(), **KW)
    drop = smooth.hc - rough.hc
    assert 0.0 < drop < 0.1e-6
    assert rough.pmax > 1.02 * smooth.pmax
    assert rough.hc_isothermal == smooth.hc_isothermal  # the start is smooth


def test_smooth_roughness_table_changes_nothing():
    a = solve_tehl_point(*ARGS, **KW)
    b = solve_tehl_point(*ARGS, roughness=SurfaceRoughness(), **KW)
    assert a.hc == b.hc and a.mu == b.mu


def test_moving_peak_refused_naming_the_key():
    with pytest.raises(SceneError, match=r"roughness\.peak\.moving"):
        solve_tehl_point(*ARGS, roughness=_peak(moving=True), **KW)
