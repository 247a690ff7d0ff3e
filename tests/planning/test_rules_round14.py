"""Round fourteen of the rules planner (issue 18): a mention grounds to a scene thing only when nothing in its words
names another product. The sim segmenter's label matching (perception/sim_segmenter.py `mismatch`) now refuses a
food or drink named by its own noun with a noun before it that the object lacks ("peanut butter" is not the
butter, "almond milk" not the milk) unless the sentence encoder puts the phrase at the object's name ("tomato
ketchup"), and a package noun of another kind than the one the object is or comes in
("cookie jar" is not the cookies its description says come in a box). Before, both grounded, and an instruction
naming a thing the scene does not hold was planned. The refusal tests fail without the mechanism they name.

(Examples are written for these tests; none comes from data/wording/.)"""

import pytest

from spark_core.perception.naming import mismatch


# -- a food named with a noun before it that the object lacks is another product ------------------------------------
@pytest.mark.parametrize(
    ("prompt", "name", "description"),
    [
        ("peanut butter", "butter", "butter"),
        ("almond milk", "milk", "milk"),
        ("the soy milk", "milk", "milk"),
    ],
)
def test_a_food_named_with_another_noun_before_it_is_another_product(prompt, name, description):
    assert mismatch(prompt, name, description) is not None


@pytest.mark.parametrize(
    ("prompt", "name", "description"),
    [
        ("butter", "butter", "butter"),
        ("salted butter", "butter", "butter"),  # a describing word, no other product
        ("fresh milk", "milk", "milk"),
        ("tomato ketchup", "ketchup", "ketchup"),  # what it is made of: the encoder puts it at the ketchup
        ("cow milk", "milk", "milk"),  # where it comes from
        ("carton of milk", "milk", "milk"),
        ("small butter", "butter", "butter"),
    ],
)
def test_the_same_food_with_describing_words_or_its_own_words_still_grounds(prompt, name, description):
    assert mismatch(prompt, name, description) is None


# -- a package of another kind than the object's is another product ------------------------------------------------
@pytest.mark.parametrize(
    ("prompt", "name", "description"),
    [
        ("cookie jar", "cookies", "rectangular cardboard box of cookies"),
        ("ketchup jar", "ketchup", "squeeze bottle of tomato ketchup"),
        ("butter tub", "butter", "small carton of butter"),
    ],
)
def test_a_package_of_another_kind_is_another_product(prompt, name, description):
    assert mismatch(prompt, name, description) is not None


@pytest.mark.parametrize(
    ("prompt", "name", "description"),
    [
        ("cookie carton", "cookies", "rectangular cardboard box of cookies"),  # a box by another name
        ("ketchup bottle", "ketchup", "squeeze bottle of tomato ketchup"),
        ("butter box", "butter", "small carton of butter"),
        ("cookie container", "cookies", "rectangular cardboard box of cookies"),  # claims no kind of package
        ("cookie tin", "cookies", "rectangular cardboard box of cookies"),  # a tin may be a box
    ],
)
def test_a_package_of_the_objects_own_kind_still_grounds(prompt, name, description):
    assert mismatch(prompt, name, description) is None
