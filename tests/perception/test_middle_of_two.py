"""'The middle bowl' of two on a table (no median of two) is the one nearer the middle of everything on the table,
for the sim oracle (from its object ids) and the camera-only segmenter (from the instances it sees) alike."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from spark_core.perception.learned.categories import CATEGORY_INDEX
from spark_core.perception.learned.segmenter import Instance, LearnedSegmenter
from spark_core.perception.sim_segmenter import SimSegmenter
from tests.perception.test_package_nouns import _found, _frame

CATALOG = {
    "black bowl": "black ceramic bowl",
    "black bowl 2": "black ceramic bowl",
    "plate": "flat round white plate",
    "cabinet": "brown wooden cabinet",
    "stove": "grey electric stove",
}
# the first bowl 4 cm from the middle of the five things, the second 38 cm
WHERE = {"black bowl": (2, -3), "black bowl 2": (-25, 30), "plate": (25, 10), "cabinet": (-20, -30), "stove": (10, 25)}


@pytest.mark.parametrize("prompt", ["middle bowl", "centre bowl", "the center black bowl"])
def test_the_sim_oracle_takes_the_bowl_nearer_the_tables_middle(prompt):
    seg = SimSegmenter(CATALOG)
    frame = _frame(WHERE)
    assert _found(seg, frame, prompt) == {"black bowl"}
    assert _found(seg, frame, "bowl not middle") == {"black bowl 2"}


def test_the_camera_only_segmenter_takes_the_same_bowl(monkeypatch):
    """Its instances stubbed (as its network would find them in this frame): the middle of what it sees decides."""
    frame = _frame(WHERE)
    assert frame.object_ids is not None
    kinds = {"black bowl": "bowl", "black bowl 2": "bowl", "plate": "plate", "cabinet": "cabinet", "stove": "stove"}
    instances = [
        Instance(CATEGORY_INDEX[kinds[label]], frame.object_ids == i, 0.9, "black" if "bowl" in label else "none")
        for i, label in frame.labels.items()
    ]
    camera_only = dataclasses.replace(frame, object_ids=None, labels={})  # what it is given: no ids
    seg = LearnedSegmenter()
    monkeypatch.setattr(seg, "instances", lambda f: instances)
    picked = seg.segment(camera_only, ["middle bowl"])
    assert len(picked) == 1
    assert np.array_equal(picked[0].mask, frame.object_ids == 1)  # "black bowl", id 1
