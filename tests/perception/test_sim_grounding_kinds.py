"""`sim` grounding refuses near matches: a prompt that names another kind, colour, shape or distinguishing word
than an object has does not ground to it, however close the sentence encoder puts the two; adaptive prompt
variants never widen a label into a word that also names something else."""

import pytest

from spark_core.perception.sim_segmenter import SimSegmenter, mismatch
from spark_core.perception.variants import prompt_variants

GROCERIES = {  # a LIBERO-object-like scene: no ketchup, no bbq sauce
    "alphabet soup": "alphabet soup",
    "basket": "basket",
    "butter": "butter",
    "milk": "milk",
    "tomato sauce": "tomato sauce",
    "cream cheese": "cream cheese",
}
KITCHEN = {
    "cabinet": "brown wooden cabinet with one drawer",
    "cabinet drawer": "the cabinet's sliding drawer",
    "cabinet drawer handle": "metal handle on the cabinet drawer",
    "stove": "grey electric stove (cooktop) with a black burner",
    "green area": "flat green square target area marked on the table",
    "basket": "brown woven wicker basket, square and deep",
    "plate": "flat round white ceramic plate",
}


@pytest.mark.parametrize(
    "prompt,name,description,why",
    [
        ("ketchup", "butter", "butter", "kind"),
        ("butter", "milk", "milk", "kind"),
        ("bbq sauce", "tomato sauce", "tomato sauce", "sauce: bbq vs tomato"),
        ("hexagonal bolt", "square nut", "brass square nut", "shape"),
        ("blue area", "green area", KITCHEN["green area"], "colour"),
        ("the green wooden cube", "red block", "small red wooden cube block", "colour"),  # wooden is no colour
        ("oven door handle", "cabinet drawer handle", KITCHEN["cabinet drawer handle"], "kind"),
        ("bowl", "plate", KITCHEN["plate"], "kind"),
        # the mention's head noun decides what it is: a modifier naming the object is not enough ...
        ("wine glass", "wine bottle", "wine bottle", "kind"),
        ("salad", "salad dressing", "salad dressing", "noun: salad"),
        ("tomato", "tomato sauce", "tomato sauce", "noun: tomato"),
        # ... a package or part noun needs a modifier the object has; an unknown noun, the encoder's nearness
        ("soda can", "ketchup", "ketchup", "kind"),
        ("cardboard box", "basket", KITCHEN["basket"], "noun: cardboard box"),
        ("red ball", "red block", "small red wooden cube block", "kind"),
        ("red pen", "red block", "small red wooden cube block", "kind"),
        ("cutting board", "plate", KITCHEN["plate"], "noun: board"),
        ("beer bottle", "wine bottle", "wine bottle", "kind"),
        ("sake bottle", "wine bottle", "wine bottle", "bottle: sake vs wine"),
        ("shoe rack", "wine rack", "wine rack", "rack: shoe vs wine"),
    ],
)
def test_a_prompt_that_contradicts_the_object_does_not_match_it(prompt, name, description, why):
    assert why in (mismatch(prompt, name, description) or "")


@pytest.mark.parametrize(
    "prompt,name,description",
    [
        ("wicker hamper", "basket", KITCHEN["basket"]),  # a synonym
        ("burner", "flat stove", "flat stove"),
        ("stove knob", "flat stove", "flat stove"),  # a stove without a separate knob: the stove itself
        ("the burner plate", "stove", KITCHEN["stove"]),  # the object's own noun, then a part of it
        ("milk carton", "milk", "milk"),  # a container named for its contents
        ("cookie box", "cookies", "cookies"),
        ("the white dish bowl", "bowl", "white ceramic bowl, round and open"),  # dish: a wider word
        ("reddest block", "red block", "small red wooden cube block"),
        ("electric stove", "flat stove", "flat stove"),  # attributes the object does not contradict
        ("coffee cup", "mug", "red ceramic mug with a handle, cylindrical cup"),
        ("ketchup bottle", "ketchup", "ketchup"),  # a package named by its contents
        ("soup can", "alphabet soup", "alphabet soup"),
        ("cream cheese box", "cream cheese", "cream cheese"),
        ("biscuit box", "cookies", "cookies"),  # the modifier by another word of its kind
        ("butter stick", "butter", "butter"),  # a portion is named like a package
        ("wine", "wine bottle", "wine bottle"),  # the contents of a bottle name the bottle
        ("cooker", "stove", KITCHEN["stove"]),  # an unknown noun the encoder puts near the object's own
        ("the red thing", "red block", "small red wooden cube block"),  # a generic noun claims no kind
        ("cabinet top", "wooden cabinet", "wooden cabinet"),  # a part noun through its owner
        ("the bowl inside", "akita black bowl", "akita black bowl"),  # a last word that is no noun
    ],
)
def test_synonyms_containers_and_compatible_attributes_still_match(prompt, name, description):
    assert mismatch(prompt, name, description) is None


def test_absent_groceries_ground_to_nothing_present_ones_to_themselves():
    seg = SimSegmenter(GROCERIES)

    def grounded(prompt):
        sims = seg.similarities(prompt)
        best = max(sims.values())
        return sorted(k for k, v in sims.items() if v >= seg.threshold and v >= best - seg.margin)

    for absent in ("ketchup", "bbq sauce", "chocolate pudding", "orange juice"):
        assert grounded(absent) == [], absent
    assert grounded("butter") == ["butter"] and grounded("the tomato sauce") == ["tomato sauce"]
    assert grounded("milk carton") == ["milk"]


def test_a_part_noun_names_the_part_when_perception_has_one():
    seg = SimSegmenter(KITCHEN)
    sims = seg.similarities("the handle of the drawer")
    assert max(sims, key=sims.__getitem__) == "cabinet drawer handle"
    assert sims["cabinet drawer"] < seg.threshold  # the drawer is no handle when a handle is there


@pytest.mark.parametrize("label", ["bbq sauce", "blue area", "black bowl", "oven door handle", "bowl"])
def test_variants_never_drop_a_word_or_widen_the_noun(label):
    variants = prompt_variants(label, 3)
    assert label not in variants
    for v in variants:
        assert len(v.split()) >= len(label.split()), v
    assert not any(v.split()[-1] == "dish" for v in prompt_variants("bowl", 3))
