"""Round 34: general mechanisms found in the read probe45, each tested on other things and wording than where it
was found."""

import pytest

from tests.planning.scene_views import leaves, plan, view
from tests.planning.test_rules_round28 import read


@pytest.mark.parametrize(
    ("text", "clauses"),
    [
        # a look said after a thing picked out by where it is joins it, at the sentence's end too ("that's" is no
        # possessive)
        ("lift the mug that's nearer to you, the blue one.", ["pick obj=nearest blue mug"]),
        ("take the cup that is farther away, the green one", ["pick obj=farthest green cup"]),
        (
            "grab the bottle that's closer to you, the tall one, and put it in the crate",
            ["pick obj=nearest tall bottle", "put obj=nearest tall bottle relation=in target=crate"],
        ),
        # a side is no other thing the look could be of
        (
            "pick up the mug that's far away and off to the left, the white one.",
            ["pick obj=leftmost farthest white mug"],
        ),
        # a side said with an adverb of place, or after a relative; far away from the robot is the farthest
        ("take the cup that's off to the right", ["pick obj=rightmost cup"]),
        (
            "grab the bowl over on the left and put it on the tray",
            ["pick obj=leftmost bowl", "put obj=leftmost bowl relation=on target=tray"],
        ),
        ("put the lemon sitting off to the right in the basket", ["put obj=rightmost lemon relation=in target=basket"]),
        ("lift the jar that is far away", ["pick obj=farthest jar"]),
        ("pick up the spoon far away from you", ["pick obj=farthest spoon"]),
        # chat shorthand: a direction texted, a laugh
        (
            "push the blue cube fwd into the red zone",
            ["push obj=blue cube relation=in target=red zone direction=forward"],
        ),
        ("put the pear in the basket lol", ["put obj=pear relation=in target=basket"]),
        # letting go said as a last step of its own: the carry does it
        (
            "routine: 1) take the pear; 2) set it in the basket; 3) release.",
            ["pick obj=pear", "put obj=pear relation=in target=basket"],
        ),
        (
            "lift the mug and put it on the tray. then let go of it.",
            ["pick obj=mug", "put obj=mug relation=on target=tray"],
        ),
        # a list's header and closing status frame the steps; "step one:" after a header still starts a step
        (
            "task 7. step one: open the lowest drawer. step two: put the lemon in it. task complete.",
            ["open obj=bottom drawer", "put obj=lemon relation=in target=bottom drawer"],
        ),
        ("job #2: wipe the plate with the sponge. done.", ["scrub target=plate tool=sponge"]),
        # where the thing is, said alone between commas before its goal ("up", "over" before the place)
        (
            "of the two mugs, the taller one, over by the sink, goes on the tray",
            ["put obj=taller mug by sink relation=on target=tray"],
        ),
        (
            "the smaller cup, next to the kettle, goes on the saucer",
            ["put obj=smallest cup next to kettle relation=on target=saucer"],
        ),
        # a place word said again after the place
        ("put the jar on the shelf, up top", ["put obj=jar relation=on target=shelf"]),
        # a state with what it holds: the opening, then the carry into it
        (
            "when ur done the cabinet should be pulled out with the lemon sitting in it",
            ["open obj=cabinet", "put obj=lemon relation=in target=cabinet"],
        ),
        (
            "the top drawer needs to be open with the bowl inside it",
            ["open obj=top drawer", "put obj=bowl relation=in target=top drawer"],
        ),
        # how a thing stands, said of its state
        ("i need the oven door standing open", ["open obj=oven door"]),
        # "that one" after a thing said first only points back at it
        ("the jar on the shelf, that one goes in the basket", ["put obj=jar on shelf relation=in target=basket"]),
        # a thing said first without its article, then "the one <where>"
        ("cup on the left, the one by the kettle, onto the tray", ["put obj=leftmost cup relation=on target=tray"]),
        # "the <look> one" compared with the robot keeps its look
        (
            "stack the green cube onto the yellow one nearer to you",
            ["stack obj=green cube relation=on target=nearest yellow cube"],
        ),
        (
            "set the small plate on the white one farther from you",
            ["put obj=small plate relation=on target=farthest white plate"],
        ),
    ],
)
def test_wordings_of_round_34_read_as_meant(text, clauses):
    assert read(text) == clauses


def test_a_look_after_two_things_is_not_joined_to_the_first():
    # the look may be of the thing said last
    assert "put obj=red lid relation=on target=pot on stove" not in read(
        "put the lid on the pot on the stove, the red one"
    )


def test_a_bare_side_after_a_moved_thing_stays_where_it_goes():
    assert read("move the mug to the left") == ["put obj=mug relation=on target=left"]


def test_no_and_a_gerund_says_how_not_to_do_it():
    scene = view(mug=(0.5, 0.0, 0.0), tray=(0.4, 0.2, 0.0), unresolved={"no lifting": "none found"})
    result = plan("shove the mug over to the tray. no lifting, just slide it.", scene)
    assert result.ok, result.error
    assert leaves(result)[0] == ("push_object", "mug")
    assert "set aside as a remark" in result.detail["understood"][-1]


def test_a_list_label_before_a_colon_is_no_thing_to_find():
    scene = view(pear=(0.5, 0.0, 0.0), bowl=(0.4, 0.2, 0.0), unresolved={"procedure": "none found"})
    result = plan("procedure: 1) take the pear; 2) put it in the bowl; 3) release.", scene)
    assert result.ok, result.error
    assert leaves(result)[-1] in (("place_in", "bowl"), ("place", "bowl"))
