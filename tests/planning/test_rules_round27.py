"""Round 27: general mechanisms, not wording of a probe ("A but B" said without a comma)."""

import pytest

from spark_core.grammar import plan_to_dict
from spark_core.planning.rules.discourse import restructured
from tests.planning.scene_views import leaves, plan, view

SCENE = view(red_block=(0.5, 0.1, 0.02), bowl=(0.5, -0.1, 0.03), plate=(0.6, 0.0, 0.01))


@pytest.mark.parametrize(
    "text",
    [
        "put the red block in the bowl but don't touch the plate",
        "put the red block in the bowl but be gentle",
        "put the red block in the bowl but leave the plate alone",
        "put the red block in the bowl but slowly",
    ],
)
def test_a_clause_after_but_is_read_as_after_a_comma(text):
    result = plan(text, SCENE)
    assert result.ok, result.error
    assert leaves(result)[:2] == [("pick", "red block"), ("place_in", "bowl")]


@pytest.mark.parametrize("text", ["put all the blocks but the red one in the tray", "anything but blue, put it away"])
def test_but_before_a_thing_or_a_colour_still_sets_it_apart(text):
    assert restructured(text) == text


TRAYS = view(
    red_block=(0.5, 0.1, 0.02),
    blue_block=(0.5, -0.1, 0.02),
    green_tray=(0.6, 0.2, 0.01),
    yellow_tray=(0.6, -0.2, 0.01),
)
BOTH = [("pick", "red block"), ("place_in", "green tray"), ("pick", "blue block"), ("place_in", "yellow tray")]


@pytest.mark.parametrize(
    "text",
    [
        "the green tray gets the red block, the yellow tray gets the blue block",
        "green tray gets the red block, yellow tray gets the blue block",
        "the green tray needs the red block; the yellow tray needs the blue block",
    ],
)
def test_goals_listed_with_commas_are_one_carry_each(text):
    result = plan(text, TRAYS)
    assert result.ok, result.error
    assert [x for x in leaves(result) if x[0] != "go_home"] == BOTH


@pytest.mark.parametrize(
    "text",
    [
        "take the red block and drop it into the green tray, then do likewise with the blue block and the yellow tray",
        "put the red block in the green tray, then repeat that with the blue block in the yellow tray",
    ],
)
def test_the_same_again_with_another_thing_and_place(text):
    result = plan(text, TRAYS)
    assert result.ok, result.error
    assert [x for x in leaves(result) if x[0] != "go_home"] == BOTH


def test_the_same_again_with_two_things_of_one_kind_is_done_to_each():
    scene = view(
        red_block=(0.5, 0.1, 0.02),
        blue_block=(0.5, -0.1, 0.02),
        green_block=(0.4, 0.0, 0.02),
        green_tray=(0.6, 0.2, 0.01),
    )
    text = "put the red block in the green tray, then do the same with the blue block and the green block"
    result = plan(text, scene)
    assert result.ok, result.error
    assert [x for x in leaves(result) if x[0] == "pick"] == [
        ("pick", "red block"),
        ("pick", "blue block"),
        ("pick", "green block"),
    ]
    assert {x for x in leaves(result) if x[0] == "place_in"} == {("place_in", "green tray")}


RAMEKIN = view(
    bowl_near_ramekin=(0.5, 0.1, 0.03),
    black_bowl_near_ramekin=(0.5, 0.1, 0.03),
    bowl_next_to_ramekin=(0.5, 0.1, 0.03),
    ramekin=(0.5, 0.2, 0.02),
    plate=(0.6, -0.1, 0.01),
)


@pytest.mark.parametrize(
    ("text", "bowl"),
    [
        ("the black bowl adjacent to the ramekin, onto the plate please", "black bowl near ramekin"),
        ("put the bowl close to the ramekin on the plate", "bowl near ramekin"),
        ("the bowl near the ramekin is the one i want on the plate", "bowl near ramekin"),
        ("the bowl near the ramekin is what we need on the plate", "bowl near ramekin"),
        ("the ramekin has a bowl next to it - put that bowl on the plate", "bowl next to ramekin"),
    ],
)
def test_a_thing_named_by_where_it_stands_in_other_words(text, bowl):
    result = plan(text, RAMEKIN)
    assert result.ok, result.error
    assert leaves(result)[:2] == [("pick", bowl), ("place", "plate")]


BLOCKS = view(red=(0.5, 0.1, 0.02), green=(0.5, 0.0, 0.02), blue=(0.5, -0.1, 0.02))


@pytest.mark.parametrize(
    "text",
    [
        "I want a stack with blue at the base, then green, then red",
        "make a tower, blue at the bottom, then green, red last",
        "i'd like a three-block tower with blue at the bottom, green in the middle and red on top",
    ],
)
def test_a_tower_said_as_a_wish_or_before_a_comma_is_stacked_from_the_bottom(text):
    result = plan(text, BLOCKS)
    assert result.ok, result.error
    stacks = [c["params"] for c in plan_to_dict(result.plan)["tree"]["children"] if c["type"] == "stack"]
    assert [(p["keypoint_label"], p["target_label"]) for p in stacks] == [("green", "blue"), ("red", "green")]


DRAWER = view(drawer=(0.6, 0.0, 0.1), drawer_handle=(0.5, 0.0, 0.1), red_block=(0.4, 0.1, 0.02))


@pytest.mark.parametrize(
    "text",
    [
        "get the drawer open and the red block in it",
        "have the drawer open and the red block inside it",
        "could you open up the drawer and stash the red block inside",
    ],
)
def test_a_drawer_opened_and_filled_in_one_breath(text):
    result = plan(text, DRAWER)
    assert result.ok, result.error
    assert [x for x in leaves(result) if x[0] != "go_home"][:3] == [
        ("open_drawer", "drawer handle"),
        ("pick", "red block"),
        ("place_in", "drawer"),
    ]


MUG = view(mug=(0.5, 0.1, 0.05), bowl=(0.5, -0.1, 0.03))


@pytest.mark.parametrize(
    "text",
    [
        "take the mug and pour what's in it into the bowl",
        "pour what is in the mug into the bowl",
        "get all the beads out of the mug and into the bowl",
        "take the beads from the mug into the bowl",
        "decant the beads into the bowl",
    ],
)
def test_what_a_container_holds_carried_elsewhere_is_poured(text):
    result = plan(text, MUG)
    assert result.ok, result.error
    assert ("pour", "bowl") in leaves(result)


ZONE = view(red_block=(0.5, 0.0, 0.02), green_area=(0.65, 0.0, 0.0))
STOVE = view(stove=(0.6, 0.0, 0.05), stove_knob=(0.5, 0.0, 0.05))


@pytest.mark.parametrize(
    "text",
    ["give the red block a push forward, into the green area", "push the red block forward, into the green area"],
)
def test_a_push_said_as_a_noun_or_with_its_place_after_a_comma(text):
    result = plan(text, ZONE)
    assert result.ok, result.error
    assert leaves(result)[0] == ("push_object", "red block")
    assert len([x for x in leaves(result) if x[0] == "push_object"]) == 1


def test_get_the_stove_going_after_a_polite_opening():
    result = plan("could you get the stove going", STOVE)
    assert result.ok, result.error
    assert leaves(result)[0] == ("turn_knob", "stove knob")


def test_the_thing_said_again_after_its_place_is_no_part_of_the_place():
    result = plan("pick up the red block, into the bowl with it", SCENE)
    assert result.ok, result.error
    assert leaves(result)[:2] == [("pick", "red block"), ("place_in", "bowl")]
    assert result.detail["understood"] == ["put obj=red block relation=in target=bowl"]  # the rule parse, as said


DRAWERS = view(top_drawer=(0.6, 0.0, 0.3), top_drawer_handle=(0.5, 0.0, 0.3), bowl=(0.4, 0.1, 0.03))


@pytest.mark.parametrize(
    "text",
    ["I'd like the bowl relocated into the uppermost drawer", "open the drawer at the top, then drop the bowl in"],
)
def test_the_top_drawer_in_other_words(text):
    result = plan(text, DRAWERS)
    assert result.ok, result.error
    assert [x for x in leaves(result) if x[0] != "go_home"][:3] == [
        ("open_drawer", "top drawer handle"),
        ("pick", "bowl"),
        ("place_in", "top drawer"),
    ]
