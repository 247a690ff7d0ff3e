"""A cabinet's drawer fronts seen as one region: "the top/middle/bottom drawer" is cut from it at the height of
its handle. Synthetic frame: a camera 10 cm above the floor looking along world +x at a cabinet face 1 m away
(1 px = 2 mm on the face; image row v is world height 0.1 - (v - 120) * 0.002 m)."""

from __future__ import annotations

import numpy as np

from spark_core.perception.frame import CameraFrame
from spark_core.perception.learned.layers import is_stacked, layer_mask

H, W = 240, 320


def _front_frame() -> CameraFrame:
    K = np.array([[500.0, 0, W / 2], [0, 500.0, H / 2], [0, 0, 1]])
    T = np.eye(4)
    T[:3, :3] = np.array([[0.0, 0, 1], [-1, 0, 0], [0, -1, 0]])  # camera x = -world y, y = -world z, z = world x
    T[2, 3] = 0.1
    return CameraFrame("front", np.zeros((H, W, 3), np.uint8), np.ones((H, W), np.float32), K, T)


def _row(z_m: float) -> int:
    return int(round(120 - (z_m - 0.1) / 0.002))


def _three_fronts_and_handles() -> tuple[np.ndarray, list[np.ndarray]]:
    """Three 7 cm drawer fronts from 0 to 21 cm as one mask, and a handle mask at the middle of each."""
    fronts = np.zeros((H, W), bool)
    fronts[_row(0.21) : _row(0.0), 100:220] = True
    handles = []
    for z in (0.035, 0.105, 0.175):
        m = np.zeros((H, W), bool)
        m[_row(z) - 3 : _row(z) + 3, 150:170] = True
        handles.append(m)
    return fronts, handles


def test_the_middle_drawer_is_the_band_around_the_middle_handle():
    frame = _front_frame()
    fronts, handles = _three_fronts_and_handles()
    middle = layer_mask(fronts, handles, "middle", frame)
    rows = np.nonzero(middle.any(1))[0]
    assert abs(rows.min() - _row(0.14)) <= 1 and abs(rows.max() - _row(0.07)) <= 1
    top = layer_mask(fronts, handles, "top", frame)
    assert abs(np.nonzero(top.any(1))[0].min() - _row(0.21)) <= 1  # up to the top front's edge
    assert not (top & middle).any()
    bottom = layer_mask(fronts, list(reversed(handles)), "bottom", frame)  # order of the handles does not matter
    assert abs(np.nonzero(bottom.any(1))[0].max() - (_row(0.0) - 1)) <= 1


def test_no_handle_no_layer_and_only_height_words_are_stacked():
    frame = _front_frame()
    fronts = np.zeros((H, W), bool)
    fronts[50:150, 100:220] = True
    assert layer_mask(fronts, [], "top", frame) is None
    assert is_stacked("top") and is_stacked("middle") and is_stacked("bottom")
    assert not is_stacked("left") and not is_stacked(None)


def test_the_learned_segmenter_answers_the_middle_drawer_with_its_layer(monkeypatch):
    """The drawer fronts seen as one instance and three handles: "drawer middle layer" (a LIBERO label) is the
    middle band, not the whole front."""
    from spark_core.perception.learned.categories import CATEGORY_INDEX
    from spark_core.perception.learned.segmenter import Instance, LearnedSegmenter

    frame = _front_frame()
    fronts, masks = _three_fronts_and_handles()
    handles = [Instance(CATEGORY_INDEX["drawer handle"], m, 0.98, "grey") for m in masks]
    seen = [Instance(CATEGORY_INDEX["drawer"], fronts, 0.97, "brown"), *handles]
    seg = LearnedSegmenter()
    monkeypatch.setattr(seg, "instances", lambda f: seen)
    (det,) = seg.segment(frame, ["drawer middle layer"])
    rows = np.nonzero(det.mask.any(1))[0]
    assert abs(rows.min() - _row(0.14)) <= 1 and abs(rows.max() - _row(0.07)) <= 1
    assert det.detail["layer"] == "middle"


def test_three_stacked_fronts_seen_as_one_region_are_three_drawer_instances():
    """The network paints the fronts as one drawer region; with a handle on each, `instances` gives three drawers,
    each the band round its own handle (the perception bench counted the one region as a miss of all three)."""
    from spark_core.perception.learned.categories import CATEGORY_INDEX
    from spark_core.perception.learned.segmenter import Instance, _drawers_apart

    frame = _front_frame()
    fronts, masks = _three_fronts_and_handles()
    handles = [Instance(CATEGORY_INDEX["drawer handle"], m, 0.98, "grey") for m in masks]
    apart = _drawers_apart([Instance(CATEGORY_INDEX["drawer"], fronts, 0.97, "brown"), *handles], frame)
    drawers = [i.mask for i in apart if i.category == CATEGORY_INDEX["drawer"]]
    assert len(drawers) == 3 and len(apart) == 6
    spans = sorted((int(np.nonzero(d.any(1))[0].min()), int(np.nonzero(d.any(1))[0].max())) for d in drawers)
    for (top, bottom), z_hi, z_lo in zip(spans, (0.21, 0.14, 0.07), (0.14, 0.07, 0.0)):
        assert abs(top - _row(z_hi)) <= 1 and abs(bottom - (_row(z_lo) - 1)) <= 1
    assert not (drawers[0] & drawers[1]).any() and int(sum(d.sum() for d in drawers)) == int(fronts.sum())
    one = _drawers_apart([Instance(CATEGORY_INDEX["drawer"], fronts, 0.97, "brown"), handles[0]], frame)
    assert len([i for i in one if i.category == CATEGORY_INDEX["drawer"]]) == 1  # one handle: one drawer
