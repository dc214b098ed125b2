"""Each FE body's default resolution (``numerics.body_level`` unset) and the key that overrides them all."""

import pytest

from femgear.scene.schema import DEFAULT_BODY_LEVELS, Numerics


def test_unset_level_gives_each_body_its_default():
    n = Numerics()
    assert n.body_level is None and n.body_elements == "p2-bending"
    assert [n.level_of(b) for b in ("ltca", "fe3d", "fe")] == [0, 1, 1]


def test_p1_ltca_bodies_keep_their_old_default_level():
    assert Numerics(body_elements="p1").level_of("ltca") == 1


@pytest.mark.parametrize("level", [0, 2])
def test_a_given_level_sets_every_body(level):
    n = Numerics(body_level=level)
    assert {n.level_of(b) for b in DEFAULT_BODY_LEVELS} == {level}


def test_unknown_body_is_an_error():
    with pytest.raises(KeyError):
        Numerics().level_of("wheel")
