"""The rules planner reads instructions the way people word them: goals stated as states or wishes, trailing
clauses and purposes, sources and destinations in one clause, objects located by others, comparatives,
possessives, containers named for their contents, pronouns across sentences; and it refuses clearly.

(Examples here are written for these tests; none comes from the frozen test half of data/wording/.)"""

import numpy as np
import pytest

from spark_core.grammar import plan_to_dict
from spark_core.perception import Keypoint
from spark_core.planning import PlanRequest, SceneView
from spark_core.planning.rules import ParseError, RulesPlanner, parse_instruction
from tests.planning.clause_tuples import clauses


@pytest.mark.parametrize(
    "text,expected",
    [
        # the goal as a state or a wish
        ("the apple belongs in the bowl", [("put", "apple", "in", "bowl")]),
        ("I'd like the cup on the saucer", [("put", "cup", "on", "saucer")]),
        ("the lamp should be switched on", [("turn_on", "lamp", None, None)]),
        ("the box should be open", [("open", "box", None, None)]),
        ("I want the mug lifted off the counter", [("pick", "mug", None, None)]),
        ("saucer: the cup", [("put", "cup", "on", "saucer")]),
        ("tray: both cups", [("put", "cups", "in", "tray")]),
        ("the cup should be stacked on the saucer", [("stack", "cup", "on", "saucer")]),
        # trailing clauses and purposes
        ("put the cup on the saucer and keep it upright", [("put", "cup", "on", "saucer")]),
        ("drop the pen in the cup so it is out of the way", [("put", "pen", "in", "cup")]),
        ("push the lamp so that it sits in front of the box", [("push", "lamp", "near", "box")]),
        # a source and a destination in one clause; objects located by what they rest on or stand beside
        ("move the mug from the shelf onto the tray", [("put", "mug on shelf", "on", "tray")]),
        ("carry the pen off the table and into the cup", [("put", "pen", "in", "cup")]),
        (
            "take the bowl sitting on the stove and put it on the plate",
            [("pick", "bowl on stove", None, None), ("put", "bowl on stove", "on", "plate")],
        ),
        # comparatives, possessives, other nouns
        ("put the closer of the two mugs on the tray", [("put", "closest mug", "on", "tray")]),
        ("open the shelf's upper drawer", [("open", "shelf upper drawer", None, None)]),
        ("put the cup on the saucer's centre", [("put", "cup", "on", "saucer")]),
        ("put a carton of milk in the basket", [("put", "milk carton", "in", "basket")]),
        ("put the mug on the left on the tray", [("put", "leftmost mug", "on", "tray")]),
        ("put the first mug from the right on the tray", [("put", "rightmost mug", "on", "tray")]),
        ("put the mug closest to the lamp on the tray", [("put", "mug near lamp", "on", "tray")]),
        ("pick up the mug farthest from the lamp", [("pick", "mug not near lamp", None, None)]),
        ("put the mug that isn't on the shelf on the tray", [("put", "mug not on shelf", "on", "tray")]),
        # an object picked out by an attribute it does not have
        ("pick up the mug that isn't red", [("pick", "mug not red", None, None)]),
        ("put the cup other than the green one on the saucer", [("put", "cup not green", "on", "saucer")]),
        # the goal as what a holder holds, or with any modal and verb of ending up
        ("the tray should contain the spoon", [("put", "spoon", "in", "tray")]),
        ("the saucer needs the cup on it", [("put", "cup", "on", "saucer")]),
        ("the box must hold both pens", [("put", "pens", "in", "box")]),
        ("the lamp ought to stand on the shelf", [("put", "lamp", "on", "shelf")]),
        ("the pen has to wind up in the cup", [("put", "pen", "in", "cup")]),
        (
            "the spoon should be in the drawer, so open it first",
            [("open", "drawer", None, None), ("put", "spoon", "in", "drawer")],
        ),
        # how to hold it is no object; a ring slid over a post is carried onto it
        ("lift the crate, gripping it by its handles", [("pick", "crate", None, None)]),
        ("pick up the kettle by its handle", [("pick", "kettle", None, None)]),
        ("slide the ring over the post", [("put", "ring", "on", "post")]),
        # other verbs and checks stated as goals
        ("push the drawer back in", [("close", "drawer", None, None)]),
        ("pull the drawer out", [("open", "drawer", None, None)]),
        ("slide open the drawer", [("open", "drawer", None, None)]),
        ("push in the drawer", [("close", "drawer", None, None)]),
        ("make sure the cup is on the saucer", [("put", "cup", "on", "saucer")]),
        ("the drawer is open", [("open", "drawer", None, None)]),
        ("I'd like the pen that is next to the cup placed in the box", [("put", "pen next to cup", "in", "box")]),
        ("pick up the cup and leave it on the tray", [("pick", "cup", None, None), ("put", "cup", "on", "tray")]),
        ("would it be possible to fire up the stove?", [("turn_on", "stove", None, None)]),
        # pronouns across sentences, several steps
        ("grab the cup. it goes on the saucer", [("pick", "cup", None, None), ("put", "cup", "on", "saucer")]),
        (
            "there's a pen by the lamp; put it in the cup",
            [("mention", "pen by lamp", None, None), ("put", "pen by lamp", "in", "cup")],
        ),
        (
            "first the pen into the cup, then the spoon into the bowl",
            [("put", "pen", "in", "cup"), ("put", "spoon", "in", "bowl")],
        ),
        (
            "the box should hold the pen, which you'll need to open first",
            [("open", "box", None, None), ("put", "pen", "in", "box")],
        ),
    ],
)
def test_wording(text, expected):
    if expected is None:
        with pytest.raises(ParseError):
            parse_instruction(text)
        return
    assert clauses(text) == expected


def test_a_destination_that_must_be_opened_first_comes_after_opening_it():
    assert clauses("the spoon should end up in the top drawer, which you'll need to open first") == [
        ("open", "top drawer", None, None),
        ("put", "spoon", "in", "top drawer"),
    ]


def test_a_pronoun_destination_is_the_last_other_thing_mentioned():
    got = clauses("pick up the bowl next to the plate and set it on top of it")
    assert got == [("pick", "bowl next to plate", None, None), ("put", "bowl next to plate", "on", "plate")]


def test_left_and_closer_pick_out_an_object_outside_a_push():
    assert clauses("put the left mug on the tray") == [("put", "left mug", "on", "tray")]
    (push,) = parse_instruction("push the mug 10 cm to the left")
    assert (push.direction, push.distance_m) == ("left", pytest.approx(0.10))


def test_the_action_as_a_noun_after_give_is_the_action():
    (c,) = parse_instruction("give the mug a wipe with the towel")
    assert (c.action, c.target, c.tool) == ("scrub", "mug", "towel")


@pytest.mark.parametrize(
    "text", ["sing a song", "the the the", "make the red block fly", "cup bowl the in put in", "give the mug a name"]
)
def test_nonsense_is_not_read_as_an_action(text):
    with pytest.raises(ParseError, match="no action I know"):
        parse_instruction(text)


def kp(label, xyz, size=(0.04, 0.04, 0.04)):
    return Keypoint(label, np.array(xyz, float), np.array(size, float))


def prims(result):
    return [(c["type"], c.get("params", {})) for c in plan_to_dict(result.plan)["tree"]["children"]]


def test_a_goal_in_a_flat_area_is_a_push():
    view = SceneView({"red block": kp("red block", (0.42, 0, 0.02)), "green area": kp("green area", (0.6, 0, 0))})
    res = RulesPlanner().plan(PlanRequest("the red block should end up in the green area", view))
    assert res.ok, res.error
    assert prims(res) == [
        ("push_object", {"keypoint_label": "red block", "direction": "forward", "distance": pytest.approx(0.18)})
    ]


def test_a_tool_already_in_hand_is_not_picked_again():
    view = SceneView({"sponge": kp("sponge", (0.4, 0.1, 0.02)), "plate": kp("plate", (0.5, -0.1, 0.01))})
    res = RulesPlanner().plan(PlanRequest("pick up the sponge and use it to clean the plate", view))
    assert [p for p, _ in prims(res)] == ["pick", "constrained_scrub", "move_relative", "release"]


def test_a_handle_far_from_the_thing_to_open_is_refused():
    view = SceneView({"red block": kp("red block", (0.4, 0, 0.02)), "red block handle": kp("h", (0.7, 0.3, 0.1))})
    res = RulesPlanner().plan(PlanRequest("open the red block", view))
    assert not res.ok and "is not on it" in res.error


def test_a_handle_that_is_the_object_itself_is_refused():
    block = kp("red block", (0.4, 0, 0.02))
    view = SceneView({"red block": block, "red block handle": kp("red block handle", (0.4, 0, 0.02))})
    res = RulesPlanner().plan(PlanRequest("open the red block", view))
    assert not res.ok and "no handle on it, only 'red block' itself" in res.error


def test_an_object_perception_did_not_find_is_refused_saying_what_was_understood_and_seen():
    view = SceneView({"plate": kp("plate", (0.6, 0, 0.01))}, unresolved={"bowl": "none found"})
    res = RulesPlanner().plan(PlanRequest("put the bowl on the plate", view))
    assert not res.ok
    assert "could not find 'bowl'" in res.error and "found in the scene: plate" in res.error
    assert "understood: put obj=bowl" in res.error and "which" not in res.error


def test_an_object_several_things_match_is_refused_asking_which():
    view = SceneView({"plate": kp("plate", (0.6, 0, 0.01))}, unresolved={"bowl": "several match: 2"})
    res = RulesPlanner().plan(PlanRequest("put the bowl on the plate", view))
    assert not res.ok
    assert res.error.startswith("which 'bowl'? perception found 2 things that match it")
    assert "'the left bowl'" in res.error and "understood: put obj=bowl" in res.error
    assert "found in the scene: plate" in res.error


def test_mentioning_objects_without_an_action_is_refused():
    with pytest.raises(ParseError, match="but no action"):
        parse_instruction("there is a cup on the table")


def test_an_object_located_by_something_perception_could_not_use_says_so():
    view = SceneView({"plate": kp("plate", (0.6, 0, 0.01))}, unresolved={"bowl next to toaster": "several match: 2"})
    res = RulesPlanner().plan(PlanRequest("put the bowl next to the toaster on the plate", view))
    assert not res.ok and res.error.startswith("could not single out 'bowl next to toaster'")
    assert "2 things that match 'bowl'" in res.error and "which one is next to 'toaster'" in res.error


def test_a_push_into_an_area_perception_did_not_find_says_what_was_understood_and_seen():
    view = SceneView({"red block": kp("red block", (0.4, 0, 0.02))}, unresolved={"blue area": "none found"})
    res = RulesPlanner().plan(PlanRequest("push the red block into the blue area", view))
    assert not res.ok and "could not find 'blue area'" in res.error
    assert "understood: push obj=red block" in res.error and "found in the scene: red block" in res.error


def test_a_lift_with_both_arms_by_the_handles_grips_one_handle_per_arm_at_once():
    text = "raise the crate with both hands, gripping it by its two handles"
    assert [(c.action, c.obj, c.together) for c in parse_instruction(text)] == [
        ("pick", "left crate handle", True),
        ("pick", "right crate handle", True),
    ]
    view = SceneView(
        {
            "left crate handle": kp("left crate handle", (0.5, 0.3, 0.1)),
            "right crate handle": kp("right crate handle", (0.5, -0.3, 0.1)),
        }
    )
    res = RulesPlanner().plan(PlanRequest(text, view, arms={"left": (0.0, 0.5), "right": (0.0, -0.5)}))
    assert res.ok, res.error
    grip, lift = plan_to_dict(res.plan)["tree"]["children"]
    assert grip["type"] == lift["type"] == "parallel"
    arms = {c["params"]["arm"]: c["params"]["keypoint_label"] for c in grip["children"]}
    assert arms == {"left": "left crate handle", "right": "right crate handle"}  # each arm the nearer handle
    assert sorted(c["params"]["arm"] for c in lift["children"]) == ["left", "right"]
    one_arm = RulesPlanner().plan(PlanRequest(text, view, arms={"right": (0.0, -0.5)}))
    assert not one_arm.ok and "needs two arms" in one_arm.error
    # without handles named, a two-handed lift stays one pick of the thing
    assert [c.together for c in parse_instruction("lift the crate with both hands")] == [False]


def test_one_arm_picks_and_hands_over_to_the_other_by_the_handle_when_there_is_one():
    from spark_core.planning.observe import phrases_for

    text = "grab the spatula with one hand and pass it over to the other hand"
    assert [(c.action, c.obj, c.arm, c.to_arm) for c in parse_instruction(text)] == [
        ("pick", "spatula", "one", "other")
    ]
    assert "spatula handle" in phrases_for(text)  # perception is asked for the grip
    arms = {"left": (0.0, 0.5), "right": (0.0, -0.5)}
    view = SceneView(
        {"spatula": kp("spatula", (0.5, -0.2, 0.02)), "spatula handle": kp("spatula handle", (0.5, -0.3, 0.02))}
    )
    res = RulesPlanner().plan(PlanRequest(text, view, arms=arms))
    assert res.ok, res.error
    (node,) = plan_to_dict(res.plan)["tree"]["children"]
    assert node["type"] == "handoff"  # the nearer arm (right) gives, by the handle
    assert node["params"] == {"keypoint_label": "spatula handle", "from_arm": "right", "to_arm": "left"}
    named = RulesPlanner().plan(
        PlanRequest(
            "pick up the bar with the left arm and hand it to the right arm",
            SceneView({"bar": kp("bar", (0.5, -0.2, 0.02))}),
            arms=arms,
        )
    )
    assert named.ok and plan_to_dict(named.plan)["tree"]["children"][0]["params"] == {
        "keypoint_label": "bar",
        "from_arm": "left",
        "to_arm": "right",
    }
    one_arm = RulesPlanner().plan(PlanRequest(text, view, arms={"right": (0.0, -0.5)}))
    assert not one_arm.ok and "needs two arms" in one_arm.error
    same = RulesPlanner().plan(
        PlanRequest(
            "pick up the bar with the left arm and hand it to the left arm",
            SceneView({"bar": kp("bar", (0.5, -0.2, 0.02))}),
            arms=arms,
        )
    )
    assert not same.ok and "to itself" in same.error


@pytest.mark.parametrize(
    "text,expected",
    [
        ("put the spoon and the pen in the cup", [("put", "spoon", "in", "cup"), ("put", "pen", "in", "cup")]),
        (
            "stack the mug and the cup on the saucer",
            [("stack", "mug", "on", "saucer"), ("stack", "cup", "on", "saucer")],
        ),
        # each object has its own destination: nothing is shared
        (
            "put the spoon in the cup and the pen in the box",
            [("put", "spoon", "in", "cup"), ("put", "pen", "in", "box")],
        ),
    ],
)
def test_coordinated_objects_share_the_destination_named_last(text, expected):
    assert clauses(text) == expected


@pytest.mark.parametrize(
    "text,expected",
    [
        # "from" before a place preposition only marks the source: where the object is stays a relation
        (
            "take the pen from inside the box and put it in the cup",
            [("pick", "pen inside box", None, None), ("put", "pen inside box", "in", "cup")],
        ),
        ("move the mug from under the shelf onto the tray", [("put", "mug under shelf", "on", "tray")]),
        # an "X of Y" anchor reads as a noun phrase, head last, like any other ("the second tier of the rack")
        ("pick up the cup on the upper tier of the rack", [("pick", "cup on rack upper tier", None, None)]),
        ("pick up the cup on top of the rack", [("pick", "cup on top of rack", None, None)]),
        # a relative clause with an adjective, on a destination too
        ("put the ring on the post that is round", [("put", "ring", "on", "round post")]),
        ("put the ring which is small on the post", [("put", "small ring", "on", "post")]),
        # "slide X over to Y" moves it along the table to Y; "slide X over Y" sets it on Y
        ("slide the box over to the front of the lamp", [("push", "box", "near", "lamp")]),
        ("slide the ring over the post", [("put", "ring", "on", "post")]),
    ],
)
def test_sources_anchors_and_relative_clauses(text, expected):
    assert clauses(text) == expected
