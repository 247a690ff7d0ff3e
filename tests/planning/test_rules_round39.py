"""Round 39: general mechanisms found in probes 55-57 (written blind in the test half's own recipe), each tested on
other things and wording than where it was found."""

from tests.planning.scene_views import leaves, plan, view


def _cups():
    where = {"cup": (0.5, -0.2, 0.05), "saucer": (0.6, 0.2, 0.01), "tin": (0.4, 0.1, 0.05), "pole": (0.7, 0.0, 0.1)}
    return view(inventory=("cup", "saucer", "tin", "pole", "post"), post=(0.7, 0.3, 0.1), **where)


def test_steps_that_set_two_things_on_each_other_are_refused():
    """ "put X on Y and Y on X" cannot both hold: the second step would lift Y from under X (probe53's nonsense).
    Moved again in between, the first thing is no longer on the second."""
    scene = _cups()
    refused = plan("put the cup on the tin and the tin on the cup", scene)
    assert not refused.ok and "rests on it" in refused.error
    moved = plan("put the cup on the tin, then put the cup on the saucer and the tin on the cup", scene)
    assert moved.ok, moved.error
    assert leaves(moved)[-1] == ("place", "cup")


def test_a_post_or_peg_is_fixed_in_place():
    """ "put the round peg on top of the square peg": a nut assembly's pegs stand fixed in the table."""
    scene = _cups()
    refused = plan("put the post on the saucer", scene)
    assert not refused.ok and "fixed in place" in refused.error
    assert plan("put the cup on the post", scene).ok
