"""Round 39: a class said with a generic noun ("the dairy thing") and the sided relations "behind" / "in front of"."""

from __future__ import annotations

import numpy as np
import pytest

from spark_core.perception.naming import class_members
from spark_core.perception.qualifiers import on_side, split_relation

NAMES = ["milk", "cream cheese", "butter", "chocolate pudding", "basket"]


@pytest.mark.parametrize("prompt", ["dairy thing", "dairy item", "dairy product"])
def test_a_class_said_with_a_generic_noun_names_every_member(prompt):
    members = class_members(prompt, NAMES)
    assert members is not None and {NAMES[k] for k in members} == {"milk", "cream cheese", "butter"}


def test_a_generic_noun_alone_names_no_class():
    assert class_members("red thing", NAMES) is None


def test_behind_and_in_front_of_are_sides_from_the_robot():
    """World x points away from the robot: "behind X" is farther than X, "in front of X" nearer."""
    assert split_relation("drawer behind red block") == ("drawer", "behind", ["red block"])
    assert split_relation("bowl in front of plate")[1] == "in front of"
    anchor = np.array([0.5, 0.0])
    far, near = np.array([0.7, 0.05]), np.array([0.3, -0.05])
    assert on_side("behind", far, anchor) and not on_side("behind", near, anchor)
    assert on_side("in front of", near, anchor) and not on_side("in front of", far, anchor)
