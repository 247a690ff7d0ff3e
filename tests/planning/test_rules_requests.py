"""Requests worded as people type them: an arrow between a thing and a place, keyboard slips, a remark opening a
turn, a place named first ("the shelf is where the mug goes", "X is the one for the tray"), a question whose subject
is the thing moved, "mind -ing", courtesies and remarks after the request, an infinitive of purpose, a holder without
its article, particles before a destination, a bare "that" pointing back, "X to the Y" with no verb, "slide it back
in", and a put that only repeats where the step before set the thing down.

(Examples are written for these tests; none comes from data/wording/.)"""

import numpy as np
import pytest

from spark_core.grammar import plan_to_dict
from spark_core.perception import Keypoint
from spark_core.planning import PlanRequest, SceneView
from spark_core.planning.rules import RulesPlanner
from tests.planning.clause_tuples import clauses


@pytest.mark.parametrize(
    "text,expected",
    [
        ("blue mug -> tray", [("put", "blue mug", "in", "tray")]),
        ("the cup \u2192 shelf", [("put", "cup", "on", "shelf")]),
        ("put teh mug ontop of the box", [("put", "mug", "on", "box")]),
        ("id like the mug on the shelf", [("put", "mug", "on", "shelf")]),
        (
            "alright, next one: the cup, put that on the shelf",
            [("mention", "cup", None, None), ("put", "cup", "on", "shelf")],
        ),
        ("what we want in the end: the mug on the shelf", [("put", "mug", "on", "shelf")]),
        ("the shelf is where the mug goes", [("put", "mug", "on", "shelf")]),
        ("the left cup is the one for the tray", [("put", "left cup", "in", "tray")]),
        ("could the cup be placed on the shelf?", [("put", "cup", "on", "shelf")]),
        ("would you mind closing the drawer", [("close", "drawer", None, None)]),
        ("tray should have the mug in it", [("put", "mug", "in", "tray")]),
        ("blue cup tucked safely in the tray", [("put", "blue cup", "in", "tray")]),
        ("the mug lifted off the table, held in the gripper", [("pick", "mug", None, None)]),
    ],
)
def test_goals_and_requests_in_everyday_forms(text, expected):
    assert clauses(text) == expected


@pytest.mark.parametrize(
    "text,expected",
    [
        ("mug onto the shelf, if you could", [("put", "mug", "on", "shelf")]),
        ("cup into the tray, cheers", [("put", "cup", "in", "tray")]),
        ("close the drawer, somebody left it open", [("close", "drawer", None, None)]),
        ("put the tray on the shelf, open side up", [("put", "tray", "on", "shelf")]),
        ("mug onto the shelf, then move away", [("put", "mug", "on", "shelf")]),
        ("put the mug on the tray to dry it", [("put", "mug", "on", "tray")]),
        ("cup into the tray, that's the one", [("put", "cup", "in", "tray")]),
    ],
)
def test_remarks_after_the_request_add_no_step(text, expected):
    assert clauses(text) == expected


@pytest.mark.parametrize(
    "text,expected",
    [
        ("take the mug and set it up on the shelf", [("pick", "mug", None, None), ("put", "mug", "on", "shelf")]),
        ("the cup by the lamp, up on top of the box", [("put", "cup by lamp", "on", "box")]),
        (
            "red cup to the blue tray, green cup to the white tray",
            [("put", "red cup", "in", "blue tray"), ("put", "green cup", "in", "white tray")],
        ),
        (
            "there's a drawer hanging open; slide it back in",
            [("mention", "drawer", None, None), ("close", "drawer", None, None)],
        ),
        (
            "pull the drawer out first and afterwards drop the cup inside it",
            [("open", "drawer", None, None), ("put", "cup", "in", "drawer")],
        ),
    ],
)
def test_clause_structure(text, expected):
    assert clauses(text) == expected


@pytest.mark.parametrize(
    "text,expected",
    [
        ("mug by the lamp goes onto the shelf", [("put", "mug by lamp", "on", "shelf")]),
        (
            "the cup resting on the box, move it into the tray",
            [("mention", "cup on box", None, None), ("put", "cup on box", "in", "tray")],
        ),
        (
            "lift the cup and set it on the tray on top of the box",
            [("pick", "cup", None, None), ("put", "cup", "on", "tray on top of box")],
        ),
        ("give the tray a quick wipe with the cloth", [("scrub", None, None, "tray")]),
        ("fire the cooker up", [("turn_on", "cooker", None, None)]),
        ("get the kettle started", [("turn_on", "kettle", None, None)]),
    ],
)
def test_verbs_split_around_their_object_and_things_named_first(text, expected):
    assert clauses(text) == expected


def test_a_verb_with_to_is_still_no_carry():
    with pytest.raises(ValueError):
        clauses("walk to the shelf")


def test_a_put_that_repeats_where_the_step_before_set_it_is_no_second_carry():
    kp = {
        k: Keypoint(k, np.array(v, float), np.full(3, 0.05))
        for k, v in {"mug": (0.5, 0.0, 0.05), "tray": (0.5, 0.2, 0.02)}.items()
    }
    res = RulesPlanner().plan(PlanRequest("lift the mug, carry it over to the tray and drop it in", SceneView(kp)))
    assert res.ok, res.error
    assert [c["type"] for c in plan_to_dict(res.plan)["tree"]["children"]] == ["pick", "place_in"]


def _leaves(text, **where):
    kp = {k.replace("_", " "): Keypoint(k, np.array(v, float), np.full(3, 0.04)) for k, v in where.items()}
    res = RulesPlanner().plan(PlanRequest(text, SceneView(kp)))
    assert res.ok, res.error
    return [
        (c["type"], next(iter(c.get("params", {}).values()), None)) for c in plan_to_dict(res.plan)["tree"]["children"]
    ]


def test_perception_is_asked_for_the_handle_of_a_drawer_something_goes_into():
    from spark_core.planning.observe import phrases_for

    assert {"cabinet drawer handle", "drawer handle"} <= set(phrases_for("put the cup in the cabinet drawer"))


def test_a_drawer_is_opened_before_something_goes_in_unless_a_step_opens_it():
    scene = {"cup": (0.5, 0.2, 0.03), "drawer": (0.6, -0.2, 0.1), "drawer_handle": (0.5, -0.2, 0.1)}
    opened = [("open_drawer", "drawer handle"), ("pick", "cup"), ("place_in", "drawer")]
    assert _leaves("put the cup in the drawer", **scene) == opened
    assert _leaves("open the drawer and put the cup inside it", **scene) == opened
    # the same drawer by another name: opened once
    same = dict(scene, cabinet_drawer=scene["drawer"], cabinet_drawer_handle=scene["drawer_handle"])
    twice = _leaves("open the cabinet drawer and put the cup in the drawer", **same)
    assert [t for t, _ in twice] == ["open_drawer", "pick", "place_in"]
    assert _leaves("the cup goes in the drawer; open the drawer and then put the cup inside", **scene) == opened


@pytest.mark.parametrize(
    "text,expected",
    [
        ("the mug on the tray, that's the end state i'm after", [("put", "mug", "on", "tray")]),
        ("cup onto the box, and try to get it centred", [("put", "cup", "on", "box")]),
        ("move the mug onto the shelf so the tray's empty", [("put", "mug", "on", "shelf")]),
        ("make a tower for me - blue at the bottom, red on top", [("stack", "red", "on", "blue")]),
        ("could you flip them round so the cup ends up on the box?", [("put", "cup", "on", "box")]),
        (
            "the tray holds the mug and the shelf holds the cup",
            [("put", "mug", "in", "tray"), ("put", "cup", "on", "shelf")],
        ),
        ("leave the centre mug alone and put the other mug on the tray", [("put", "mug not middle", "on", "tray")]),
    ],
)
def test_goals_with_remarks_arrangements_and_several_holders(text, expected):
    assert clauses(text) == expected
