"""Round fifteen of the rules planner (issue 18): how the parts of an instruction relate, handled once for every
wording (rules/discourse.py): steps said out of order ("before X, Y"; "Y once X"), a description of the scene
before the request ("the drawer is open - shut it"), what is not meant after a complete request ("..., not the
crate"), a header that names nothing ("two jobs: ..."), "the former / the latter", a goal said as a cleft or as the
holder with its contents; "the other <kind>" as the complement of the one picked out before, whatever picked it out
(parse._complement); a rank and an extreme said as one word ("second-highest"), a position said by a verb ("the bowl
that sits lowest"), one negation of two of three places ("the drawer that isn't at the top or at the bottom"). Each
test fails without the mechanism it names.

(Examples are written for these tests; none comes from data/wording/.)"""

import pytest

from spark_core.planning import PlanRequest
from spark_core.planning.rules import RulesPlanner, parse_instruction
from spark_core.planning.rules.discourse import restructured
from spark_core.planning.rules.parse import _complement
from spark_core.planning.rules.qualify import neither_nor, ordinals, qualify
from tests.planning.scene_views import leaves as _leaves
from tests.planning.scene_views import view as _view


# -- steps said out of order -----------------------------------------------------------------------------------------
@pytest.mark.parametrize(
    "text, said",
    [
        ("before putting the cube in the drawer, open it", "open the drawer, then put the cube in the drawer"),
        ("put the cube in the drawer after you open it", "open the drawer, then put the cube in the drawer"),
        ("after opening it, put the cube in the drawer", "open the drawer, then put the cube in the drawer"),
        ("once the drawer is open, put the cube in it", "open the drawer, then put the cube in it"),
        (
            "put the lime in the crate once the pear is in the bin",
            "the pear is in the bin, then put the lime in the crate",
        ),
        ("open the drawer before putting the cube in it", "open the drawer, then put the cube in it"),
    ],
)
def test_steps_said_out_of_order_are_put_in_the_order_they_happen(text, said):
    assert restructured(text) == said


def test_a_remark_before_the_request_is_no_step_to_reorder():
    text = "when you get a sec, put the cube in the bin"
    assert restructured(text) == text


def test_a_step_said_after_the_one_it_must_follow_is_planned_after_it():
    view = _view(("cube", "drawer"), cube=(0.4, 0.0, 0.02), drawer=(0.7, 0.2, 0.07), drawer_handle=(0.62, 0.2, 0.09))
    result = RulesPlanner().plan(PlanRequest("before putting the cube in the drawer, open it", view))
    assert result.ok, result.error
    assert [s[0] for s in _leaves(result)] == ["open_drawer", "pick", "place_in"]


# -- a description of the scene before the request -------------------------------------------------------------------
@pytest.mark.parametrize(
    "text, said",
    [
        ("the drawer is open - shut it", "there is the drawer. shut it"),
        ("the hob is off, switch it on", "there is the hob. switch it on"),
        ("the jar stays put; put the lid on top of it", "there is the jar. put the lid on top of it"),
    ],
)
def test_a_description_of_how_a_thing_is_now_only_names_it(text, said):
    assert restructured(text) == said


def test_a_drawer_said_to_be_open_is_closed_not_opened_first():
    view = _view(("drawer",), drawer=(0.6, 0.2, 0.07), drawer_handle=(0.5, 0.2, 0.09))
    result = RulesPlanner().plan(PlanRequest("the drawer is open - shut it", view))
    assert result.ok, result.error
    assert [s[0] for s in _leaves(result)] == ["close_drawer", "go_home"]


# -- what is not meant, after a complete request ---------------------------------------------------------------------
def test_a_contrast_after_the_request_names_its_things_but_is_no_step():
    assert (
        restructured("tip the beads into the pot, not back into the jug")
        == "there is the jug. tip the beads into the pot"
    )
    assert (
        restructured("the lime goes in the bin - not the pear and not the plum")
        == "there is the pear. there is the plum. the lime goes in the bin"
    )
    assert restructured("put the cube in the bin, not too fast") == "put the cube in the bin, not too fast"


def test_a_thing_ruled_out_after_the_request_must_still_be_in_the_scene():
    view = _view(("cube", "bin"), {"crate": "none found"}, cube=(0.4, 0.0, 0.02), bin=(0.5, 0.2, 0.04))
    result = RulesPlanner().plan(PlanRequest("put the cube in the bin, not in the crate", view))
    assert not result.ok
    assert "crate" in result.error


def test_a_thing_ruled_out_after_the_request_is_not_moved():
    view = _view(("cube", "bin", "crate"), cube=(0.4, 0.0, 0.02), bin=(0.5, 0.2, 0.04), crate=(0.5, -0.2, 0.04))
    result = RulesPlanner().plan(PlanRequest("put the cube in the bin, not in the crate", view))
    assert result.ok, result.error
    assert _leaves(result) == [("pick", "cube"), ("place_in", "bin")]


# -- headers, the former and the latter, clefts ----------------------------------------------------------------------
def test_a_header_that_names_nothing_is_read_past_and_one_that_names_a_thing_is_kept():
    assert restructured("two jobs: cube -> bin; lime -> crate") == "cube -> bin; lime -> crate"
    assert restructured("red cube: into the bin") == "red cube: into the bin"


def test_the_former_and_the_latter_name_the_two_things_listed_first():
    assert (
        restructured("lime and pear: the former into the bin, the latter into the crate")
        == "the lime into the bin, the pear into the crate"
    )


@pytest.mark.parametrize(
    "text, said",
    [
        ("the lime is what should go into the bin", "the lime should go into the bin"),
        ("the pear is the one that goes on the tray", "the pear goes on the tray"),
        ("bin with the lime in it, that's what i want", "the lime in the bin"),
    ],
)
def test_a_goal_said_as_a_cleft_or_as_the_holder_is_said_plainly(text, said):
    assert restructured(text) == said


# -- the other one of a kind -----------------------------------------------------------------------------------------
@pytest.mark.parametrize(
    "ref, phrase, other",
    [
        ("red cube", None, "cube not red"),
        ("cube not blue", None, "blue cube"),
        ("black bowl on stove", None, "black bowl not on stove"),
        ("bowl not on stove", None, "bowl on stove"),
        ("leftmost black bowl", "black bowl", "black bowl not leftmost"),
    ],
)
def test_the_other_of_a_kind_is_the_complement_of_the_one_picked_out(ref, phrase, other):
    assert _complement(ref, phrase) == other


@pytest.mark.parametrize(
    "text, target",
    [
        ("put the red cube on the other cube", "cube not red"),
        ("put whichever cube is not blue on top of the other cube", "blue cube"),
        ("put the cube that is not blue on the other one", "blue cube"),
    ],
)
def test_the_other_one_in_the_same_clause_is_the_complement_of_its_object(text, target):
    (clause,) = parse_instruction(text)
    assert clause.target == target


# -- ranks, extremes and places ruled out ----------------------------------------------------------------------------
def test_a_rank_and_an_extreme_said_as_one_word_count_from_that_extreme():
    assert ordinals("open the second-highest drawer") == "open the second top drawer"
    assert ordinals("take the third leftmost cup") == "take the third leftmost cup"


def test_a_position_said_by_a_verb_picks_the_extreme():
    assert qualify("take the bowl that sits lowest") == "take the bottom bowl"


def test_one_negation_of_two_of_three_places_names_the_third():
    assert neither_nor("open the drawer that isn't at the top or at the bottom") == "open the drawer middle"
    assert neither_nor("open the drawer that is not the top or the middle one") == "open the drawer bottom"


# -- "it" by what the action can do with a thing ---------------------------------------------------------------------
def test_it_carried_after_a_fixture_is_opened_is_the_thing_named_before_the_fixture():
    clauses = parse_instruction("pick up the cube, open the drawer and put it inside")
    assert [(c.action, c.obj) for c in clauses] == [("pick", "cube"), ("open", "drawer"), ("put", "cube")]


def test_it_switched_after_a_carry_onto_a_hob_is_the_hob():
    clauses = parse_instruction("move the pan onto the hob, then switch it on")
    assert (clauses[-1].action, clauses[-1].obj) == ("turn_on", "hob")


def test_a_fixture_is_worked_with_the_hand_free():
    view = _view(("cube", "drawer"), cube=(0.4, 0.0, 0.02), drawer=(0.7, 0.2, 0.07), drawer_handle=(0.62, 0.2, 0.09))
    result = RulesPlanner().plan(PlanRequest("grab the cube. open the drawer, then drop it in there", view))
    assert result.ok, result.error
    assert _leaves(result) == [("open_drawer", "drawer handle"), ("pick", "cube"), ("place_in", "drawer")]


def test_the_other_one_as_a_destination_is_the_other_destination_and_a_later_phrase_is_not_the_other():
    clauses = parse_instruction("red cube into the bin that isn't yellow, blue cube into the other one")
    assert [c.target for c in clauses] == ["bin not yellow", "yellow bin"]
    clauses = parse_instruction("the leftmost cube goes in the green bin, the other cube in the yellow bin")
    assert [(c.obj, c.target) for c in clauses] == [("leftmost cube", "green bin"), ("cube not leftmost", "yellow bin")]
