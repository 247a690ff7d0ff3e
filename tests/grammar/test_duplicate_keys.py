"""A plan that says two things at once is refused, not resolved silently in favour of the last (adversarial
review L10)."""

from __future__ import annotations

import pytest

from spark_core import validate


@pytest.mark.parametrize(
    "text,message",
    [
        ("task: t\ntree: {type: open_gripper, type: close_gripper}", "line 2: duplicate key 'type'"),
        ("task: t\ntree: {primitive: wait}\ntask: u", "line 3: duplicate key 'task'"),
        ('{"task": "t", "tree": {"primitive": "wait", "primitive": "grasp"}}', "duplicate key 'primitive'"),
    ],
)
def test_a_duplicate_key_is_a_plan_error(text, message):
    plan, issues = validate(text)
    assert plan is None and [(i.path, i.message) for i in issues] == [("text", message)]


def test_the_same_key_in_different_mappings_is_fine():
    plan, issues = validate(
        "task: t\ntree:\n  type: sequence\n  children:\n    - {primitive: wait}\n    - {primitive: wait}\n"
    )
    assert issues == [] and plan is not None
