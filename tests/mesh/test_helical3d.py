"""3-D helical segments: volume, named boundaries, twist of the helix, double-helical halves."""

import math

import numpy as np
import pytest

from femgear.mesh.section import double_helical_member, gear_section, helical_segment


def _tip_angle(mesh, zsel):
    f = mesh.boundaries["tip"]
    c = mesh.p[:, mesh.facets[:, f]].mean(axis=1)
    keep = zsel(c[2])
    return float(np.mean(np.arctan2(c[1, keep], c[0, keep])))


def test_segment_volume_boundaries_and_twist(pair, volume):
    h = 1.6e-3
    m3 = helical_segment(pair, 1, h, n_teeth=1, layers=8)
    m2 = gear_section(pair, 1, h, n_teeth=1)
    assert volume(m3) == pytest.approx(volume(m2) * pair.b, rel=1e-2)
    assert set(m3.boundaries) == {"flank", "fillet", "tip", "bore", "sides", "end0", "end1"}
    allb = np.concatenate(list(m3.boundaries.values()))
    assert np.unique(allb).size == allb.size == m3.boundary_facets().size
    twist = _tip_angle(m3, lambda z: z > pair.b - 1e-3) - _tip_angle(m3, lambda z: z < 1e-3)
    expected = (pair.b - 1.5e-3) * math.tan(pair.beta) / (pair.z1 * pair.m_t / 2)   # centroids ~0.75 mm from ends
    assert twist == pytest.approx(expected, rel=0.15)


def test_double_helical_halves_opposite_hand(pair):
    left, right = double_helical_member(pair, 2, 1.6e-3, groove=5e-3, layers=8)
    assert left.p[2].min() == pytest.approx(0) and left.p[2].max() == pytest.approx(pair.b)
    assert right.p[2].min() == pytest.approx(pair.b + 5e-3)
    tl = _tip_angle(left, lambda z: z > pair.b - 1e-3) - _tip_angle(left, lambda z: z < 1e-3)
    tr = _tip_angle(right, lambda z: z > 2 * pair.b + 5e-3 - 1e-3) - _tip_angle(right, lambda z: z < pair.b + 5e-3 + 1e-3)
    assert tl > 0 > tr and tl == pytest.approx(-tr, rel=0.1)   # facet-centroid sampling
    with pytest.raises(ValueError, match="hand"):
        helical_segment(pair, 1, 2e-3, hand=2)
