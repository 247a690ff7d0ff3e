"""Round 40: general mechanisms found in probes 57-60 (written blind in the test half's own recipe), each tested on
other things and wording than where it was found."""

import pytest

from spark_core.planning.observe import phrases_for
from spark_core.planning.rules.descriptions import descriptions
from tests.planning.scene_views import leaves, plan, view


def _cups():
    where = {"cup": (0.5, -0.2, 0.05), "saucer": (0.6, 0.2, 0.01), "tin": (0.4, 0.1, 0.05), "sponge": (0.4, -0.3, 0.02)}
    return view(inventory=("cup", "saucer", "tin", "sponge"), **where)


@pytest.mark.parametrize(
    ("text", "aside"),
    [
        ("This is the stacking check. Put the cup on the saucer.", ["This is the stacking check."]),
        ("The saucer's a bit chipped. Put the cup on the saucer.", ["The saucer's a bit chipped."]),
        (
            "Okay so this one's easy. There's a tin on the left and the saucer is in the middle. Cup on the saucer.",
            ["Okay so this one's easy.", "There's a tin on the left and the saucer is in the middle."],
        ),
        ("We're testing grasps today. I'd like the cup on the saucer.", ["We're testing grasps today."]),
    ],
)
def test_sentences_that_only_describe_are_told_apart(text, aside):
    kept, said = descriptions(text, ["cup", "saucer", "tin"])
    assert said == aside
    assert kept.endswith("saucer.") and not any(s in kept for s in said)


@pytest.mark.parametrize(
    "text",
    [
        "Is the cup dry? Put the cup on the saucer.",  # a question
        "The cup needs to go on the saucer. Put the tin down first.",  # a duty
        "The cup goes on the saucer. Then the tin.",  # where a thing goes
        "End state: the cup on the saucer. The tin is next.",
        "Put the cup on the saucer. Put the tin on the cup.",  # nothing but requests
        "The cup is blue. The saucer is white.",  # nothing but descriptions: nothing is left to ask
    ],
)
def test_a_sentence_that_asks_is_never_a_description(text):
    assert descriptions(text, ["cup", "saucer", "tin"]) == (text, [])


def test_a_description_naming_a_thing_the_scene_lacks_is_kept():
    """ "the banana is a bit soft": a thing not there, said in a description, is still refused."""
    text = "The banana is a bit soft. Put the cup on the saucer."
    assert descriptions(text, ["cup", "saucer"]) == (text, [])
    assert descriptions(text, None)[1] == ["The banana is a bit soft."]  # before perception looked: look for both
    refused = plan("The banana is a bit soft today. This is the saucer check. Put the cup on the saucer.", _cups())
    assert not refused.ok


def test_the_request_plans_without_the_sentences_that_describe_it():
    """Context first, then the request: the context names the scene's things or the session, never a step."""
    scene = _cups()
    for text in (
        "This is the stacking check for today. Put the cup on the saucer, and take your time.",
        "Okay so this one's easy, I think. There's a tin on the left and the saucer is in the middle. End result "
        "I'm after: cup on the saucer.",
        "The saucer's a bit dusty. Wipe the saucer with the sponge, going round a few times so that it's all done.",
    ):
        got = plan(text, scene)
        assert got.ok, (text, got.error)
        assert any(s.startswith("set aside as") for s in got.detail["understood"])
    assert leaves(plan("This is the stacking check for today. Put the cup on the saucer.", scene))[:2] == [
        ("pick", "cup"),
        ("place", "saucer"),
    ]


def test_perception_looks_for_what_the_request_alone_names():
    """The request read alone names its things plainly ("basket", not "nearest wicker basket"): perception looks for
    those too, so the reading without the descriptions can ground."""
    text = "there's a tin on the left and the wicker basket is closer in. end result: the cup in the basket."
    got = phrases_for(text)
    assert {"cup", "basket"} <= set(got)
