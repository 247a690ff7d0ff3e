"""Noun phrases by their words alone: what observe looks for when no reading of a sentence gives it anything."""

import numpy as np
import pytest

from spark_core.perception import Keypoint, LabelNotFound
from spark_core.planning.observe import observe, phrases_for
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


class _Finder:
    """A resolver that finds a thing by its exact name and remembers what it was asked for."""

    def __init__(self, names: set[str]):
        self.names = names
        self.asked: list[str] = []

    def resolve(self, label: str) -> Keypoint:
        self.asked.append(label)
        if label not in self.names:
            raise LabelNotFound(label)
        return Keypoint(label, np.zeros(3), np.full(3, 0.05))


def test_observe_also_looks_for_every_thing_the_sentence_names_by_a_noun():
    # the rules read "bowl time" as one phrase; the bowl is still looked for, on its own
    finder = _Finder({"red block", "bowl"})
    seen = observe("grab red block, bowl time", finder)
    assert "bowl" in finder.asked and "bowl" in seen.keypoints and "bowl time" in seen.unresolved
    assert len(finder.asked) == len(set(finder.asked))  # each phrase once
