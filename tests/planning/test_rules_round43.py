"""Round 43: compound names of the scenes' things (rules/names.py) and what the round's probes showed, each tested on
other things and wording than where it was found."""

import pytest

from spark_core.planning.rules.names import compound_names
from tests.planning.scene_views import leaves, plan, view
from tests.planning.test_rules_round28 import read


@pytest.mark.parametrize(
    ("text", "said"),
    [
        ("put the bowl on the hot plate", "put the bowl on the stove"),
        ("the hotplate, switch it on", "the stove, switch it on"),
        ("open the top drawer of the chest of drawers", "open the top drawer of the cabinet"),
        ("the drawer unit's bottom drawer", "the cabinet's bottom drawer"),
        ("pasta sauce into the basket", "tomato sauce into the basket"),
        ("grab the marinara", "grab the tomato sauce"),
        ("the canned soup goes in the basket", "the soup goes in the basket"),
        ("the choc pudding", "the chocolate pudding"),
        # controls: a plate that is hot is not said so; "chocolate" stays; a soup can stays a can
        ("put the hot bowl on the plate", "put the hot bowl on the plate"),
        ("the soup can", "the soup can"),
        ("the chocolate pudding", "the chocolate pudding"),
    ],
)
def test_a_compound_name_is_said_in_the_word_the_kinds_table_knows(text, said):
    assert compound_names(text) == said


def test_the_hot_plate_is_the_stove_not_the_plate():
    scene = view(inventory=("black bowl", "plate", "stove"), black_bowl=(0.4, 0.1, 0.03), plate=(0.5, -0.2, 0.01),
                 stove=(0.3, -0.3, 0.02))
    result = plan("move the black bowl onto the hot plate", scene)
    assert result.ok, result.error
    labels = {label for _, label in leaves(result)}
    assert "stove" in labels and "plate" not in labels, leaves(result)


def test_a_compound_name_of_a_thing_the_scene_lacks_is_absent():
    # no stove: "the hot plate" is not the plate
    scene = view(inventory=("black bowl", "plate"), black_bowl=(0.4, 0.1, 0.03), plate=(0.5, -0.2, 0.01),
                 unresolved={"stove": "not found"})
    assert not plan("move the black bowl onto the hot plate", scene).ok


def test_a_chest_of_drawers_reads_as_the_cabinet():
    assert read("open the middle drawer of the chest of drawers") == ["open obj=cabinet middle drawer"]
