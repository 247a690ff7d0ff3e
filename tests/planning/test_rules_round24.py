"""Round twenty-four of the rules planner (issue 18): wording found by the blind probe data/wording/probe25.yaml after
its blind figure was recorded.

- what is not meant, said after a complete request: "not the round one" (one of the kind the request named last),
  "not in any of the drawers", and the request said the other way round ("stack red on green, not green on red");
- a thing not to take, said before the request ("don't take the bowl on the shelf. ..."), and what the speaker does
  not want any more ("i don't want the lime cube on top anymore - ...");
- "the one on the stove" after a thing was named: one of that thing's kind;
- "the red one ... the green one": a colour is no noun for "one" to stand for;
- "there are two black bowls - put the closer one ...": which of them;
- a word that names anything ("the item closest to you") names each thing alike, for the qualifier to choose; a thing
  said that way and then named ("..., that's the milk") is the thing named;
- "the cube underneath the green cube": perception's "under" (no thing is related to itself); "the cube at the bottom
  of the stack";
- asides after a request: what the speaker will do ("so i can see what's inside", "before we put anything on it"),
  how not to do it ("don't leave any stains behind"); "wipe up the dirt";
- "pass the hammer from one gripper to the other" is a handover; "pot lifted off the table, held with both arms by
  its two handles" a two-arm lift.

Each test fails without the mechanism it names. (Examples are written for these tests; none comes from
data/wording/.)"""

import numpy as np
import pytest

from spark_core.perception.factory import make_resolver
from spark_core.planning.rules.discourse import restructured
from spark_core.planning.rules.mentions import stray_nouns
from spark_core.planning.rules.parse import parse_instruction
from spark_core.planning.rules.rewrite import imperatives
from spark_core.sim.tasks import SUITES


def _read(text):
    return [(c.action, c.obj, c.relation, c.target) for c in parse_instruction(restructured(text))]


def test_the_one_by_a_place_after_a_thing_was_named_is_of_that_kind():
    said = "don't take the mug from the shelf. take the one on the tray and put it in the sink"
    assert _read(said)[1:] == [("pick", "mug on tray", None, None), ("put", "mug on tray", "in", "sink")]


def test_a_colour_is_no_noun_for_one_to_stand_for():
    assert _read("put the pink one on the lime one") == [("put", "pink", "on", "lime")]


def test_there_are_two_says_which_kind_the_closer_one_is():
    assert _read("there are two teacups - put the closer one on the saucer") == [
        ("put", "closest teacup", "on", "saucer")
    ]


def test_a_thing_said_as_an_item_and_then_named_is_the_thing_named():
    assert _read("put the item nearest you in the crate, that's the lemon") == [("put", "lemon", "in", "crate")]
    assert _read("the item furthest left, the lemon - put it in the crate") == [
        ("mention", "lemon", None, None),
        ("put", "lemon", "in", "crate"),
    ]


@pytest.fixture(scope="module")
def object_scene():
    world = SUITES["liberopro"]["libero_object_swap:pick_up_the_milk_and_place_it_in_the_basket"].make_world(0)
    yield make_resolver(world, "sim", 0)
    world.close()


def test_a_word_that_names_anything_lets_the_qualifier_choose(object_scene):
    nearest = object_scene.resolve("nearest item")
    names = ("milk", "butter", "orange juice", "basket", "cream cheese", "tomato sauce", "chocolate pudding")
    # nearest to the robot's base (the world origin here, table plane): no thing of the scene is nearer
    reach = {n: float(np.linalg.norm(object_scene.resolve(n).position_m[:2])) for n in names}
    assert float(np.linalg.norm(nearest.position_m[:2])) <= min(reach.values()) + 0.01
    with pytest.raises(Exception, match="no single confident detection"):
        object_scene.resolve("item")  # anything at all, with nothing to choose: ambiguous


@pytest.mark.parametrize("segmenter", ["sim", "learned"])
def test_under_picks_the_other_thing_of_the_anchors_kind(segmenter):
    world = SUITES["capbench"]["CubeRestack"].make_world(0)
    try:
        resolver = make_resolver(world, segmenter, 0)
        under = resolver.resolve("cube under green cube")
        assert np.linalg.norm(under.position_m - resolver.resolve("red cube").position_m) < 0.02
    finally:
        world.close()


def test_underneath_and_the_bottom_of_the_stack_are_said_plainly():
    said = imperatives("put the cube that's underneath the green cube on top of the green cube")
    assert "under the green cube" in said[0]
    assert _read("take the cube at the bottom of the stack")[0] == ("pick", "bottom cube", None, None)


@pytest.mark.parametrize(
    "said, step",
    [
        ("open the drawer of the dresser so i can see whats inside", ("open", "dresser drawer", None, None)),
        ("wipe the counter before we put anything on it", ("scrub", None, None, None)),
        ("wipe up the mess on the counter, don't leave any stains behind", ("scrub", None, None, None)),
    ],
)
def test_asides_after_a_request_are_no_step_and_name_nothing(said, step):
    clauses = parse_instruction(restructured(said))
    assert [c.action for c in clauses] == [step[0]]
    if step[1]:
        assert clauses[0].obj == step[1]
    assert stray_nouns(said, clauses) == []


def test_from_one_gripper_to_the_other_is_a_handover():
    assert imperatives("pass the wrench from one gripper to the other") == imperatives(
        "pick up the wrench with one arm and hand it over to the other arm"
    )


def test_held_with_both_arms_by_its_handles_is_a_two_arm_lift():
    said = imperatives("kettle lifted off the table, held with both arms by its two handles")
    assert said == [f"pick up the {side} kettle handle with both arms" for side in ("left", "right")]


# From the dev half and the blind probe data/wording/probe26.yaml (after its blind figure was recorded).


def test_not_the_one_by_a_place_then_the_other_of_a_kind():
    said = "not the one on the shelf: the other teacup, onto the saucer"
    assert _read(said) == [("mention", "on shelf", None, None), ("put", "teacup not on shelf", "on", "saucer")]


def test_counted_from_the_top_of_the_thing_it_is_part_of():
    assert _read("open the second drawer from the top of the oak dresser") == [
        ("open", "second top oak dresser drawer", None, None)
    ]


@pytest.mark.parametrize(
    "said",
    [
        "lift the lime cube, just want to see if the grasp holds",
        "wipe the counter, we have a demo later.",
        "pour the beads from the teacup into the tureen, try not to spill any",
        "put the lemon in the crate; it's the yellow one",
    ],
)
def test_a_remark_after_the_request_names_nothing(said):
    clauses = parse_instruction(restructured(said))
    assert stray_nouns(said, clauses) == []
    assert all(c.obj is None or not {"want", "demo", "any", "yellow"} & set(c.obj.split()) for c in clauses)


def test_pushing_an_area_or_into_a_solid_thing_is_impossible():
    from tests.planning.scene_views import plan, view

    scene = view(green_area=(0.6, 0.1, 0.0), lime_block=(0.5, -0.1, 0.02))
    result = plan("push the green area into the lime block", scene)
    assert not result.ok and "a place on the table, not a thing to push" in result.error
    assert plan("push the lime block into the green area", scene).ok


def test_held_by_both_handles_with_both_arms_after_up_off_the_table():
    said = imperatives("kettle up off the table, held by both handles with both arms")
    assert said == [f"pick up the {side} kettle handle with both arms" for side in ("left", "right")]


# From the blind probe data/wording/probe27.yaml (after its blind figure was recorded).


def test_the_cleaning_goal_said_again_after_a_comma_is_no_step():
    said = "the counter should end up clean, with none of the brown dirt left on it."
    assert _read(said) == _read("the counter should end up clean") == [("scrub", None, None, "counter dirt")]


def test_a_state_negated_before_a_place_is_where_it_is_not():
    assert _read("put the teacup that isn't on the shelf on the saucer") == [
        ("put", "teacup not on shelf", "on", "saucer")
    ]


def test_pouring_into_a_product_is_impossible():
    from tests.planning.scene_views import plan, view

    scene = view(crate=(0.6, 0.1, 0.05), milk_carton=(0.5, -0.1, 0.07), teacup=(0.5, 0.2, 0.04))
    result = plan("pour the crate into the milk carton", scene)
    assert not result.ok and "a product in its package" in result.error


# A remark sentence after the request (rules/remarks.py), found on the blind probe data/wording/probe28.yaml.


@pytest.mark.parametrize(
    "said, kept, aside",
    [
        (
            "lift the lime cube. just want to see the grasp work, nothing else after that",
            "lift the lime cube.",
            ["just want to see the grasp work, nothing else after that"],
        ),
        (
            "put the lime cube on the tray. Don't just set it down next to the tray.",
            "put the lime cube on the tray.",
            ["Don't just set it down next to the tray."],
        ),
        (
            "take the teacup on the shelf. the other teacup can stay where it is",
            "take the teacup on the shelf.",
            ["the other teacup can stay where it is"],
        ),
        # the request said again as a wish is no remark, nor is a sentence before the request
        ("put the lemon in the crate. I want the lemon in the crate, not on the tray.", None, []),
        ("the lemon is not in the crate. put it there.", None, []),
    ],
)
def test_remarks_are_the_sentences_after_the_request_that_ask_nothing(said, kept, aside):
    from spark_core.planning.rules.remarks import remarks

    assert remarks(said) == (kept or said, aside)


def test_a_remark_naming_a_thing_the_scene_lacks_keeps_the_refusal():
    from spark_core.planning.rules.remarks import names_absent
    from tests.planning.scene_views import plan, view

    found = ["lime cube", "tray"]
    assert names_absent("don't touch the banana.", found) == "banana"
    assert names_absent("don't bump the laptop.", found) == "laptop"
    assert names_absent("just want to see the grasp work, nothing else", found) is None
    scene = view(lime_cube=(0.5, 0.1, 0.02), tray=(0.5, -0.1, 0.01))
    ok = plan("put the lime cube on the tray. just want to see the grasp work, nothing else after that", scene)
    assert ok.ok, ok.error
    assert "set aside as a remark" in ok.detail["understood"][-1]
    refused = plan("put the lime cube on the tray. just don't knock the banana over, nothing else after that", scene)
    assert not refused.ok


def test_turning_on_what_does_not_switch_is_impossible():
    from tests.planning.scene_views import plan, view

    scene = view(wine_rack=(0.6, 0.1, 0.1), hob=(0.5, -0.1, 0.01))
    scene.keypoints["wine rack knob"] = scene.keypoints["wine rack"]
    scene.keypoints["hob knob"] = scene.keypoints["hob"]
    result = plan("turn on the wine rack so it warms up", scene)
    assert not result.ok and "a rack is not something that switches on or off" in result.error
    assert plan("turn on the hob", scene).ok


def test_its_part_after_the_thing_was_named_is_that_things_part():
    said = "See the oak dresser in front of you? Its drawer is closed. Open it."
    assert _read(said)[-1] == ("open", "dresser drawer", None, None)


def test_a_courtesy_before_the_request_still_leaves_the_remark_after_it():
    from spark_core.planning.rules.remarks import remarks

    assert remarks("please turn on the hob. i do the rest myself") == (
        "please turn on the hob.",
        ["i do the rest myself"],
    )


@pytest.mark.parametrize(
    "said, read",
    [
        # what is not meant after a request is no step
        (
            "put the brass nut on the hex peg - not the round one!",
            [("mention", "round peg", None, None), ("put", "brass nut", "on", "hex peg")],
        ),
        (
            "put the mug on top of the shelf, not in any of the drawers",
            [("mention", "drawer", None, None), ("put", "mug", "on", "shelf")],
        ),
        (
            "stack the lime cube on the pink cube, not the pink cube on the lime cube.",
            [("stack", "lime cube", "on", "pink cube")],
        ),
        # a thing not to take or no longer wanted is named not moved
        (
            "don't take the mug on the shelf. put the other mug on the tray",
            [("mention", "mug on shelf", None, None), ("put", "mug not on shelf", "on", "tray")],
        ),
        (
            "i don't want the lime cube on top anymore - the pink cube goes on top of the lime cube",
            [("mention", "lime cube", None, None), ("put", "pink cube", "on", "lime cube")],
        ),
        # a thing and only where it goes is a carry
        ("lime cube next to the tray, straight onto the tray", [("put", "lime cube next to tray", "on", "tray")]),
        (
            "open the drawer, then lime cube in, that's it",
            [("open", "drawer", None, None), ("put", "lime cube", "in", "drawer")],
        ),
        (
            "top drawer open with the lemon inside",
            [("open", "top drawer", None, None), ("put", "lemon", "in", None)],
        ),
        # a state said as the others negation is that state
        ("make sure the hob isn't on", [("turn_off", "hob", None, None)]),
        ("make sure the drawer is not open", [("close", "drawer", None, None)]),
        (
            # (since round 28 "shouldn't be open" is read as the state "should be closed": one close, said twice)
            "the dresser drawer shouldn't be open, close it",
            [("close", "dresser drawer", None, None)],
        ),
        ("the hob is not on yet - switch it on", [("mention", "hob", None, None), ("turn_on", "hob", None, None)]),
        # what a speaker says around the request is no part of it
        ("lift the lime cube. that's it, nothing else for now", [("pick", "lime cube", None, None)]),
        ("scrub the tray with the rag ok that's all", [("scrub", None, None, "tray")]),
        ("put the lemon in the crate and then you can stop there", [("put", "lemon", "in", "crate")]),
        ("when you're done I want the lemon sitting in the crate.", [("put", "lemon", "in", "crate")]),
        (
            "of the two teacups, take the closer one, it's sitting on the tray, and put it on the saucer",
            [("pick", "closest teacup", None, None), ("put", "closest teacup", "on", "saucer")],
        ),
        (
            "i want the teacup that's currently on the tray to end up on the saucer",
            [("put", "teacup on tray", "on", "saucer")],
        ),
        # what a thing looks like said after it goes before its noun
        ("put the brass nut on the peg on the left, the hex one", [("put", "brass nut", "on", "leftmost hex peg")]),
        ("pick up the farther of the two cubes, the lime one", [("pick", "farthest lime cube", None, None)]),
        (
            "put the smaller of the two cubes (the lime one) on top of the bigger pink one.",
            [("put", "smallest lime cube", "on", "largest pink cube")],
        ),
        (
            "set the cup on the tray: not the one on the shelf, the other one",
            [("put", "cup not on shelf", "on", "tray")],
        ),
        # goals said with how or what not
        (
            "the lime cube should end up inside the green square, push it in there",
            [("push", "lime cube", "in", "green square")],
        ),
        (
            "grab the teacup in the drawer, not the one sitting on the shelf, and set it on the saucer",
            [("pick", "teacup in drawer", None, None), ("put", "teacup in drawer", "on", "saucer")],
        ),
        (
            "put the teacup next to the jug on the saucer, not the one further back.",
            [("put", "teacup next to jug", "on", "saucer")],
        ),
        (
            "put the tray on top of the dresser, not inside one of its drawers",
            [("mention", "drawer", None, None), ("put", "tray", "on", "dresser")],
        ),
        ("final configuration: lime cube stacked on the pink cube", [("stack", "lime cube", "on", "pink cube")]),
        (
            "build a tower with the blue cube at the bottom, green in the middle and red on top",
            [("stack", "green", "on", "blue cube"), ("stack", "red", "on", "green")],
        ),
        # links means purposes and headers said plainly
        (
            "pull the dresser drawer open, and once it's open put the lemon inside it.",
            [("open", "dresser drawer", None, None), ("put", "lemon", "in", "dresser drawer")],
        ),
        (
            "one of the teacups is sitting on the tray. take it and put it on the saucer.",
            [("mention", "teacup on tray", None, None), ("pick", "teacup on tray", None, None)]
            + [("put", "teacup on tray", "on", "saucer")],
        ),
        (
            "get the lime cube into the blue square marked on the table by pushing it forward.",
            [("push", "lime cube", "in", "blue square")],
        ),
        ("turn the hob's knob to switch the hob on.", [("turn_on", "hob knob", None, None)]),
        (
            "the item closest to you is the lemon. pick that one up and put it in the crate.",
            [("mention", "lemon", None, None), ("pick", "lemon", None, None), ("put", "lemon", "in", "crate")],
        ),
        ("final state i'm after: the jug sitting on the tray.", [("put", "jug", "on", "tray")]),
    ],
)
def test_wordings_of_the_round_read_as_meant(said, read):
    assert _read(said) == read
