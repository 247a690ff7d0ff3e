"""A goal stated without a verb, as the rules planner reads it: the thing, then the place its relation word names
("in", "on", "inside", "on top of"), with or without an article and whatever goal verb stands between them; "Y
with X on it"; a colon between a thing and its place or state; a goal said of "it" ("it should be X on Y"); a
goal of a container's contents (a pour).

(Examples are written for these tests with made-up objects; none comes from data/wording/.)"""

import pytest

from spark_core.planning.rules import parse_instruction
from spark_core.planning.rules.parse import ParseError
from tests.planning.clause_tuples import clauses


@pytest.mark.parametrize(
    "text,expected",
    [
        # no verb, no article: the relation word between the two mentions gives the roles
        ("green mug inside the crate", [("put", "green mug", "in", "crate")]),
        ("teapot on the tray", [("put", "teapot", "on", "tray")]),
        (
            "orange cup in the sink, yellow cup in the bin",
            [("put", "orange cup", "in", "sink"), ("put", "yellow cup", "in", "bin")],
        ),
        # a goal verb between them, without an article
        ("blue jug winds up inside the crate", [("put", "blue jug", "in", "crate")]),
        ("lemon goes in the jar", [("put", "lemon", "in", "jar")]),
        ("kettle on", [("turn_on", "kettle", None, None)]),
        # "Y with X on it"
        ("the saucer with the teacup on it", [("put", "teacup", "on", "saucer")]),
        ("a crate with the lemon in it", [("put", "lemon", "in", "crate")]),
        # a colon: place said after, state said after, container said bare after
        ("tallest jug: onto the tray", [("put", "tallest jug", "on", "tray")]),
        ("oven: open", [("open", "oven", None, None)]),
        ("soup can: crate", [("put", "soup can", "in", "crate")]),
        # the thing, then only where it goes
        ("the teapot, onto the tray", [("put", "teapot", "on", "tray")]),
        # a goal said of "it"
        ("it should be yellow on top of purple", [("put", "yellow", "on", "purple")]),
        # a label for the goal said first, and "was" for where it was
        ("end state: the cup that was on the shelf is on the tray", [("put", "cup on shelf", "on", "tray")]),
        # a wish of two goals, a causative wish, a state word for a drawer pulled out
        (
            "I want purple in the sink and white in the bin",
            [("put", "purple", "in", "sink"), ("put", "white", "in", "bin")],
        ),
        ("could you have the mug sitting on the saucer?", [("put", "mug", "on", "saucer")]),
        ("I'd like the desk's drawer pulled out", [("open", "desk drawer", None, None)]),
        # items after a verb and a colon that state their own goal
        (
            "tidy up for me: the mug goes to the sink, the cup to the bin",
            [("put", "mug", "in", "sink"), ("put", "cup", "in", "bin")],
        ),
    ],
)
def test_goal_without_a_verb(text, expected):
    assert clauses(text) == expected


def test_contents_of_a_container_stated_as_a_goal_are_poured():
    (c,) = parse_instruction("all the water from the jug should end up in the pot")
    assert (c.action, c.source, c.target) == ("pour", "jug", "pot")


@pytest.mark.parametrize("text", ["fly to the moon", "someone sang a song", "green tea tastes nice"])
def test_no_thing_and_place_is_still_no_goal(text):
    # "to" without a verb says a direction; a clause of another verb is no noun phrase
    with pytest.raises(ParseError):
        parse_instruction(text)
