"""Ordinals and extremes counted over one kind, in the forms perception reads: counted from the top or the bottom of
a stack ("the second drawer from the top", "the third shelf down"), the rank first in a reordered phrase, "whichever
X is <extreme>", an extreme said first without a determiner, and the robot's own left and right.

(Examples are written for these tests; none comes from data/wording/.)"""

import pytest

from tests.planning.clause_tuples import clauses


@pytest.mark.parametrize(
    "text,expected",
    [
        ("open the second drawer from the top", [("open", "second top drawer", None, None)]),
        ("open the third drawer from the bottom", [("open", "third bottom drawer", None, None)]),
        ("close the second drawer down", [("close", "second top drawer", None, None)]),
        ("close the second drawer up", [("close", "second bottom drawer", None, None)]),
        ("open the last drawer from the top", [("open", "bottom drawer", None, None)]),
        # a possessive or "on the X" puts the owner first; the rank stays the phrase's first word
        ("open the dresser's second drawer from the top", [("open", "second top dresser drawer", None, None)]),
    ],
)
def test_counting_from_the_top_or_the_bottom(text, expected):
    assert clauses(text) == expected


@pytest.mark.parametrize(
    "text,expected",
    [
        ("lift whichever mug is nearest to you", [("pick", "nearest mug", None, None)]),
        (
            "whichever cup is farthest from the robot, move it onto the tray",
            [("mention", "farthest cup", None, None), ("put", "farthest cup", "on", "tray")],
        ),
        ("highest mug: onto the tray", [("put", "top mug", "on", "tray")]),
        ("leftmost cup into the tray", [("put", "leftmost cup", "in", "tray")]),
        ("the higher of the two mugs goes on the tray", [("put", "top mug", "on", "tray")]),
    ],
)
def test_extremes_without_the_usual_frame(text, expected):
    assert clauses(text) == expected


@pytest.mark.parametrize(
    "text,expected",
    [
        ("put the cup on your left onto the tray", [("put", "leftmost cup", "on", "tray")]),
        ("set the mug on the robot's right on the shelf", [("put", "rightmost mug", "on", "shelf")]),
    ],
)
def test_the_robots_own_left_and_right_are_the_sides_perception_counts_in(text, expected):
    assert clauses(text) == expected
