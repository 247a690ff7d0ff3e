"""Only a word that names a thing refuses an instruction when perception does not find it: a concrete noun does
(an absent object is never planned around); a place or manner noun, or a word that is no noun at all, does not.

(Examples are written for these tests; none comes from data/wording/.)"""

import numpy as np
import pytest

from spark_core.perception import Keypoint
from spark_core.planning import PlanRequest, SceneView
from spark_core.planning.rules import RulesPlanner, parse_instruction
from spark_core.planning.rules.mentions import read_past
from spark_core.planning.rules.things import is_thing


@pytest.mark.parametrize("word", ["saucer", "spatula", "tomato", "stool", "whisk", "akita", "colander"])
def test_concrete_nouns_and_unknown_names_are_things(word):
    assert is_thing(word)


@pytest.mark.parametrize("word", ["spot", "gap", "corner", "side", "way", "ideally", "carefully", "going", "gently"])
def test_places_manners_and_other_parts_of_speech_are_not(word):
    assert not is_thing(word)


def test_read_past_keeps_things_and_drops_non_things():
    text = "put the mug on the tray, leaving a gap, without hitting the colander"
    assert read_past(text, parse_instruction(text)) == ["colander"]


def _plan(text, found, unresolved):
    kp = {k: Keypoint(k, np.array(xyz, float), np.array((0.05, 0.05, 0.05))) for k, xyz in found.items()}
    return RulesPlanner().plan(PlanRequest(text, SceneView(kp, unresolved=unresolved)))


def test_an_unfound_non_thing_does_not_refuse_and_an_unfound_thing_does():
    found = {"mug": (0.5, 0.0, 0.05), "tray": (0.5, 0.2, 0.02)}
    ok = _plan("put the mug on the tray, leaving a gap", found, {"gap": "none found"})
    assert ok.ok, ok.error
    refused = _plan("put the mug on the tray, without hitting the colander", found, {"colander": "none found"})
    assert not refused.ok and "colander" in refused.error


def test_a_pronoun_in_a_remark_is_no_thing_to_find():
    text = "move the mug onto the tray, that's the end state i'm after"
    assert read_past(text, parse_instruction(text)) == []
    assert not is_thing("i") and not is_thing("you")
