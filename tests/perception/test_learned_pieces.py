"""Pieces too small for their kind that stand on another object join it (learned/pieces.py, the segmenter's
_absorb_pieces): synthetic frames from a camera 1 m above a floor looking straight down (1 px = 2 mm)."""

from __future__ import annotations

import numpy as np
import pytest

from spark_core.perception.learned.categories import CATEGORY_INDEX
from spark_core.perception.learned.pieces import support_of, world_points
from spark_core.perception.learned.segmenter import Instance, _absorb_pieces
from tests.perception.test_learned_geometry import H, W, _frame


def _stove_with_fin() -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """A 4 cm tall slab (a flat stove, 20 x 16 cm) with a fin 4 cm tall and 2 cm long standing at its edge. Its
    depth runs from its base to its top along the rows, as a side seen at an angle does (the real cameras look
    down at about 45 degrees; this one looks straight down)."""
    depth = np.ones((H, W))
    depth[60:140, 100:200] = 0.96
    fin = np.zeros((H, W), bool)
    fin[56:66, 96:103] = True  # over the slab's corner and a little past it
    depth[56:66, 96:103] = np.linspace(0.955, 0.92, 10)[:, None]
    slab = (depth < 0.97) & ~fin
    return depth, slab, fin


def test_an_undersized_piece_on_an_object_is_part_of_it():
    depth, slab, fin = _stove_with_fin()
    frame = _frame(depth)
    assert support_of(fin, [slab], frame, min_extent_m=0.10) == 0
    # the same piece, large enough for its kind, is an object of its own
    assert support_of(fin, [slab], frame, min_extent_m=0.01) is None


def test_a_piece_beside_an_object_or_far_above_it_stays_apart():
    depth, slab, _ = _stove_with_fin()
    beside = np.zeros((H, W), bool)
    beside[100:110, 202:210] = True  # touching the slab's side, standing on the floor, as tall as the slab
    depth[100:110, 202:210] = np.linspace(0.995, 0.96, 10)[:, None]
    assert support_of(beside, [slab], _frame(depth), min_extent_m=0.10) is None
    floating = np.zeros((H, W), bool)
    floating[100:106, 150:156] = True
    depth[100:106, 150:156] = np.linspace(0.86, 0.85, 6)[:, None]  # 11 cm above the slab's top: not standing on it
    assert support_of(floating, [slab], _frame(depth), min_extent_m=0.10) is None


def test_the_segmenter_joins_a_knob_fin_read_as_a_wine_bottle_to_the_stove_as_its_knob():
    depth, slab, fin = _stove_with_fin()
    stove = Instance(CATEGORY_INDEX["stove"], slab, 0.98, "grey")
    bottle = Instance(CATEGORY_INDEX["wine bottle"], fin, 0.7, "black")
    whole, part = _absorb_pieces([stove, bottle], _frame(depth))  # no bottle left
    assert whole.category == CATEGORY_INDEX["stove"] and (whole.mask == (slab | fin)).all()
    assert part.category == CATEGORY_INDEX["knob"] and (part.mask == fin).all()  # a stove's one kind of part
    # a plate has no smallest size: a small plate piece is left for the other clean-ups
    plate = Instance(CATEGORY_INDEX["plate"], fin, 0.7, "white")
    assert len(_absorb_pieces([stove, plate], _frame(depth))) == 2
    # a cabinet has two kinds of part (drawer, handle): the piece joins it and names no part
    cabinet = Instance(CATEGORY_INDEX["cabinet"], slab, 0.98, "brown")
    (only,) = _absorb_pieces([cabinet, bottle], _frame(depth))
    assert only.category == CATEGORY_INDEX["cabinet"]


def test_a_stray_of_what_stands_in_front_leaves_the_mask_and_the_object_stays_whole():
    """A bowl (5 cm tall, seen top-down) whose upscaled mask took an edge of a bottle standing beside it (15 cm
    tall, so 10 cm nearer the camera): the bottle's pixels go, every bowl pixel stays, and the bowl's seen top is
    its rim again."""
    from spark_core.perception.learned.pieces import without_strays
    from spark_core.perception.learned.segmenter import _standing_part

    depth = np.ones((H, W))
    yy, xx = np.mgrid[:H, :W]
    bowl = np.hypot(yy - 120, xx - 160) < 40
    depth[bowl] = 0.95 + 0.03 * (np.hypot(yy - 120, xx - 160)[bowl] < 30)  # rim 5 cm up, inside 2 cm up
    bottle_edge = (xx >= 201) & (xx <= 213) & (np.abs(yy - 120) < 18)  # 8 % of the mask
    depth[bottle_edge] = 0.85
    mask = bowl | bottle_edge
    frame = _frame(depth)
    kept = without_strays(mask, frame)
    assert (kept == bowl).all()
    inst = Instance(CATEGORY_INDEX["bowl"], kept, 0.9, "black")
    assert (_standing_part(inst, frame).mask == bowl).all()
    # the seen top (98th percentile height), which the standing-part cut and the keypoint measure from, is the
    # bowl's rim without the stray and the bottle's with it
    assert bottle_edge.sum() < 0.15 * mask.sum()
    top = {k: np.percentile(world_points(m, frame)[:, 2], 98) for k, m in (("kept", kept), ("raw", mask))}
    assert abs(top["kept"] - 0.05) < 0.005 and top["raw"] > 0.14


def test_a_mask_in_two_large_pieces_keeps_both():
    """Two halves of a bowl seen either side of a thin occluder are both kept (each far over the stray share)."""
    from spark_core.perception.learned.pieces import without_strays

    depth = np.ones((H, W))
    depth[100:140, 100:150] = 0.95
    depth[100:140, 170:220] = 0.95
    mask = depth < 0.97
    assert (without_strays(mask, _frame(depth)) == mask).all()


def test_a_brush_the_size_of_a_plates_rim_piece_is_part_of_the_plate_and_no_brush_is_found():
    """builtin scrub_plate, seen through frames alone: the network names a few centimetres of the plate's rim
    "brush" in both views; a brush is 14 cm long, so the piece joins the plate and "scrub the plate with the
    brush" (no brush in the scene) is refused instead of planned."""
    from spark_core.perception.keypoint import LabelNotFound
    from spark_core.perception.learned.segmenter import LearnedSegmenter
    from spark_core.perception.resolver import PerceptionResolver
    from spark_core.sim.tasks import SUITES
    from tests.perception.test_learned import CamerasOnly

    world = SUITES["builtin"]["scrub_plate"].make_world(0)
    try:
        resolver = PerceptionResolver(CamerasOnly(world), LearnedSegmenter(), cameras=("agentview", "side"))
        with pytest.raises(LabelNotFound):
            resolver.resolve("brush")
        resolver.resolve("plate")  # the plate and the sponge are still there
        resolver.resolve("sponge")
    finally:
        world.close()
