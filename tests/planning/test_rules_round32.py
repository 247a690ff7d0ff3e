"""Round 32: general mechanisms found in the read probe41, each tested on other things and wording than where it
was found."""

import pytest

from tests.planning.scene_views import leaves, plan, view
from tests.planning.test_rules_round28 import read


@pytest.mark.parametrize(
    ("text", "clauses"),
    [
        # a tag asking for assent is no part of the request
        (
            "there is a mug by the sink, yeah? put it on the rack",
            ["mention obj=mug by sink", "put obj=mug by sink relation=on target=rack"],
        ),
        (
            "the red block, yep, drop it in the tray",
            ["mention obj=red block", "put obj=red block relation=in target=tray"],
        ),
        # "the X one of the two Ys" is the X Y, whatever follows it
        ("the left one of the two mugs goes on the saucer", ["put obj=left mug relation=on target=saucer"]),
        ("the nearest one of those three cups goes in the sink", ["put obj=nearest cup relation=in target=sink"]),
        (
            "the far one of the glass jars, put it in the bin",
            ["mention obj=farthest glass jar", "put obj=farthest glass jar relation=in target=bin"],
        ),
        # a thing made to go somewhere is put there
        ("make the apple go into the bowl", ["put obj=apple relation=in target=bowl"]),
        ("get the cube to end up on the plate", ["put obj=cube relation=on target=plate"]),
        ("have the lemon land in the basket", ["put obj=lemon relation=in target=basket"]),
        # a drawer slid or pulled out is opened
        ("slide out the bottom drawer", ["open obj=bottom drawer"]),
        (
            "pull out the middle drawer and put the spoon in it",
            ["open obj=middle drawer", "put obj=spoon relation=in target=middle drawer"],
        ),
        # an apposition saying where the subject of a goal is joins it
        ("the lemon, the one on your left, goes in the basket", ["put obj=leftmost lemon relation=in target=basket"]),
        (
            "the butter, the item nearest you, belongs in the basket",
            ["put obj=nearest butter relation=in target=basket"],
        ),
        (
            "the cup, the one next to the kettle, should go on the tray",
            ["put obj=cup next to kettle relation=on target=tray"],
        ),
        # a thing ruled out between the subject of a goal and its verb, with any words
        ("the mug, not the one by the sink, goes on the rack", ["put obj=mug not by sink relation=on target=rack"]),
        # ... and "not the X one" there says which of the subject's kind (not which place)
        ("the red cup, not the blue one, goes on the tray", ["put obj=red cup not blue relation=on target=tray"]),
        ("the apple, not the green one, belongs in the bowl", ["put obj=apple not green relation=in target=bowl"]),
        # a carry ruled out, then "<verb> it": "it" is the thing, not the place ruled out
        ("never put the mug in the sink; set it on the rack instead", ["put obj=mug relation=on target=rack"]),
        ("do not place the lemon on the plate, just drop it in the bowl", ["put obj=lemon relation=in target=bowl"]),
        # a tower wished as what one ends with
        ("finish with a tower, yellow at the bottom and red on top", ["stack obj=red relation=on target=yellow"]),
        ("end up with a stack: green at the bottom, red on top", ["stack obj=red relation=on target=green"]),
        # a contrast after a goal said without a verb
        ("the pear onto the plate, not the bowl", ["mention obj=bowl", "put obj=pear relation=on target=plate"]),
        # small balls a container holds are poured, as beads are
        ("tip the balls from the mug into the bowl", ["pour obj=balls target=bowl source=mug"]),
    ],
)
def test_round32_wording_reads_as_its_plain_form(text, clauses):
    assert read(text) == clauses


def test_a_thing_made_to_go_that_the_scene_lacks_is_refused():
    scene = view(bowl=[0.5, -0.1, 0.05], unresolved={"banana": "none found"}, inventory=("apple", "bowl"))
    result = plan("make the banana go into the bowl", scene)
    assert not result.ok and "banana" in result.error


def test_a_contrast_after_a_verbless_goal_plans_the_goal():
    scene = view(square_nut=[0.5, 0.1, 0.02], square_peg=[0.6, 0.2, 0.05], round_peg=[0.6, -0.2, 0.05])
    result = plan("square nut onto the square peg on the left, not the round one on the right", scene)
    assert result.ok, result.error
    assert leaves(result) == [("pick", "square nut"), ("place", "square peg")]


@pytest.mark.parametrize(
    ("text", "clauses"),
    [
        # a spec of keyed fields is the sentence it stands for
        ("obj: apple; dst: bowl", ["put obj=apple relation=in target=bowl"]),
        ("action: push; object: mug; to: green zone", ["push obj=mug relation=near target=green zone"]),
        ("src: lemon (on the left); dst: basket", ["put obj=leftmost lemon relation=in target=basket"]),
        ("item: butter; destination: inside the basket", ["put obj=butter relation=in target=basket"]),
        # a place said as "there", then again by name
        ("put the cup in there, on the tray i mean", ["put obj=cup relation=on target=tray"]),
        # a state said as not to be left
        ("make sure the lamp is not left on", ["turn off obj=lamp"]),
        # how the scene should look, said as a header
        ("final scene: apple inside the bowl", ["put obj=apple relation=in target=bowl"]),
        # a correction that is only a pause before the next step
        (
            "put the apple in the bowl and then, wait, after that the pear on the plate",
            ["put obj=apple relation=in target=bowl", "put obj=pear relation=on target=plate"],
        ),
        # chat address and closings; a verb of raising
        ("switch on the lamp real quick fam", ["turn on obj=lamp"]),
        ("kindly elevate the mug", ["pick obj=mug"]),
        # a relative clause saying which side a place is on
        (
            "put the mug on the shelf that sits close to you on the left",
            ["put obj=mug relation=on target=leftmost shelf"],
        ),
        # steps said to the robot as what "you" do; the tool said first ("with it ..."); "make X clean"; how it is
        # rubbed
        ("you take the cloth and you scrub the plate", ["pick obj=cloth", "scrub target=plate"]),
        (
            "grab the sponge, then with it you make the tray clean by scrubbing hard",
            ["pick obj=sponge", "scrub target=tray tool=sponge"],
        ),
        ("then you put the apple in the bowl", ["put obj=apple relation=in target=bowl"]),
        # ... but "with that sponge" names the tool
        ("mind scrubbing the tray with that sponge?", ["scrub target=tray tool=sponge"]),
        # the thing opened before, said by its state
        (
            "open the drawer and put the spoon into the opened drawer",
            ["open obj=drawer", "put obj=spoon relation=in target=drawer"],
        ),
    ],
)
def test_round32_probe42_wording_reads_as_its_plain_form(text, clauses):
    assert read(text) == clauses


def test_a_spec_naming_a_thing_the_scene_lacks_is_refused():
    scene = view(bowl=[0.5, -0.1, 0.05], unresolved={"banana": "none found"}, inventory=("apple", "bowl"))
    result = plan("obj: banana; dst: bowl", scene)
    assert not result.ok and "banana" in result.error


def test_a_text_with_a_colon_that_is_no_spec_is_left_alone():
    from spark_core.planning.rules.specs import spelled_out

    assert spelled_out("note: put the apple in the bowl") == "note: put the apple in the bowl"
    assert spelled_out("obj: apple") == "obj: apple"  # one field says no goal


def test_chat_spellings_and_colour_shorthand_are_read_as_words():
    from spark_core.planning.rules.spelling import corrected

    assert corrected("stack ylw on grn") == "stack yellow on green"
    assert corrected("move da cup onto the saucer") == "move the cup onto the saucer"


def test_a_flavour_the_scenes_thing_lacks_is_refused_as_another_product():
    from spark_core.planning.rules.kinds import other_variety

    inventory = ("milk", "chocolate pudding", "basket")
    assert other_variety("chocolate milk", inventory) == "chocolate"
    assert other_variety("milk carton", inventory) is None
    assert other_variety("chocolate pudding", inventory) is None


def test_a_narrower_kind_before_a_wider_word_names_the_thing():
    from spark_core.planning.rules.discourse import restructured

    assert restructured("take the bowl by the ramekin dish") == "take the bowl by the ramekin"
    assert restructured("take the bowl by the dinner dish") == "take the bowl by the dinner dish"


@pytest.mark.parametrize(
    ("text", "clauses"),
    [
        # a header with an arrow; a tower named without a verb
        ("goal -> apple inside the bowl", ["put obj=apple relation=in target=bowl"]),
        ("final tower, blue at the bottom, red on top", ["stack obj=red relation=on target=blue"]),
        # a word of address; a remark on time after the request; what the speakers are doing, before it
        (
            "look at the red mug, dear? put it on the saucer",
            ["mention obj=red mug", "put obj=red mug relation=on target=saucer"],
        ),
        ("put the pear in the bowl - we are running late", ["put obj=pear relation=in target=bowl"]),
        (
            "hi, we are testing the new gripper today. could you put the pear in the bowl?",
            ["put obj=pear relation=in target=bowl"],
        ),
        # "closer in", "farther out"; a comparison with "the other one"
        ("put the apple on the cube farther out", ["put obj=apple relation=on target=farthest cube"]),
        (
            "the bowl nearer the stove than the other one goes on the plate",
            ["put obj=bowl near stove relation=on target=plate"],
        ),
        # the side an ordinal counts from, said apart from it
        (
            "the third mug, counting from the left, goes on the tray",
            ["put obj=third leftmost mug relation=on target=tray"],
        ),
        (
            "counting out from the robot, the second cup goes in the sink",
            ["put obj=second nearest cup relation=in target=sink"],
        ),
        # what is not meant, said first
        (
            "instead of the plate, put the apple in the bowl",
            ["mention obj=plate", "put obj=apple relation=in target=bowl"],
        ),
        ("rather than the mug, the cup goes on the tray", ["mention obj=mug", "put obj=cup relation=on target=tray"]),
        # "that <kind>": the one of that kind named before
        (
            "open the top drawer and put the bowl in that drawer",
            ["open obj=top drawer", "put obj=bowl relation=in target=top drawer"],
        ),
        # a reason, then the request asked in a frame after "so"
        ("we need some heat, so would you mind switching the stove on?", ["turn on obj=stove"]),
        # "down" of setting a thing down; "the second drawer down"; "it" of a request after a contrast said first
        ("set the apple down inside the bowl", ["put obj=apple relation=in target=bowl"]),
        ("rather than turning the lamp on, turn it off", ["turn off obj=lamp"]),
        ("open the second drawer down on the wooden cabinet", ["open obj=second top wooden cabinet drawer"]),
        # a chat address at the end; praise said as a sentence; "fix the stack" after the goal just stated
        ("put the red block in the bowl yo", ["put obj=red block relation=in target=bowl"]),
        (
            "can you see the mug? good. now put it on the saucer",
            ["mention obj=mug", "put obj=mug relation=on target=saucer"],
        ),
        ("i want red on green, not green on red. fix the stack.", ["put obj=red relation=on target=green"]),
        # a thing that can stay right where it is
        (
            "the pear goes in the bowl; the apple can stay right where it is",
            ["put obj=pear relation=in target=bowl", "mention obj=apple"],
        ),
    ],
)
def test_round32_probe43_wording_reads_as_its_plain_form(text, clauses):
    assert read(text) == clauses


def test_robot_said_as_where_counting_starts_is_not_a_word_of_address():
    # "from the robot," keeps its "robot": only words of address between a comma and the sentence's end go
    assert read("take the second cup counting out from the robot, and put it in the sink") == [
        "pick obj=second nearest cup",
        "put obj=second nearest cup relation=in target=sink",
    ]
