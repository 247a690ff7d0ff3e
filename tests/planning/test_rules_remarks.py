"""Words around a request that are no step of it: a remark before it ("hey", "when you get a minute", "somebody
left the oven open"), a sentence adverb ("preferably ..."), when the goal should hold ("... by the end", "...
when you are done"), a step that only takes the arm away or a don't ("... then go back", "... and do not drop
it"); and verbs outside the planner's own list that the English lexicon knows ("wedge it into the crate").

(Examples are written for these tests with made-up objects; none comes from data/wording/.)"""

import pytest

from tests.planning.clause_tuples import clauses


@pytest.mark.parametrize(
    "text,expected",
    [
        ("yo, could you put the teapot on the tray?", [("put", "teapot", "on", "tray")]),
        ("oh, when you have a minute, put the teapot on the tray", [("put", "teapot", "on", "tray")]),
        ("somebody left the oven open, shut it", [("mention", "oven", None, None), ("close", "oven", None, None)]),
        ("preferably the lemon ends up in the jar", [("put", "lemon", "in", "jar")]),
        ("the lemon should go in the jar at the end", [("put", "lemon", "in", "jar")]),
        ("the lemon should be in the jar once you are finished", [("put", "lemon", "in", "jar")]),
        ("put the lemon in the jar and then head back to the start", [("put", "lemon", "in", "jar")]),
        ("put the lemon in the jar and do not drop it", [("put", "lemon", "in", "jar")]),
        ("switch on the kettle and move your gripper out of the way", [("turn_on", "kettle", None, None)]),
    ],
)
def test_remarks_are_no_steps(text, expected):
    assert clauses(text) == expected


@pytest.mark.parametrize(
    "text,expected",
    [
        ("pick up the lemon and wedge it into the jar", [("pick", "lemon", None, None), ("put", "lemon", "in", "jar")]),
        (
            "lift the green mug and perch it on the purple one",
            [("pick", "green mug", None, None), ("put", "green mug", "on", "purple mug")],
        ),
        ("rotate the kettle's dial so it comes on", [("turn_on", "kettle dial", None, None)]),
    ],
)
def test_verbs_the_lexicon_knows(text, expected):
    assert clauses(text) == expected


def test_an_object_said_by_its_colour_alone_is_of_the_kind_named_before():
    got = clauses("take the green mug and put it in the crate; the purple one goes in the sink")
    assert got[-1] == ("put", "purple mug", "in", "sink")


def test_one_in_parallel_with_a_coloured_destination_is_of_its_kind():
    got = clauses("put the green mug in the orange crate and the purple mug in the white one")
    assert got == [("put", "green mug", "in", "orange crate"), ("put", "purple mug", "in", "white crate")]
