"""No partial plans (issue 18: absent objects and nonsense are always refused, never executed).

A part of an instruction that the rule parse reads no verb in, said before the request, was kept as a remark ("someone
left the drawer open, close it") whether or not any step used it, so a step it could not read was dropped and the
rest planned: "into the green bin with the lime. the pear in the grey bin next" planned the pear alone. Such a part
must now serve a step after it (a thing it names is acted on or said again, or a pronoun refers back), or only say to
go near a thing; else the instruction is refused, saying which part could not be read (after the check that every
thing named is in the scene, whose refusal still comes first). Context sentences ("the lime
stays put"), remarks a pronoun refers back to, and approaches still plan.

The refusal tests of `test_a_part_no_step_uses_refuses_the_whole` fail without the check (rules/parse.py
`_remark_used`, planner `_compose`); the others guard it against refusing what was planned before it, or taking the
place of the absent thing's refusal. (Examples are written for these tests; none comes from data/wording/.)"""

import pytest

from spark_core.planning import PlanRequest
from spark_core.planning.rules import RulesPlanner
from tests.planning.scene_views import leaves as _leaves
from tests.planning.scene_views import view as _view

TRAYS = dict(lime=(0.5, 0.1, 0.03), pear=(0.5, -0.1, 0.03), green_bin=(0.4, 0.3, 0.01), grey_bin=(0.4, -0.3, 0.01))


def _plan(text, unresolved=None):
    return RulesPlanner().plan(PlanRequest(text, _view(unresolved=unresolved, **TRAYS)))


@pytest.mark.parametrize(
    "text, unread, unresolved",
    [
        # a step said in an order the parse does not read
        ("into the green bin with the lime. the pear in the grey bin next", "into the green bin with the lime", None),
        # the same, the thing in it not in the scene view (perception said nothing of it; had it reported 'none
        # found', the check that every thing named is there refused it before this one)
        (
            "into the green bin with the banana. the pear in the grey bin next",
            "into the green bin with the banana",
            None,
        ),
        # a verb the planner does not know
        ("frobnicate the lime. put the pear in the grey bin", "frobnicate the lime", None),
        ("the lime wugs the green bin. the pear in the grey bin", "the lime wugs the green bin", None),
    ],
)
def test_a_part_no_step_uses_refuses_the_whole(text, unread, unresolved):
    result = _plan(text, unresolved)
    assert not result.ok, _leaves(result)
    assert f"could not read {unread!r}" in result.error
    assert "put obj=pear relation=in target=grey bin" in result.error  # what was understood
    assert "found in the scene: lime, pear, green bin, grey bin" in result.error


def test_a_thing_perception_found_none_of_is_still_said_so():
    result = _plan("into the green bin with the banana. the pear in the grey bin next", {"banana": "none found"})
    assert not result.ok
    assert result.error.startswith("could not find 'banana' in the scene")


@pytest.mark.parametrize(
    "text, planned",
    [
        # a context sentence: only says what to leave alone
        ("the lime stays put. put the pear in the grey bin", [("pick", "pear"), ("place_in", "grey bin")]),
        # a remark a pronoun refers back to, then one more sentence
        (
            "someone left the green bin open, put the lime in it. the pear in the grey bin",
            [("pick", "lime"), ("place_in", "green bin"), ("pick", "pear"), ("place_in", "grey bin")],
        ),
        # only says to go near a thing
        ("go over to the green bin, put the pear in the grey bin", [("pick", "pear"), ("place_in", "grey bin")]),
        # every sentence a step
        (
            "the lime goes in the green bin. the pear in the grey bin",
            [("pick", "lime"), ("place_in", "green bin"), ("pick", "pear"), ("place_in", "grey bin")],
        ),
    ],
)
def test_context_remarks_and_steps_still_plan(text, planned):
    result = _plan(text)
    assert result.ok, result.error
    assert _leaves(result) == planned
