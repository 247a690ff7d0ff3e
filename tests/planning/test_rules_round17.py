"""Round seventeen of the rules planner (issue 18): general mechanisms for steps, negation and back-references.

- rules/steps.py: every cue that says where one step ends and the next begins ("step 1:", "1)", "first ... and
  finally ...", "as a second step", "after that" without a comma) is a sentence boundary, and a condition that only
  restates the step before's result ("once it's open", "once you have it") is no step.
- rules/stepwise.py + planner._by_steps: when no reading of the whole instruction plans, each step is planned on its
  own by the whole pipeline, a pronoun bound to the step before's thing; any step that does not plan refuses all.
- rules/qualify.py: a quantifier with its exception ("all but the blue block") and "the remaining / leftover one"
  rule one out as the other negations do; "the one that is" after a thing ruled out is the one ruled in; two
  negations of three places in a row ("not top and not middle") name the third.
- rules/parse.py: "the blue one" after "the block not blue" is a block (the head before the negation).

Each test fails without the mechanism it names. (Examples are written for these tests; none comes from
data/wording/.)"""

import pytest

from spark_core.planning import PlanRequest
from spark_core.planning.rules import RulesPlanner, discourse, qualify
from spark_core.planning.rules.parse import parse_instruction
from spark_core.planning.rules.planner import RulesPlanner as _Planner
from tests.planning.scene_views import leaves as _leaves
from tests.planning.scene_views import view as _view


def _plan(text, view):
    return RulesPlanner().plan(PlanRequest(text, view))


def _objects(text):
    return [(c.action, c.obj, c.target) for c in parse_instruction(text)]


# -- step cues ----------------------------------------------------------------------------------------------------
TRAYS = dict(lime=(0.5, 0.1, 0.03), pear=(0.5, -0.1, 0.03), green_bin=(0.4, 0.3, 0.01), grey_bin=(0.4, -0.3, 0.01))
STEP_CUES = [
    "step 1: lime into the green bin. step 2: pear into the grey bin",
    "1) lime into the green bin 2) pear into the grey bin",
    "first the lime goes in the green bin and finally the pear in the grey bin",
    "put the lime in the green bin, then, as a second step, put the pear in the grey bin",
]


@pytest.mark.parametrize("text", STEP_CUES)
def test_step_cues_are_step_boundaries(text):
    result = _plan(text, _view(**TRAYS))
    assert result.ok, result.error
    assert _leaves(result) == [("pick", "lime"), ("place_in", "green bin"), ("pick", "pear"), ("place_in", "grey bin")]


@pytest.fixture
def without_steps(monkeypatch):
    monkeypatch.setattr(discourse, "sequenced", lambda text: text)
    monkeypatch.setattr(_Planner, "_by_steps", lambda self, request, t0: None)


@pytest.mark.parametrize("text", STEP_CUES[:2])
def test_without_the_step_cues_these_are_refused(text, without_steps):
    assert not _plan(text, _view(**TRAYS)).ok


def test_each_numbered_step_read_on_its_own_plans_without_the_cues(monkeypatch):
    monkeypatch.setattr(discourse, "sequenced", lambda text: text)
    result = _plan(STEP_CUES[0], _view(**TRAYS))
    assert result.ok, result.error
    assert _leaves(result) == [("pick", "lime"), ("place_in", "green bin"), ("pick", "pear"), ("place_in", "grey bin")]


DRAWER = dict(lime=(0.4, 0.0, 0.03), crate_drawer=(0.7, 0.2, 0.1), crate_drawer_handle=(0.6, 0.2, 0.1))


def test_a_condition_restating_the_step_before_is_no_step():
    result = _plan("open the crate drawer, then once it's open tuck the lime inside", _view(**DRAWER))
    assert result.ok, result.error
    assert _leaves(result) == [("open_drawer", "crate drawer handle"), ("pick", "lime"), ("place_in", "crate drawer")]


def test_without_dropping_the_restated_condition_it_is_refused(without_steps):
    assert not _plan("open the crate drawer, then once it's open tuck the lime inside", _view(**DRAWER)).ok


def test_an_ordinal_of_a_thing_is_no_step_cue():
    from spark_core.planning.rules.steps import sequenced

    assert sequenced("first bowl from the left onto the plate") == "first bowl from the left onto the plate"
    assert sequenced("put the bowl next to the plate on the stove") == "put the bowl next to the plate on the stove"
    assert sequenced("first grab the bowl; afterwards put it on the plate") == "grab the bowl. put it on the plate"


# -- each step on its own ----------------------------------------------------------------------------------------
def test_a_step_naming_what_perception_did_not_find_refuses_the_whole(monkeypatch):
    monkeypatch.setattr(discourse, "sequenced", lambda text: text)  # the steps read one by one
    result = _plan("step 1: lime into the green bin. step 2: kiwi into the grey bin", _view(**TRAYS))
    assert not result.ok


def test_a_pronoun_after_a_step_names_its_own_thing_is_that_thing():
    from spark_core.planning.rules.stepwise import steps

    assert steps("grab the lime. then grab the pear and drop it in the grey bin") == [
        "grab the lime",
        "grab the pear and drop it in the grey bin",
    ]
    assert steps("grab the lime. then it goes in the green bin") == ["grab the lime", "the lime goes in the green bin"]


# -- negation -----------------------------------------------------------------------------------------------------
def test_all_but_the_one_rules_it_out():
    assert _objects("all but the blue block go in the tray")[0][1] == "block not blue"
    where = dict(block_not_blue=(0.5, 0.1, 0.03), blue_block=(0.5, -0.1, 0.03), tray=(0.4, 0.3, 0.01))
    result = _plan("everything except the blue block goes in the tray", _view(**where))
    assert result.ok, result.error
    assert _leaves(result) == [("pick", "block not blue"), ("place_in", "tray")]


def test_the_remaining_one_is_the_other_one():
    text = "ignore the mug on the shelf; the remaining mug goes onto the tray"
    assert _objects(text) == [("put", "mug not on shelf", "tray")]


def test_the_one_that_is_after_a_ruled_out_attribute_is_the_one_ruled_in():
    assert _objects("pick up the cube that's not green and stack it on the one that is") == [
        ("pick", "cube not green", None),
        ("stack", "cube not green", "green cube"),
    ]


def test_without_the_positive_reading_the_one_that_is_names_nothing(monkeypatch):
    monkeypatch.setattr(qualify, "_positive_of_ruled_out", lambda text: text)
    assert _objects("pick up the cube that's not green and stack it on the one that is")[1][2] != "green cube"


def test_two_negations_of_three_places_name_the_third():
    assert _objects("of the drawers, open the one that is not top and not middle") == [("open", "drawer bottom", None)]


def test_the_kind_of_one_after_a_negated_phrase_is_its_head():
    assert _objects("put the block not blue in the green tray; the blue one goes in the yellow tray")[1] == (
        "put",
        "blue block",
        "yellow tray",
    )


# -- back-references ----------------------------------------------------------------------------------------------
def test_the_former_and_the_latter_name_the_last_pair_listed_in_any_frame():
    assert _objects(discourse.restructured("there's a lime and a pear. put the latter on the former")) == [
        ("mention", "lime", None),
        ("mention", "pear", None),
        ("put", "pear", "lime"),
    ]
    said = "take the lime and the pear: the former goes in the green bin, the latter in the grey bin"
    assert _objects(discourse.restructured(said)) == [
        ("put", "lime", "green bin"),
        ("put", "pear", "grey bin"),
    ]
