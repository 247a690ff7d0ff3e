"""How the rules planner reads the structure of a clause: English verbs of moving a thing beyond the first few,
remarks and manner clauses after the action, a thing named first and acted on through a pronoun, a destination
said before the object, a destination located by a relative clause, the strongest destination preposition,
possessive pronouns and extremes after a possessive, and a correction that rules one thing out.

(Examples are written for these tests; none comes from data/wording/.)"""

import pytest

from spark_core.planning.rules import parse_instruction
from tests.planning.clause_tuples import clauses


@pytest.mark.parametrize(
    "text,expected",
    [
        # verbs of moving a thing somewhere
        ("shift the mug onto the tray", [("put", "mug", "on", "tray")]),
        ("stow the spoon in the drawer", [("put", "spoon", "in", "drawer")]),
        ("park the toy car on the mat", [("put", "toy car", "on", "mat")]),
        ("plonk the lemon into the jug", [("put", "lemon", "in", "jug")]),
        ("snatch the pen", [("pick", "pen", None, None)]),
        ("kill the burner", [("turn_off", "burner", None, None)]),
        # a particle before the destination adds nothing
        ("move the mug across onto the tray", [("put", "mug", "on", "tray")]),
    ],
)
def test_verbs_of_moving_and_particles(text, expected):
    assert clauses(text) == expected


@pytest.mark.parametrize(
    "text,expected",
    [
        ("put the mug on the tray, then you're done", [("put", "mug", "on", "tray")]),
        ("put the mug on the tray and that is all", [("put", "mug", "on", "tray")]),
        ("set the cup in the sink, making sure it stays upright", [("put", "cup", "in", "sink")]),
        ("lay the pen in the box without rolling it", [("put", "pen", "in", "box")]),
        ("place the cup on the saucer, taking care not to spill", [("put", "cup", "on", "saucer")]),
    ],
)
def test_remarks_and_manner_after_the_action_are_no_steps(text, expected):
    assert clauses(text) == expected


@pytest.mark.parametrize(
    "text,expected",
    [
        (
            "the mug standing by the kettle, move that one onto the tray",
            [("mention", "mug by kettle", None, None), ("put", "mug by kettle", "on", "tray")],
        ),
        (
            "the lemon? put it in the jug",
            [("mention", "lemon", None, None), ("put", "lemon", "in", "jug")],
        ),
        (
            "see the spoon? drop it in the cup",
            [("mention", "spoon", None, None), ("put", "spoon", "in", "cup")],
        ),
        # a short bare noun phrase, then a verbless carry onto it
        (
            "green mug, then blue mug on it",
            [("mention", "green mug", None, None), ("put", "blue mug", "on", "green mug")],
        ),
    ],
)
def test_a_thing_named_first_and_acted_on_through_a_pronoun(text, expected):
    assert clauses(text) == expected


@pytest.mark.parametrize(
    "text,expected",
    [
        # the destination before the object
        ("put on the tray the mug that is next to the kettle", [("put", "mug next to kettle", "on", "tray")]),
        ("place into the box whichever pen is not red", [("put", "pen not red", "in", "box")]),
        # a destination located by a relative clause: its preposition says where the destination is
        (
            "move the mug sitting on the shelf onto the tray that sits on the chair",
            [("put", "mug on shelf", "on", "tray on chair")],
        ),
        # "onto" / "into" can only say where a thing goes: a later "on" locates the destination
        ("put the cup onto the tray in the box", [("put", "cup", "on", "tray in box")]),
    ],
)
def test_where_the_destination_starts(text, expected):
    assert clauses(text) == expected


def test_a_possessive_pronoun_of_contents_is_the_thing_named_before():
    parsed = parse_instruction("pick up the jug and pour its water into the cup")
    assert [(c.action, c.source, c.target) for c in parsed] == [("pick", None, None), ("pour", "jug", "cup")]


def test_an_extreme_after_a_possessive_is_perceptions_word():
    assert clauses("open the dresser's lowest drawer") == [("open", "dresser bottom drawer", None, None)]


@pytest.mark.parametrize(
    "text,expected",
    [
        ("put the mug on the tray, not the one on the shelf", [("put", "mug not on shelf", "on", "tray")]),
        ("put the mug on the tray, not the mug by the lamp", [("put", "mug not by lamp", "on", "tray")]),
        ("put the mug on the tray, not the green one", [("put", "mug not green", "on", "tray")]),
        ("put the mug on the tray, not on the shelf", [("put", "mug", "on", "tray")]),  # the place said stands
    ],
)
def test_a_correction_after_the_clause_rules_one_out(text, expected):
    assert clauses(text) == expected


@pytest.mark.parametrize(
    "text,expected",
    [
        # a wish said as a cleft or as wanting to see it
        ("what I'd like is the spoon in the cup", [("put", "spoon", "in", "cup")]),
        ("I want to see the lemon in the jug", [("put", "lemon", "in", "jug")]),
        # no verb and no article: a preposition that only says where a thing goes makes it a carry
        ("spoon into the cup please", [("put", "spoon", "in", "cup")]),
        # what a holder should have, with how the thing sits on it
        ("the saucer should have the cup resting on it", [("put", "cup", "on", "saucer")]),
        # which way up it ends: said at the end, it is no place
        ("stand the vase on the shelf, right way up", [("put", "vase", "on", "shelf")]),
        # the one of the kind not named yet
        (
            "put the tin mug on the tray, then the remaining mug on the shelf",
            [("put", "tin mug", "on", "tray"), ("put", "mug not tin", "on", "shelf")],
        ),
    ],
)
def test_wishes_verbless_carries_and_the_remaining_one(text, expected):
    assert clauses(text) == expected


@pytest.mark.parametrize(
    "text,expected",
    [
        # the table is the lowest place: not on it is any but the lowest, on it (when said) the lowest
        ("move whichever mug isn't on the table onto the tray", [("put", "mug not bottom", "on", "tray")]),
        ("put the mug on the table into the box", [("put", "bottom mug", "in", "box")]),
        ("lift the mug off the table", [("pick", "mug", None, None)]),
        # a dash between two parts, a relative pronoun before a participle
        (
            "the mug which is standing on the shelf - put it on the tray",
            [("mention", "mug on shelf", None, None), ("put", "mug on shelf", "on", "tray")],
        ),
        # a manner clause with "leaving"
        ("put the mug on the tray, leaving the cup where it is", [("put", "mug", "on", "tray")]),
        # the kind said first stands for "the one"
        (
            "of the two mugs, take the one on the shelf and set it on the tray",
            [("pick", "mug on shelf", None, None), ("put", "mug on shelf", "on", "tray")],
        ),
    ],
)
def test_the_table_dashes_leaving_and_partitives(text, expected):
    assert clauses(text) == expected


@pytest.mark.parametrize(
    "text,expected",
    [
        # "is" before a participle goes with it, with or without the relative pronoun
        ("grab the mug that is sitting on the shelf", [("pick", "mug on shelf", None, None)]),
        ("lift the mug, which is resting on the shelf", [("pick", "mug on shelf", None, None)]),
        # a possessive of a thing that is no part or package of it says where it is
        ("pick up the shelf's mug", [("pick", "mug on shelf", None, None)]),
        ("open the dresser's top drawer", [("open", "dresser top drawer", None, None)]),
    ],
)
def test_participles_and_possessives_that_locate(text, expected):
    assert clauses(text) == expected
