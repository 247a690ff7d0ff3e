"""Round 40: a colour said of a wide word ("the black dish") picks the object whose name says that colour over one
whose name says none (the sim segmenter, PRIVILEGED: it reads names, not pixels)."""

from __future__ import annotations

from spark_core.perception.sim_segmenter import SimSegmenter

CATALOG = {"akita_black_bowl_1": "akita black bowl", "plate_1": "plate", "wine_bottle_1": "wine bottle"}


def _matches(segmenter: SimSegmenter, prompt: str) -> set[str]:
    scores = segmenter.similarities(prompt)
    return {label for label, c in scores.items() if c >= segmenter.threshold}


def test_a_colour_said_of_a_wide_word_picks_the_thing_named_in_it():
    segmenter = SimSegmenter(CATALOG)
    assert _matches(segmenter, "dish") >= {"akita_black_bowl_1", "plate_1"}  # the wide word alone: both
    assert _matches(segmenter, "black dish") == {"akita_black_bowl_1"}


def test_a_colour_no_match_says_leaves_the_colourless_thing():
    """ "the white plate": the only thing of that kind says no colour, and no other match says white: kept."""
    segmenter = SimSegmenter(CATALOG)
    assert "plate_1" in _matches(segmenter, "white plate")
