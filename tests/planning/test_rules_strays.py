"""Safety, round eight: a thing named where the parser reads no thing is still a thing the scene must hold. A noun
after a preposition perception does not measure ("under", "with", "behind"), a thing joined by "and" inside a
phrase, a noun that no phrase holds at all, and a shape said as a noun ("hex nut") each refuse when absent; words
that only look like nouns there ("once", "fish it out", "the gripper clear") do not.

(Examples are written for these tests; none comes from data/wording/.)"""

import numpy as np
import pytest

from spark_core.perception import Keypoint
from spark_core.perception.naming import mismatch
from spark_core.planning import PlanRequest, SceneView
from spark_core.planning.observe import phrases_for
from spark_core.planning.rules import RulesPlanner, parse_instruction
from spark_core.planning.rules.mentions import anchors, stray_nouns
from tests.planning.clause_tuples import clauses


@pytest.mark.parametrize(
    "phrase,expected",
    [
        ("plate under lamp", ["lamp"]),
        ("square peg with wrench", ["wrench"]),
        ("bowl behind toaster", ["toaster"]),
        ("plate and mind vase", ["mind vase"]),  # a second thing joined inside the phrase
        ("plate after you move kettle", ["you move kettle"]),  # a clause the phrase swallowed
        ("black bowl on stove", ["stove"]),  # perception's own relations: as before
    ],
)
def test_things_after_other_prepositions_and_conjunctions_are_anchors(phrase, expected):
    assert anchors(phrase) == expected


@pytest.mark.parametrize(
    "text,expected",
    [
        ("pour the mug into the bowl, careful with teapot", ["teapot"]),  # no determiner, in a dropped remark
        ("put the mug on the tray once it is free", []),  # "once": an adverb here
        ("put the mug on the tray", []),
    ],
)
def test_nouns_no_phrase_holds(text, expected):
    assert stray_nouns(text, parse_instruction(text)) == expected


def test_observe_looks_for_a_stray_noun_and_the_planner_refuses_when_it_is_absent():
    text = "pour the mug into the bowl, careful with teapot"
    assert "teapot" in phrases_for(text)
    kp = {
        k: Keypoint(k, np.array(v, float), np.full(3, 0.05))
        for k, v in {"mug": (0.4, 0, 0), "bowl": (0.6, 0, 0)}.items()
    }
    refused = RulesPlanner().plan(PlanRequest(text, SceneView(kp, unresolved={"teapot": "none found"})))
    assert not refused.ok and "could not find 'teapot'" in refused.error
    found = dict(kp, teapot=Keypoint("teapot", np.array((0.5, 0.2, 0.0)), np.full(3, 0.05)))
    assert RulesPlanner().plan(PlanRequest(text, SceneView(found))).ok


def test_a_pour_destination_located_by_another_thing_keeps_the_relation():
    # "the bowl on the tray" stays a located bowl (the tray an anchor), not a "tray bowl" whose tray nobody checks
    assert clauses("pour the beads from the mug into the bowl on the tray")[0][3] == "bowl on tray"


def test_a_table_word_before_another_noun_is_no_table():
    # "from the counter shelf": the shelf it is on (an anchor that must be there), not "bowl shelf"
    assert clauses("move the bowl from the counter shelf onto the plate") == [
        ("put", "bowl on counter shelf", "on", "plate")
    ]
    assert clauses("take the block off the table and put it on the plate")[0] == ("pick", "block", None, None)


@pytest.mark.parametrize("prompt,name", [("bag", "basket"), ("loaf", "ketchup")])
def test_a_bag_or_a_loaf_is_a_kind_of_its_own(prompt, name):
    assert mismatch(prompt, name, name) is not None


@pytest.mark.parametrize("prompt", ["hex nut", "triangle nut", "hexagon nut"])
def test_a_shape_said_as_a_noun_is_a_shape_claim(prompt):
    assert mismatch(prompt, "square nut", "square nut") is not None
    assert mismatch("square nut", "square nut", "square nut") is None
