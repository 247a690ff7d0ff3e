"""Which one of several of a kind, as the rules planner reads it: ordinals counted in a direction, comparisons and
extremes of position, sides, negation ruling one candidate out, "one" standing for the noun just named, and the
participles and particles that only say where a thing is.

(Examples here are written for these tests with made-up objects; none comes from data/wording/.)"""

import pytest

from spark_core.planning.rules import parse_instruction
from tests.planning.clause_tuples import clauses


@pytest.mark.parametrize(
    "text,expected",
    [
        # counting in a direction; "last" counts to the far end
        ("grab the second cup from the left", [("pick", "second leftmost cup", None, None)]),
        ("put the mug third from the right on the tray", [("put", "third rightmost mug", "on", "tray")]),
        ("the last cup on the right goes on the tray", [("put", "rightmost cup", "on", "tray")]),
        ("put the last cup from the left on the tray", [("put", "rightmost cup", "on", "tray")]),
        # comparisons and extremes of position
        ("lift the cup that is farther away from the robot", [("pick", "farthest cup", None, None)]),
        ("put the highest cup on the tray", [("put", "top cup", "on", "tray")]),
        ("put the lower of the two mugs on the tray", [("put", "lower mug", "on", "tray")]),
        ("move the farthest of the cups to the plate", [("put", "farthest cup", "on", "plate")]),
        ("put the rearmost mug on the tray", [("put", "farthest mug", "on", "tray")]),
        ("put the cup nearest the lamp on the tray", [("put", "cup near lamp", "on", "tray")]),
        # a side after the noun is no destination; before a noun it stays an adjective of that noun
        (
            "stack the cup on the right on top of the cup on the left",
            [("stack", "rightmost cup", "on", "leftmost cup")],
        ),
        ("put the left cup in the left tray", [("put", "left cup", "in", "left tray")]),
        # "one" stands for the noun just named
        ("put the farther cup onto the nearer one", [("put", "farthest cup", "on", "nearest cup")]),
        ("stack the non-red cup on the red one", [("stack", "cup not red", "on", "red cup")]),
    ],
)
def test_ordinals_extremes_and_sides(text, expected):
    assert clauses(text) == expected


@pytest.mark.parametrize(
    "text,expected",
    [
        ("pick up the other cup, not the red one", [("pick", "cup not red", None, None)]),
        ("lift whichever cup is not the red one", [("pick", "cup not red", None, None)]),
        ("put the cup that isn't on the left on the tray", [("put", "cup not leftmost", "on", "tray")]),
        ("put the cup other than the one further back on the tray", [("put", "cup not farthest", "on", "tray")]),
        ("any cup except the one near the lamp goes on the tray", [("put", "cup not near lamp", "on", "tray")]),
        (
            "the other cup, not the one between the lamp and the box, goes on the tray",
            [("put", "cup not between lamp and box", "on", "tray")],
        ),
        ("not the cup on the shelf, the other one goes on the tray", [("put", "cup not on shelf", "on", "tray")]),
        (
            "not the cup on the shelf, the other one: put it on the tray",
            [("mention", "cup not on shelf", None, None), ("put", "cup not on shelf", "on", "tray")],
        ),
        (
            "leave the cup on the shelf alone and put the other cup on the tray",
            [("put", "cup not on shelf", "on", "tray")],
        ),
        ("put the cup that's not up on the shelf on the tray", [("put", "cup not on shelf", "on", "tray")]),
    ],
)
def test_negation_rules_one_candidate_out(text, expected):
    assert clauses(text) == expected


@pytest.mark.parametrize(
    "text,expected",
    [
        ("put the cup stacked on the box on the tray", [("put", "cup on box", "on", "tray")]),
        ("pick up the cup up on the shelf", [("pick", "cup on shelf", None, None)]),
        ("move the mug in front of the lamp onto the tray", [("put", "mug near lamp", "on", "tray")]),
        ("would you be so kind as to drop the pen into the cup?", [("put", "pen", "in", "cup")]),
        ("turn the lamp on and let it warm up", [("turn_on", "lamp", None, None)]),
    ],
)
def test_where_a_thing_is_and_politeness(text, expected):
    assert clauses(text) == expected


def test_a_push_keeps_its_comparatives_for_the_way_to_move_and_its_sides_for_the_object():
    (push,) = parse_instruction("push the cup closer to you")
    assert (push.action, push.direction) == ("push", "backward")
    (push,) = parse_instruction("push the cup on the left forward")
    assert (push.obj, push.direction) == ("leftmost cup", "forward")


@pytest.mark.parametrize(
    "text,expected",
    [
        # a partitive with "pair of", and an extreme before "one"
        ("of the pair of mugs, put the nearer one on the tray", [("put", "nearest mug", "on", "tray")]),
        # an extreme said after the noun as a state ("sitting higher", "is highest up")
        ("of the two cups, the one sitting lower goes on the tray", [("put", "lower cup", "on", "tray")]),
        (
            "whichever mug is highest up, move it onto the tray",
            [("mention", "top mug", None, None), ("put", "top mug", "on", "tray")],
        ),
        # a cleft wish
        ("it's the lower mug I want on the tray", [("put", "lower mug", "on", "tray")]),
        # a kind ruled out by a kind of it
        ("put the jam that isn't strawberry jam in the crate", [("put", "jam not strawberry", "in", "crate")]),
        # the one ruled out, then the other after a dash or a semicolon
        ("not the mug by the kettle - the other one goes on the tray", [("put", "mug not by kettle", "on", "tray")]),
        ("skip the mug on the shelf; move the other one onto the tray", [("put", "mug not on shelf", "on", "tray")]),
        # an apposition that locates it, and an adverb before a relation
        ("put the jam - it's the one near the kettle - in the crate", [("put", "jam near kettle", "in", "crate")]),
        ("the cup right beside the kettle goes on the tray", [("put", "cup beside kettle", "on", "tray")]),
        # a place word between two things is the relation between them
        (
            "the cup that isn't in the gap between the tray and the kettle: put that one on the tray",
            [
                ("mention", "cup not between tray and kettle", None, None),
                ("put", "cup not between tray and kettle", "on", "tray"),
            ],
        ),
        # "onto it" with nothing before: the thing the object is located by
        ("of the two cups, put the one nearer the tray onto it", [("put", "cup near tray", "on", "tray")]),
    ],
)
def test_qualifiers_in_other_words(text, expected):
    assert clauses(text) == expected


def test_a_path_over_the_table_says_nothing_about_which_object():
    # "across the table" / "along the table": the way it goes, not where the object is
    assert clauses("shove the mug across the table into the green zone") == [("push", "mug", "in", "green zone")]
