"""Dev round eight (issue 18): remarks after the request, requests said without their subject or as a chance asked
for, an obligation put on the listener, arrows both ways, the order of opening and filling, gripping a part as the
way an action is done, "that" pointing back, a thing said first and picked out after, corrections before a request,
and a redundant ruling-out. Each rule is general English, not a corpus string.

(Examples are written for these tests; none comes from data/wording/.)"""

import numpy as np
import pytest

from spark_core.perception import Keypoint
from spark_core.planning import PlanRequest, SceneView
from spark_core.planning.rules import RulesPlanner
from tests.planning.clause_tuples import clauses

MUG_ON_TRAY = [("put", "mug", "on", "tray")]


@pytest.mark.parametrize(
    "text",
    [
        "put the mug on the tray and leave the rest where they are",
        "put the mug on the tray and then leave the tray where it is",
        "put the mug on the tray when you get a chance",
        "when you get a chance, put the mug on the tray",
        "put the mug on the tray, nice and slow",
        "put the mug on the tray in one go",
        "put the mug on the tray, I will wash it later",
        "put the mug on the tray, try to get it near the middle of the tray",
        "mug on the tray. that's it",
        "want the mug sitting on the tray",  # a wish without its subject
        "any chance you could put the mug on the tray?",
        "can I get the mug on the tray please",
        "only the mug needs to end up on the tray",
        "end goal: the mug on the tray",
        "mug -> onto the tray",  # a preposition after the arrow
        "pick-and-place the mug onto the tray",
    ],
)
def test_remarks_and_request_forms_around_one_carry(text):
    assert clauses(text) == MUG_ON_TRAY


def test_whose_point_of_view_is_no_thing_to_look_for():
    from spark_core.planning.observe import phrases_for

    text = "from the robot's point of view, the left mug goes on the tray"
    assert clauses(text) == [("put", "left mug", "on", "tray")]
    assert phrases_for(text) == ["left mug", "tray"]


def test_an_arrow_pointing_back():
    assert clauses("shelf <- mug") == [("put", "mug", "on", "shelf")]
    assert clauses("box <- the red cup") == [("put", "red cup", "in", "box")]


def test_leaving_it_running_and_getting_it_clean_are_no_steps():
    assert clauses("switch the kettle on and just leave it running") == [("turn_on", "kettle", None, None)]
    assert clauses("scrub the pan with the sponge, get it properly clean") == [("scrub", None, None, "pan")]


def test_twisting_a_knob_to_on_turns_it_on():
    assert clauses("twist the kettle's dial to the on position") == [("turn_on", "kettle dial", None, None)]


def test_an_open_said_after_the_carry_into_it_comes_first():
    expected = [("open", "drawer", None, None), ("put", "spoon", "in", "drawer")]
    assert clauses("the spoon goes in the drawer - you'll have to open it first") == expected
    assert clauses("stow the spoon in the drawer, you will need to open the drawer first") == expected


def test_gripping_a_part_is_how_the_action_after_it_is_done():
    assert clauses("grab the cupboard handle and pull the cupboard open") == [("open", "cupboard", None, None)]
    assert clauses("the cupboard's drawer, open it up") == [
        ("mention", "cupboard drawer", None, None),
        ("open", "cupboard drawer", None, None),
    ]


def test_that_points_back_as_a_destination_and_before_a_kind():
    assert clauses("put the cup on the saucer, then the spoon on top of that") == [
        ("put", "cup", "on", "saucer"),
        ("put", "spoon", "on", "cup"),
    ]
    assert clauses("there's a cup on the shelf; that cup goes in the box") == [
        ("mention", "cup on shelf", None, None),
        ("put", "cup on shelf", "in", "box"),
    ]
    assert clauses("there is a spoon in the box, red one. take it out of the box and put it on the tray") == [
        ("mention", "red spoon in box", None, None),
        ("pick", "red spoon in box", None, None),
        ("put", "red spoon in box", "on", "tray"),
    ]


def test_goals_with_other_participles_and_in_front_of():
    assert clauses("the lid seated on the jar") == [("put", "lid", "on", "jar")]
    assert clauses("the tray, in front of the lamp") == [("push", "tray", "near", "lamp")]
    assert clauses("the tray at the front of the lamp") == [("push", "tray", "near", "lamp")]


def test_a_sort_with_its_items_after_a_dash():
    assert clauses("could you sort the cups - red into the box and blue into the bin?") == [
        ("put", "red", "in", "box"),
        ("put", "blue", "in", "bin"),
    ]


@pytest.mark.parametrize(
    "text,expected",
    [
        ("not the red one - grab the other cup", [("pick", "cup not red", None, None)]),
        ("ignore the cup by the sink, I want the other one on the tray", [("put", "cup not by sink", "on", "tray")]),
        ("dont touch the cup by the sink; put the other cup on the tray", [("put", "cup not by sink", "on", "tray")]),
        ("pick up whichever of the two cups is nearer to you", [("pick", "nearest cup", None, None)]),
        ("open the top drawer, not the middle one", [("open", "top drawer", None, None)]),
    ],
)
def test_corrections_and_ruling_out(text, expected):
    assert clauses(text) == expected


def _kp(where):
    return SceneView({k: Keypoint(k, np.array(v, float), np.full(3, 0.05)) for k, v in where.items()})


def _primitives(res):
    import yaml

    tree = yaml.safe_load(res.text)["tree"]
    return [c.get("primitive") or c.get("type") for c in tree["children"]]


def test_a_pick_of_what_is_already_in_hand_adds_no_step():
    res = RulesPlanner().plan(PlanRequest("grab the cube and raise it off the table", _kp({"cube": (0.5, 0, 0.02)})))
    assert res.ok, res.error
    assert _primitives(res) == ["pick"]


def test_setting_it_down_there_repeats_the_carry_before():
    where = {"mug": (0.5, 0, 0.02), "shelf": (0.6, 0.2, 0.1)}
    res = RulesPlanner().plan(PlanRequest("pick up the mug, carry it to the shelf and set it down there", _kp(where)))
    assert res.ok, res.error
    assert _primitives(res) == ["pick", "place"]


def test_a_dial_is_the_knob_it_turns():
    where = {"kettle dial": (0.5, 0, 0.02)}
    res = RulesPlanner().plan(PlanRequest("twist the kettle's dial to the on position", _kp(where)))
    assert res.ok, res.error
    assert "turn_knob" in _primitives(res)


def test_a_tower_in_the_order_said_and_a_holder_on_the_left_of_a_colon():
    stacked = [("stack", "green", "on", "blue"), ("stack", "red", "on", "green")]
    assert clauses("tower from the bottom up: blue, green, red") == stacked
    assert clauses("stack from the top down: red, green, blue") == stacked
    assert clauses("the box's contents should be: the lemon") == [("put", "lemon", "in", "box")]
    assert clauses("the tray should hold: the mug") == [("put", "mug", "in", "tray")]


def test_a_container_said_as_the_verb():
    assert clauses("the lemon - box it") == [("mention", "lemon", None, None), ("put", "lemon", "in", "box")]


def test_a_thing_named_first_by_what_it_is_stacked_on():
    assert clauses("the cup stacked on the saucer, move it onto the tray") == [
        ("mention", "cup on saucer", None, None),
        ("put", "cup on saucer", "on", "tray"),
    ]
