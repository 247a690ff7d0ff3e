"""Negation as a qualifier that removes candidates: a correction said first ("not the X, the Y"), another kind ruled
out in passing (still named, so it must be in the scene), an attribute ruled out by a relative clause, the one left
alone, and a clause's object corrected after it ("..., but not the one ...", "...: not the one ..., the other one").

(Examples are written for these tests; none comes from data/wording/.)"""

import pytest

from tests.planning.clause_tuples import clauses


@pytest.mark.parametrize(
    "text,expected",
    [
        # a correction said first: the phrase after it is the thing meant, its "one" of the kind ruled out
        (
            "not the green mug - the red one. move it onto the tray",
            [("mention", "red mug", None, None), ("put", "red mug", "on", "tray")],
        ),
        ("not the cup on the shelf; the cup by the sink, into the tray", [("put", "cup by sink", "in", "tray")]),
        (
            "not the one near the lamp, the mug next to the box: onto the tray",
            [("put", "mug next to box", "on", "tray")],
        ),
        # another kind ruled out is still named: a "there is" mention first, which must be found
        (
            "not the tray, the mug: put it on the shelf",
            [("mention", "tray", None, None), ("mention", "mug", None, None), ("put", "mug", "on", "shelf")],
        ),
        (
            "slide the mug, not the tray, to the front of the shelf",
            [("mention", "tray", None, None), ("push", "mug", "near", "shelf")],
        ),
    ],
)
def test_a_correction_names_the_thing_meant(text, expected):
    assert clauses(text) == expected


@pytest.mark.parametrize(
    "text,expected",
    [
        ("place the nut on the rod that isn't square", [("put", "nut", "on", "rod not square")]),
        ("put the cup which is not green on the tray", [("put", "cup not green", "on", "tray")]),
    ],
)
def test_an_attribute_ruled_out_by_a_relative_clause(text, expected):
    assert clauses(text) == expected


@pytest.mark.parametrize(
    "text,expected",
    [
        ("ignore the cup on the shelf; the other cup goes on the tray", [("put", "cup not on shelf", "on", "tray")]),
        ("leave the left mug alone and move the other mug onto the tray", [("put", "mug not leftmost", "on", "tray")]),
        (
            "leave the cup by the sink where it is, then put the other one in the tray",
            [("put", "cup not by sink", "in", "tray")],
        ),
    ],
)
def test_the_one_left_alone_is_ruled_out(text, expected):
    assert clauses(text) == expected


@pytest.mark.parametrize(
    "text,expected",
    [
        ("move the mug onto the tray, but not the one by the sink", [("put", "mug not by sink", "on", "tray")]),
        (
            "set the cup on the tray: not the one on the shelf, the other one",
            [("put", "cup not on shelf", "on", "tray")],
        ),
    ],
)
def test_a_clause_object_corrected_after_the_clause(text, expected):
    assert clauses(text) == expected
