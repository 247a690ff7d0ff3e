"""Round 29: general mechanisms found in the read probe 36, each tested on other things and wording than where it
was found."""

import pytest

from spark_core.planning.rules.discourse import restructured
from spark_core.planning.rules.parse import parse_instruction
from spark_core.planning.rules.planner import _describe
from spark_core.planning.rules.remarks import trailing_remarks


def read(text: str) -> list[str]:
    """The rule parse of `text` after the discourse rewrites, one line per clause."""
    return [_describe(c) for c in parse_instruction(restructured(text))]


@pytest.mark.parametrize(
    ("text", "clauses"),
    [
        # a state brought about, said of a thing named by whose part it is
        (
            "get the fridge's door open and put the mug in it",
            ["open obj=fridge door", "put obj=mug relation=in target=fridge door"],
        ),
        ("have the cabinet's drawer shut", ["close obj=cabinet drawer"]),
        # a stack counted from the bottom up ("first" is a filler by the time the stack is read)
        (
            "make a pile: the yellow cube first, the red cube second and the blue cube third",
            ["stack obj=red cube relation=on target=yellow cube", "stack obj=blue cube relation=on target=red cube"],
        ),
        (
            "build a tower where the green cube is first (the base), the red cube is second, and the blue cube goes "
            "third",
            ["stack obj=red cube relation=on target=green cube", "stack obj=blue cube relation=on target=red cube"],
        ),
        (
            "a stack: red cube second, blue cube at the bottom, green cube third",
            ["stack obj=red cube relation=on target=blue cube", "stack obj=green cube relation=on target=red cube"],
        ),
        # an apposition between the thing and where it goes: the name stands for "the thing ...", a place joins it
        ("place the thing furthest from you, the pear, on the plate", ["put obj=pear relation=on target=plate"]),
        ("put the ketchup, the bottle nearest you, in the box", ["put obj=nearest ketchup relation=in target=box"]),
        # a cleft singles the thing out
        ("it's the mug that belongs on the tray", ["put obj=mug relation=on target=tray"]),
        (
            "leave the cup. it is the mug that should go on the tray",
            ["mention obj=cup", "put obj=mug relation=on target=tray"],
        ),
        # "further back" after the noun: the farthest
        ("of the two mugs, the one further back goes on the tray", ["put obj=farthest mug relation=on target=tray"]),
        # the other one said by where it is: that says which on its own
        (
            "not the mug on the shelf, the other one next to the kettle. put it on the tray",
            ["mention obj=mug next to kettle", "put obj=mug next to kettle relation=on target=tray"],
        ),
        (
            "not the mug on the shelf - the other one by the kettle goes on the tray",
            ["put obj=mug by kettle relation=on target=tray"],
        ),
    ],
)
def test_round29_wording_reads_as_its_plain_form(text, clauses):
    assert read(text) == clauses


def test_further_forward_is_not_read_as_either_end():
    # "forward" is away from the robot in a push and towards the speaker's front otherwise: no extreme is guessed
    assert "nearest" not in " ".join(read("put the black bowl further forward on the plate"))
    assert "farthest" not in " ".join(read("put the black bowl further forward on the plate"))


@pytest.mark.parametrize(
    ("text", "found", "kept"),
    [
        # the speaker's own doing after the request: a verb there is no step of the robot's
        ("close the drawer, i want to put stuff in it tomorrow", ["drawer"], "close the drawer"),
        # what the thing is wanted for: a dish, not a thing of the scene
        ("put the pear in the pot, we will need it for soup tonight", ["pear", "pot"], "put the pear in the pot"),
        ("put the pear in the pot, it's for the soup tonight", ["pear", "pot"], "put the pear in the pot"),
    ],
)
def test_a_remark_of_the_speakers_doing_or_purpose_is_set_aside(text, found, kept):
    assert kept in [k for k, _ in trailing_remarks(text, found)]


@pytest.mark.parametrize(
    ("text", "found"),
    [
        # "it's for the banana" with no time may ask for a banana: not set aside
        ("put the pear in the pot, it's for the banana", ["pear", "pot"]),
        # the speaker's doing that names a thing of the scene, or asks the robot: still part of the request
        ("open the drawer, we need to put the apple in it later", ["drawer", "apple"]),
        ("open the drawer, i need you to close it later", ["drawer"]),
    ],
)
def test_a_clause_that_may_ask_for_something_is_no_remark(text, found):
    assert trailing_remarks(text, found) == []
