"""_grow_into works inside the bounding box of the region and the labelled pixels: the same labels as growing over
the whole frame (the way it was done before), for regions and labels anywhere, including at the frame's edges."""

import cv2
import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from spark_core.perception.learned.segmenter import _grow_into


def _whole_frame(comp: np.ndarray, region: np.ndarray, iterations: int = 4) -> np.ndarray:
    comp = comp.astype(np.int32)
    kernel = np.ones((3, 3), np.uint8)
    for _ in range(iterations):
        free = region & (comp == 0)
        if not free.any():
            break
        grown = cv2.dilate(comp.astype(np.float32), kernel).astype(np.int32)
        comp = np.where(free & (grown > 0), grown, comp)
    return comp


@settings(max_examples=200, deadline=None)
@given(
    seed=st.integers(0, 2**32 - 1),
    h=st.integers(1, 40),
    w=st.integers(1, 40),
    fill=st.floats(0.0, 0.9),
    inside_only=st.booleans(),  # the callers' case: components cut from the region itself
)
def test_the_same_labels_as_growing_over_the_whole_frame(seed, h, w, fill, inside_only):
    rng = np.random.default_rng(seed)
    region = np.zeros((h, w), bool)
    r0, c0 = rng.integers(0, h), rng.integers(0, w)
    region[r0 : r0 + rng.integers(1, h + 1), c0 : c0 + rng.integers(1, w + 1)] = True
    region &= rng.random((h, w)) < 0.95
    cut = rng.random((h, w)) < 0.3  # boundary pixels the network marked
    n, comp = cv2.connectedComponents(((region if inside_only else rng.random((h, w)) < fill) & ~cut).astype(np.uint8))
    before = comp.copy()
    np.testing.assert_array_equal(_grow_into(comp, region), _whole_frame(comp, region))
    np.testing.assert_array_equal(comp, before)  # the caller's labels are not changed in place


def test_an_empty_frame_stays_empty():
    comp, region = np.zeros((5, 6), np.int32), np.zeros((5, 6), bool)
    assert not _grow_into(comp, region).any()
