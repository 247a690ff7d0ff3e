"""Round 31: general mechanisms found in the read probe39, each tested on other things and wording than where it
was found."""

import pytest

from tests.planning.scene_views import leaves, plan, view
from tests.planning.test_rules_round28 import read


@pytest.mark.parametrize(
    ("text", "clauses"),
    [
        # a thing's own place said with a possessive determiner: the place, not a part of the thing
        ("set the mug back on its saucer", ["put obj=mug relation=on target=saucer"]),
        ("the ketchup belongs in their basket", ["put obj=ketchup relation=in target=basket"]),
        # a reason that asks for nothing, then the request after "so"
        (
            "the table is a mess, so i would like the apple moved into the bowl",
            ["put obj=apple relation=in target=bowl"],
        ),
        # the reason names the thing the request acts on through a pronoun
        ("the bowl is dirty, so scrub it with the sponge", ["scrub target=bowl tool=sponge"]),
        ("the drawer is open, so shut it", ["close obj=drawer"]),
        # "so" of degree in a courtesy is no purpose
        ("if you would be so kind, move the red block onto the plate", ["put obj=red block relation=on target=plate"]),
        # the action said as the -ing noun of a verb the planner knows
        ("give the table a good wiping with the cloth", ["scrub target=table tool=cloth"]),
        # asking leave to ask
        ("may i ask you to turn the stove off", ["turn off obj=stove"]),
        # a wish said with "appreciate", where the thing goes said as it going there
        ("i would appreciate the butter going into the basket", ["put obj=butter relation=in target=basket"]),
        # the speakers' doing, or what happens otherwise, after the request
        ("put the apple in the bowl, we are cooking for friends", ["put obj=apple relation=in target=bowl"]),
        ("put the mug on the rack, otherwise it gets knocked over", ["put obj=mug relation=on target=rack"]),
        # a container said to hold small things, then poured through a pronoun
        (
            "the bowl has some tiny beads in it. tip them into the plate",
            ["mention obj=bowl", "pour obj=bowl target=plate source=bowl"],
        ),
        # an extreme "on the table": the extreme says which, not the lowest one
        (
            "take the block farthest back on the table and put it on the plate",
            ["pick obj=farthest block", "put obj=farthest block relation=on target=plate"],
        ),
        ("whichever one is nearest to you, put it in the tray", ["put obj=nearest thing relation=in target=tray"]),
        # "that is what goes in ..." after a sentence naming the thing; a cleft with "the one that goes"
        (
            "not the pear, the apple. that is what goes in the bowl",
            ["mention obj=pear", "mention obj=apple", "put obj=apple relation=in target=bowl"],
        ),
        ("the yellow block is the one that goes in the tray", ["put obj=yellow block relation=in target=tray"]),
    ],
)
def test_round31_wording_reads_as_its_plain_form(text, clauses):
    assert read(text) == clauses


def test_a_part_said_with_its_keeps_naming_the_part():
    # "its lid" is a part of the thing before, not a thing of its own to look up as "lid"
    assert read("put the pot on the stove and take off its lid") != read("put the pot on the stove and take off lid")


def test_the_speakers_doing_followed_by_another_step_is_kept():
    # "... and the pear too" may ask for a pear: the clause stays and must be found
    clauses = read("put the apple in the bowl, we are cooking for friends and the pear too")
    assert any("pear" in c for c in clauses)


def test_a_possessive_place_the_scene_lacks_is_refused():
    scene = view(mug=[0.5, 0.0, 0.05], unresolved={"its shelf": "none found"}, inventory=("mug", "saucer"))
    result = plan("put the mug back on its shelf", scene)
    assert not result.ok and "shelf" in result.error


def test_a_reason_first_then_a_request_plans_the_request():
    scene = view(apple=[0.5, 0.1, 0.05], bowl=[0.5, -0.1, 0.05])
    result = plan("the counter is cluttered, so i would like the apple moved into the bowl", scene)
    assert result.ok, result.error
    assert leaves(result) == [("pick", "apple"), ("place_in", "bowl")]
