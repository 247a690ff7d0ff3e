"""Noun phrases by their words alone: what observe looks for when no reading of a sentence gives it anything."""

import pytest

from spark_core.planning.observe import phrases_for
from spark_core.planning.rules.chunks import noun_chunks


@pytest.mark.parametrize(
    ("text", "chunks"),
    [
        ("my plate is missing its bowl", ["plate", "bowl"]),
        ("what about the bowl on the plate", ["bowl", "plate"]),
        ("both black bowls near the cream cheese box", ["black bowl", "cream cheese box"]),
        ("alphabet soup and tomato sauce into the basket", ["alphabet soup", "tomato sauce", "basket"]),
        ("the akita black bowl: plate, now", ["akita black bowl", "plate"]),
        ("the wine bottle's spot is the cabinet top", ["wine bottle", "cabinet"]),
        ("make the red block fly", ["red block"]),  # the request's verb is no thing, though the lexicon lists it
    ],
)
def test_each_thing_is_named_with_the_words_before_it_in_the_singular(text, chunks):
    assert noun_chunks(text) == chunks


def test_a_sentence_no_reading_looks_into_has_its_noun_phrases_looked_for():
    assert phrases_for("what about the bowl on the plate") == ["bowl", "plate"]
