"""Round 41: general mechanisms found in probe57 (read in round 40), each tested on other things and wording than
where it was found."""

import pytest

from spark_core.planning.rules.descriptions import descriptions
from tests.planning.scene_views import leaves, plan, view
from tests.planning.test_rules_round28 import read


def _mugs():
    where = {"mug": (0.5, -0.2, 0.05), "tray": (0.6, 0.2, 0.01), "green block": (0.4, 0.1, 0.03)}
    return view(inventory=("mug", "tray", "green block"), **where)


@pytest.mark.parametrize(
    ("text", "thing"),
    [
        ("the mug in the gripper", "mug"),
        ("the mug in the robot's hand.", "mug"),
        ("the mug clear of the table", "mug"),
        ("the mug off the table.", "mug"),
        ("mug held in the gripper, clear of the table", "mug"),
        ("I'd like the mug clear of the surface", "mug"),
        ("the green block up in the gripper, well clear of the tabletop", "green block"),
        ("i want the green block up in the gripper", "green block"),  # "block" is no verb here
        ("What I'm hoping to see is the green block up in the gripper.", "green block"),
    ],
)
def test_a_thing_said_to_be_in_the_gripper_or_off_the_table_is_lifted(text, thing):
    result = plan(text, _mugs())
    assert result.ok, result.error
    assert [p for p, _ in leaves(result)] == ["pick"] and leaves(result)[0][1] == thing


def test_a_thing_said_to_be_on_or_in_another_is_still_carried_there():
    assert read("the mug on the tray") == ["put obj=mug relation=on target=tray"]
    # "held" dropped before "in" keeps the space before it (had read "mugin the tray")
    assert read("the mug held in the tray") == ["put obj=mug relation=in target=tray"]


@pytest.mark.parametrize(
    "text",
    [
        "what we're after is the mug on the tray",
        "What I'd like to see is the mug on the tray.",
        "Final state we want: the mug on the tray.",
        "end result i'm after: the mug on the tray",
    ],
)
def test_a_goal_labelled_as_the_speakers_wish_is_the_goal(text):
    assert read(text) == ["put obj=mug relation=on target=tray"]


@pytest.mark.parametrize(
    ("text", "aside"),
    [
        ("Put the mug on the tray. It keeps catching my sleeve every time I walk past.", "It keeps catching"),
        ("Put the mug on the tray. I don't really care how you get there.", "I don't really care"),
        ("Mug on the tray. Doesn't matter which way round.", "Doesn't matter"),
        ("Put the mug on the tray. Either way is fine.", "Either way"),
    ],
)
def test_a_remark_about_the_speakers_own_things_or_what_does_not_matter_is_set_aside(text, aside):
    kept, said = descriptions(text, ["mug", "tray"])
    assert len(said) == 1 and said[0].startswith(aside) and aside not in kept
    result = plan(text, _mugs())
    assert result.ok, result.error
    assert [p for p, _ in leaves(result)] == ["pick", "place"]


@pytest.mark.parametrize(
    "text",
    [
        "Put the mug on the tray. It keeps catching the banana every time I walk past.",  # not the speaker's
        "Put the mug on the tray. I don't care where the banana goes.",
        "Put the mug on the tray. Then the banana, either way is fine.",
    ],
)
def test_a_thing_the_scene_lacks_in_such_a_remark_is_still_refused(text):
    assert not plan(text, _mugs()).ok
