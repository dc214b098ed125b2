"""3-D member bodies: both helices, the groove, the stagger, the rim down to the bore (femgear.physics.mesh.segment)."""

import math

import numpy as np
import pytest


def _spec(pair, **kw):
    from femgear.physics.mesh.segment import default_spec

    return default_spec(pair, 1, 0, n_teeth=3, r_bore=0.02, **kw)


def _section(pair, spec, member=1):
    from femgear.physics.mesh.section import gear_section
    from femgear.physics.mesh.segment import groove_radius

    rf, ra = pair.rf1, pair.ra1
    return gear_section(pair, member, spec.h, n_teeth=spec.n_teeth, bore_radius=0.02, refine_at=(0.0, 0.5 * (rf + ra)),
                        refine_ratio=spec.h_tooth / spec.h, refine_radius=0.75 * (ra - rf),
                        split_radius=groove_radius(pair, member), grade=(spec.grade, 12 * spec.h_tooth, 3), ring=True)


def test_body_volume_regions_and_opposite_hands(pair, volume):
    """Volume = section area × 2b + the area under the groove floor × g; the named regions partition the
    boundary; the helices turn opposite ways; the loaded flanks of the two helices are mirror images."""
    from femgear.physics.mesh.segment import groove_radius, helix_frame, member_body

    g = 6e-3
    spec = _spec(pair, groove=g)
    body = member_body(pair, 1, spec)
    sec = _section(pair, spec)
    r_g = groove_radius(pair, 1)
    inner = math.pi * (r_g**2 - 0.02**2)
    assert volume(body) == pytest.approx(volume(sec) * 2 * pair.b + inner * g, rel=2e-3)
    names = {"flank", "fillet", "tip", "bore", "rim", "end0", "end1", "groove_wall", "groove_floor"}
    assert names <= set(body.boundaries)
    allb = np.concatenate([body.boundaries[n] for n in names])
    assert np.unique(allb).size == allb.size == body.boundary_facets().size
    floor = body.p[:, body.facets[:, body.boundaries["groove_floor"]].ravel()]
    assert np.allclose(np.hypot(floor[0], floor[1]), r_g, rtol=1e-9)
    assert np.all((floor[2] >= pair.b - 1e-12) & (floor[2] <= pair.b + g + 1e-12))
    fr = helix_frame(pair, 1, spec)
    assert fr.theta(np.array([pair.b]))[0] == pytest.approx(fr.theta(np.array([pair.b + g]))[0])
    assert fr.theta(np.array([0.0]))[0] == pytest.approx(fr.theta(np.array([2 * pair.b + g]))[0])
    left = body.p[:, np.unique(body.facets[:, body.boundaries["loaded_flank"]])]
    right = body.p[:, np.unique(body.facets[:, body.boundaries["loaded_flank_right"]])]
    assert left.shape == right.shape                       # nodes (the prisms' diagonals are not mirrored)
    mirrored = np.vstack([right[:2], 2 * pair.b + g - right[2]])
    key = np.lexsort(np.round(left, 9))
    key_m = np.lexsort(np.round(mirrored, 9))
    assert np.allclose(left[:, key], mirrored[:, key_m], atol=1e-9)


def test_stagger_turns_the_right_helix_and_needs_a_groove(pair):
    from femgear.physics.mesh.segment import default_spec, helix_frame, member_body

    for member, sign in ((1, -1), (2, 1)):
        spec = default_spec(pair, member, 0, n_teeth=3, groove=5e-3, stagger=0.25)
        fr = helix_frame(pair, member, spec)
        z = pair.z1 if member == 1 else pair.z2
        assert fr.stagger_angle == pytest.approx(sign * 0.25 * 2 * math.pi / z)
        assert fr.theta(np.array([2 * pair.b + 5e-3]))[0] == pytest.approx(fr.stagger_angle)
    with pytest.raises(ValueError, match="stagger"):
        member_body(pair, 1, _spec(pair, stagger=0.25))


def test_section_ring_is_graded_coarse_far_from_the_loaded_tooth(pair):
    spec = _spec(pair)
    sec = _section(pair, spec)
    assert set(sec.boundaries) == {"flank", "fillet", "tip", "bore", "rim", "split"}
    edges = sec.p[:, sec.facets]
    length = np.linalg.norm(edges[:, 0] - edges[:, 1], axis=0)
    mid = edges.mean(axis=1)
    near = np.hypot(mid[0], mid[1] - 0.5 * (pair.rf1 + pair.ra1)) < 0.5 * pair.m_n
    bottom = mid[1] < -0.5 * pair.rf1
    assert np.median(length[near]) < 1.3 * spec.h_tooth
    assert np.median(length[bottom]) > 4 * spec.h_tooth


def test_tips_turn_by_the_helix_angle_opposite_ways_on_the_two_helices(pair):
    """The tip of the middle tooth turns by hand · b tan β / r_ref across a helix (r_ref = z m_t / 2), back across
    the other one (replaces the test of the former gmsh twist-extruded helix halves)."""
    from femgear.physics.mesh.segment import HAND, member_body

    g = 4e-3
    for member in (1, 2):
        body = member_body(pair, member, _spec(pair, groove=g))
        tip = body.p[:, np.unique(body.facets[:, body.boundaries["tip"]])]
        angle = np.arctan2(tip[1], tip[0])
        z = pair.z1 if member == 1 else pair.z2
        twist = HAND[member] * math.tan(pair.beta) / (z * pair.m_t / 2)

        def at(z0):       # tooth 0's tip nodes: within half a pitch of where the helix puts its centre line
            turn = twist * min(z0, 2 * pair.b + g - z0)
            sel = (np.abs(angle - math.pi / 2 - turn) < math.pi / z) & np.isclose(tip[2], z0, atol=1e-9)
            assert sel.sum() >= 2
            return float(np.mean(angle[sel]))

        assert at(pair.b) - at(0.0) == pytest.approx(twist * pair.b, rel=1e-9)
        assert at(2 * pair.b + g) - at(pair.b + g) == pytest.approx(-twist * pair.b, rel=1e-9)
