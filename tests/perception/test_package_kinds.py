"""A package noun that is also a kind of thing ("bottle": a wine bottle is one) names the things said to come in that
very package as well (the ketchup and the salad dressing come in bottles), never what holds such packages (a wine
rack "holds bottles"); a word of the kind of a name's other word is that word ("vino" for the wine bottle); a thing
of no kind said by where it rests ("the thing on the stove") is only what rests there. Synthetic top-down frame as
in test_package_nouns.py."""

from __future__ import annotations

from spark_core.perception.naming import own_noun_prompts, package_members
from spark_core.perception.sim_segmenter import SimSegmenter
from tests.perception.test_package_nouns import _found, _frame

SAUCES = {"ketchup": (-30, 20), "salad dressing": (-10, -20), "milk": (10, 20), "basket": (30, -20)}


def test_a_bottle_is_a_bottled_product_when_no_thing_is_named_bottle():
    seg = SimSegmenter({name: name for name in SAUCES})
    frame = _frame(SAUCES)
    assert _found(seg, frame, "bottle") == {"ketchup", "salad dressing"}
    assert _found(seg, frame, "nearest bottle") == {"ketchup"}  # 30 cm behind the camera's centre, the other 10
    assert _found(seg, frame, "farthest bottle") == {"salad dressing"}
    assert _found(seg, frame, "the carton") == {"milk"}


def test_a_thing_named_by_the_kind_stays_a_bottle_and_a_rack_of_bottles_is_none():
    catalog = {
        "wine bottle": "dark glass wine bottle with a long neck",
        "wine rack": "metal wine rack, a stand that holds bottles",
        "plate": "flat round ceramic plate",
    }
    seg = SimSegmenter(catalog)
    frame = _frame({"wine bottle": (-20, 0), "wine rack": (20, 0), "plate": (0, 30)})
    assert _found(seg, frame, "bottle") == {"wine bottle"}
    assert _found(seg, frame, "vino") == {"wine bottle"}  # "vino" is a word of the wine's kind


def test_package_members_of_a_kind_word_need_the_package_said_of_the_thing():
    descriptions = ["squeeze bottle of tomato ketchup", "metal wine rack, a stand that holds bottles", "carton of milk"]
    assert package_members("bottle", descriptions) is None  # a kind: not without kind_too
    assert package_members("bottle", descriptions, kind_too=True) == {0}
    assert package_members("jar", descriptions, kind_too=True) is None  # no jar of anything, and no alike package
    assert own_noun_prompts("the vino", ["wine bottle", "plate"]) == {0: "the wine"}


def test_a_thing_of_no_kind_on_a_place_is_only_what_rests_there():
    """ "thing on plate" with nothing resting on the plate: nothing, not the thing nearest the plate (a bowl of a kind
    said keeps nearness: "bowl on plate" of two bowls is the nearer)."""
    catalog = {"bowl": "black bowl", "bowl 2": "black bowl", "plate": "flat plate", "cup": "white cup"}
    frame = _frame({"bowl": (-20, 0), "bowl 2": (-40, 30), "plate": (25, 0), "cup": (30, 25)})
    seg = SimSegmenter(catalog)
    assert _found(seg, frame, "thing on plate") == set()
    assert _found(seg, frame, "bowl on plate") == {"bowl"}
