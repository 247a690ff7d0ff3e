"""Round 35: general mechanisms found in the read probes (probe45's leftovers, probe46), each tested on other things
and wording than where it was found."""

import pytest

from tests.planning.scene_views import leaves, plan, view
from tests.planning.test_rules_round28 import read


@pytest.mark.parametrize(
    ("text", "clauses"),
    [
        # a request taken back and said again with another verb: the second one stands; "it" is what the first
        # acted on
        ("shut the drawer, no wait, i mean open it", ["open obj=drawer"]),
        ("put the lemon in the bowl, sorry, put it on the tray", ["put obj=lemon relation=on target=tray"]),
        ("push the pear to the left, scratch that, push it to the right", ["push obj=pear direction=right"]),
        ("lift the mug. actually, put it in the sink", ["put obj=mug relation=in target=sink"]),
        # "sorry" with nothing before it takes nothing back
        ("sorry, open the drawer", ["open obj=drawer"]),
        # a contrast after the goal, with the sentence's end mark, rules out one of the object's kind
        (
            "the cup on the shelf goes in the sink, not the one on the tray.",
            ["put obj=cup not on tray on shelf relation=in target=sink"],
        ),
        ("put the jar on the shelf, not the one by the sink!", ["put obj=jar not by sink relation=on target=shelf"]),
        # a thing said first without its article, however long, then a request on "it": the thing is the topic
        (
            "top drawer of the dresser, open it",
            ["mention obj=dresser top drawer", "open obj=dresser top drawer"],
        ),
        (
            "green apple next to the sink, put it in the basket please",
            ["mention obj=green apple next to sink", "put obj=green apple next to sink relation=in target=basket"],
        ),
        # ... but a word of assent or address is no thing
        ("okay, open it", ["open obj=it"]),
        # an ordinal only counted the thing as another of its kind when an apposition then says where it is
        ("the second mug, the one closer to you, goes in the sink", ["put obj=nearest mug relation=in target=sink"]),
        ("put the second cup, the one on the tray, in the sink", ["put obj=cup on tray relation=in target=sink"]),
        ("the other jar, the one on the left, goes on the shelf", ["put obj=leftmost jar relation=on target=shelf"]),
        # an apposition between dashes, or after one at the sentence's end, is one between commas; "the taller of
        # the two mugs" is "the taller one"
        ("grab the pear on the left - the yellow one.", ["pick obj=leftmost yellow pear"]),
        (
            "take the mug next to the kettle - the taller of the two mugs - and put it in the sink",
            ["pick obj=mug next to kettle", "put obj=mug next to kettle relation=in target=sink"],
        ),
        # an apposition naming a class the thing falls under only says what sort of thing it is
        ("put the ketchup bottle - the condiment - in the crate", ["put obj=ketchup bottle relation=in target=crate"]),
        # where the thing is, said between commas with a participle or "between"
        (
            "of the two cups, take the nearer one, standing on the tray, and put it in the sink",
            ["pick obj=nearest cup on tray", "put obj=nearest cup on tray relation=in target=sink"],
        ),
        (
            "of the two mugs, take the farther one, between the kettle and the sink, and put it on the tray",
            ["pick obj=mug between kettle and sink", "put obj=mug between kettle and sink relation=on target=tray"],
        ),
        # interjections, particles and chat spellings say nothing of what is done
        ("psst, put the pear in the bowl", ["put obj=pear relation=in target=bowl"]),
        ("put the apple in the crate lah", ["put obj=apple relation=in target=crate"]),
        ("yo can u put the mug on the tray fr", ["put obj=mug relation=on target=tray"]),
        # a drawer eased shut, yanked open
        ("ease the drawer shut", ["close obj=drawer"]),
        ("yank open the drawer", ["open obj=drawer"]),
        # how it is done: an adverb before the verb or alone at the end, a comparison, a stage direction
        ("softly place the egg in the bowl, very carefully", ["put obj=egg relation=in target=bowl"]),
        ("put the mug in the sink, as you would a glass", ["put obj=mug relation=in target=sink"]),
        ("(humming) put the pear in the bowl", ["put obj=pear relation=in target=bowl"]),
        # urging before the request; "there" after a thing pointed at
        (
            "come on, open that drawer there and put the pear in it",
            ["open obj=drawer", "put obj=pear relation=in target=drawer"],
        ),
        # a thing said first, then a carry that says only where
        ("the lemon, drop into the bowl", ["mention obj=lemon", "put obj=lemon relation=in target=bowl"]),
        # a request made on the state it changes is the request
        ("if the oven is on, turn it off", ["turn off obj=oven"]),
        # a word broken off and taken back
        ("put the green cu- sorry, the red cube on the plate", ["put obj=red cube relation=on target=plate"]),
        # "shall be", "and nothing more", who the list is for, a bullet
        ("the pear shall be put in the bowl", ["put obj=pear relation=in target=bowl"]),
        ("put the pear in the bowl, and nothing more", ["put obj=pear relation=in target=bowl"]),
        ("note for the robot: put the pear in the bowl", ["put obj=pear relation=in target=bowl"]),
        ("- pick up the pear - put it in the bowl", ["pick obj=pear", "put obj=pear relation=in target=bowl"]),
        # holding still after a lift; up toward the ceiling is up
        ("raise the mug toward the ceiling. hold it there for a moment.", ["pick obj=mug"]),
        # a thing pointed out first, then "it" where another thing is
        ("see the kettle? the mug next to it goes in the sink", ["put obj=mug next to kettle relation=in target=sink"]),
        # a parenthesis that says what sort of thing it is and rules another thing out
        (
            "push the butter (the small package, not the jar) to the left",
            ["mention obj=jar", "push obj=butter direction=left"],
        ),
    ],
)
def test_wordings_of_round_35_read_as_meant(text, clauses):
    assert read(text) == clauses


def test_a_carry_keeps_there_as_its_place():
    """ "put that cup there": "there" is where the carry goes, not a word of pointing."""
    assert read("go on, put that cup there") == read("put that cup there")


def test_a_word_of_address_before_a_carry_is_no_thing():
    assert read("okay, put it in the bowl") == ["put obj=it relation=in target=bowl"]


def test_a_hesitation_takes_nothing_back():
    """ "um" is no correction: both requests stand."""
    assert len(read("open the drawer. um, put the pear in it")) == 2


def test_a_drawer_opened_twice_by_two_names_is_opened_once():
    """The request said again with another name perception resolved to the same handle: one opening."""
    scene = view(
        drawer=(0.7, 0.2, 0.07),
        drawer_handle=(0.65, 0.2, 0.09),
        cabinet_drawer=(0.7, 0.2, 0.07),
        cabinet_drawer_handle=(0.65, 0.2, 0.09),
    )
    result = plan("open the drawer. then open the cabinet drawer.", scene)
    assert result.ok, result.error
    assert [p for p, _ in leaves(result)].count("open_drawer") == 1


def test_two_drawers_opened_one_after_the_other_stay_two_steps():
    scene = view(
        top_drawer=(0.7, 0.2, 0.2),
        top_drawer_handle=(0.65, 0.2, 0.2),
        bottom_drawer=(0.7, 0.2, 0.05),
        bottom_drawer_handle=(0.65, 0.2, 0.05),
    )
    result = plan("open the top drawer. then open the bottom drawer.", scene)
    assert result.ok, result.error
    assert [p for p, _ in leaves(result)].count("open_drawer") == 2


def test_a_remark_about_people_is_set_aside_but_not_one_about_a_thing():
    """A trailing remark whose noun names a person ("nobody wake up") names no thing the scene must hold; one
    naming a thing the scene lacks still refuses."""
    people = view(pear=(0.5, 0.0, 0.0), bowl=(0.4, 0.2, 0.0), unresolved={"nobody wake up": "none found"})
    result = plan("put the pear in the bowl, nobody wake up.", people)
    assert result.ok, result.error
    assert leaves(result)[0] == ("pick", "pear")
    thing = view(pear=(0.5, 0.0, 0.0), bowl=(0.4, 0.2, 0.0), unresolved={"dirty spoon": "none found"})
    refused = plan("put the pear in the bowl, the spoon is dirty.", thing)
    assert not refused.ok
    assert "spoon" in refused.error
