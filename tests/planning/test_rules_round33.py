"""Round 33: general mechanisms found in the read probe44, each tested on other things and wording than where it
was found."""

import pytest

from spark_core.planning.rules.planner import _carried_once
from spark_core.planning.rules.spelling import corrected
from tests.planning.scene_views import leaves, plan, view
from tests.planning.test_rules_round28 import read


@pytest.mark.parametrize(
    ("text", "clauses"),
    [
        # "after which" begins a step, as "then" does; "you'll want to" is the request itself
        (
            "first you'll want to lift the mug, after which set it on the tray",
            ["pick obj=mug", "put obj=mug relation=on target=tray"],
        ),
        ("you'll want to put the lemon in the basket", ["put obj=lemon relation=in target=basket"]),
        # where the thing is, said alone between commas after it, joins it
        (
            "take the cup closest to you, next to the kettle, and put it on the tray",
            ["pick obj=nearest cup next to kettle", "put obj=nearest cup next to kettle relation=on target=tray"],
        ),
        # near the robot is the nearer one: the robot is no thing to be near
        (
            "grab the mug close to you and put it on the rack",
            ["pick obj=nearest mug", "put obj=nearest mug relation=on target=rack"],
        ),
        # a favour asked for, then a state brought about
        ("could you be a love and get the kettle going?", ["turn on obj=kettle"]),
        # the state a thing is to leave: the other one brought about
        ("make the lamp stop being on", ["turn off obj=lamp"]),
        ("make the stove stop being off", ["turn on obj=stove"]),
        # an ordinal said again at the end, of a thing already picked out, or picking it out
        ("open the lowest drawer of the dresser, the third one down", ["open obj=dresser bottom drawer"]),
        ("open the drawer of the dresser, the second one down", ["open obj=second top dresser drawer"]),
        # where the gripper takes hold is no thing of the scene's
        (
            "grasp the bottle by the neck and put it in the crate",
            ["pick obj=bottle", "put obj=bottle relation=in target=crate"],
        ),
        ("take the mug by its rim and set it on the tray", ["pick obj=mug", "put obj=mug relation=on target=tray"]),
        # a pose header, and a word that only says go
        ("target pose: lamp switched on. execute.", ["turn on obj=lamp"]),
        ("final position: mug on the saucer. proceed.", ["put obj=mug relation=on target=saucer"]),
        # the side of another thing stays a side (perception measures it), when the thing is carried elsewhere after
        (
            "grab the cup to the left of the kettle and put it on the tray",
            ["pick obj=cup left of kettle", "put obj=cup left of kettle relation=on target=tray"],
        ),
        (
            "take the mug to the right of the sink, then put it on the rack",
            ["pick obj=mug right of sink", "put obj=mug right of sink relation=on target=rack"],
        ),
        # a thing ruled out first, then "the one" meant; "the other one" keeps what rules it out
        (
            "not the mug by the sink; the one next to the kettle goes on the rack",
            ["put obj=mug next to kettle relation=on target=rack"],
        ),
        (
            "not the cup on the tray but the other one: put it in the sink",
            ["mention obj=cup not on tray", "put obj=cup not on tray relation=in target=sink"],
        ),
        # a push in the passive, the surface it moves on, and where it ends ("lies within")
        (
            "the tray is to be slid along the table until it rests in front of the lamp",
            ["push obj=tray relation=near target=lamp"],
        ),
        (
            "shove the red block forwards until it lies within the green zone",
            ["push obj=red block relation=in target=green zone direction=forward"],
        ),
        # the robot's own part raised with the thing in it lifts the thing
        ("grab the mug and raise the gripper", ["pick obj=mug", "pick obj=mug"]),
        ("grasp the lemon and lift the end-effector up", ["pick obj=lemon", "pick obj=lemon"]),
        # a container's belly is the container
        ("put the lemon in the crate's belly", ["put obj=lemon relation=in target=crate"]),
    ],
)
def test_round33_probe44_wording_reads_as_its_plain_form(text, clauses):
    assert read(text) == clauses


def test_a_letter_held_for_emphasis_is_read_as_the_word():
    assert corrected("put the pear in the crate pleeease", ("pear", "crate")) == "put the pear in the crate please"
    assert corrected("sooo put the pear in the baskettt", ("pear", "basket")) == "so put the pear in the basket"
    assert corrected("put the pear in the zzzz", ("pear", "crate")) == "put the pear in the zzzz"  # no word: as said


def test_a_carry_said_again_right_after_it_is_one_carry():
    pick = {"primitive": "pick", "params": {"keypoint_label": "lemon"}}
    place = {"primitive": "place_in", "params": {"container_label": "bowl"}}
    other = {"primitive": "place", "params": {"target_label": "plate"}}
    assert _carried_once([pick, place, pick, place]) == [pick, place]
    assert _carried_once([pick, place, pick, other]) == [pick, place, pick, other]  # moved on: two carries
    scene = view(lemon=(0.5, 0.0, 0.0), bowl=(0.4, 0.2, 0.0))
    result = plan("grab the lemon and drop it in the bowl; target pose is inside the bowl", scene)
    assert result.ok, result.error
    assert leaves(result) == [("pick", "lemon"), ("place_in", "bowl")]


def test_a_pose_said_of_a_thing_the_scene_lacks_is_refused():
    scene = view(lemon=(0.5, 0.0, 0.0), bowl=(0.4, 0.2, 0.0), unresolved={"crate": "none found"})
    result = plan("grab the lemon; target pose is inside the crate", scene)
    assert not result.ok and "crate" in result.error
