"""The learned segmenter's geometric clean-up of instances, on synthetic frames from a camera 1 m above a floor
looking straight down (camera x = world x, camera y = -world y; 1 px = 2 mm on the floor)."""

from __future__ import annotations

import numpy as np

from spark_core.perception.frame import CameraFrame
from spark_core.perception.learned.segmenter import _apart_in_space, _proud, _rejoin

H, W = 240, 320


def _frame(depth_m: np.ndarray) -> CameraFrame:
    K = np.array([[500.0, 0, W / 2], [0, 500.0, H / 2], [0, 0, 1]])
    T = np.eye(4)
    T[:3, :3] = np.diag([1.0, -1.0, -1.0])  # looking down: camera z = world -z
    T[2, 3] = 1.0
    return CameraFrame("top", np.zeros((H, W, 3), np.uint8), depth_m.astype(np.float32), K, T)


def test_two_items_joined_by_floor_pixels_come_apart():
    """A can and a carton 10 cm apart, one mask over both and the floor strip between them (a blob the network
    did not cut): two pieces, each without the floor."""
    depth = np.ones((H, W))
    depth[100:140, 60:100] = 0.9  # 10 cm tall
    depth[100:140, 150:190] = 0.88  # 12 cm tall
    mask = np.zeros((H, W), bool)
    mask[95:145, 55:195] = True
    pieces = _apart_in_space(mask, _frame(depth))
    assert len(pieces) == 2
    cols = sorted(int(np.nonzero(p)[1].mean()) for p in pieces)
    assert abs(cols[0] - 80) < 3 and abs(cols[1] - 170) < 3
    assert all(np.all(depth[p] < 0.95) for p in pieces)  # no floor pixel kept


def test_one_object_stays_whole():
    depth = np.ones((H, W))
    depth[100:140, 60:100] = 0.9
    mask = np.zeros((H, W), bool)
    mask[100:140, 60:100] = True
    (piece,) = _apart_in_space(mask, _frame(depth))
    assert (piece == mask).all()


def test_a_bowls_pieces_rejoin_but_two_bowls_do_not():
    """Network-resolution components (factor 1 here): a bowl's rim and its bottom (3 cm apart in depth, cut by a
    depth edge) join; a second bowl touching the first stays apart (together 24 cm wide)."""
    depth = np.ones((H, W))
    yy, xx = np.mgrid[:H, :W]
    r1 = np.hypot(yy - 120, xx - 100)
    r2 = np.hypot(yy - 120, xx - 160)
    depth[r1 < 30] = 0.95  # rim (6 cm radius ring)
    depth[r1 < 20] = 0.98  # bottom
    depth[r2 < 30] = 0.95
    comp = np.zeros((H, W), np.int32)
    comp[(r1 < 30) & (r1 >= 20)] = 1
    comp[r1 < 20] = 2
    comp[r2 < 30] = 3
    comp[(r2 < 30) & (r1 < 30)] = 1
    out, _ = _rejoin(comp, 4, 0.18, depth, _frame(depth), 1)
    assert out[120, 100] == out[120, 75]  # bottom joined with its rim
    assert out[120, 170] != out[120, 100]  # the other bowl kept apart


def test_a_handle_mask_loses_the_drawer_face_around_it():
    """Seen from the front: a handle 2 cm proud of the drawer face; the mask spilled onto the face below it."""
    depth = np.full((H, W), 0.80)
    depth[110:118, 100:200] = 0.78  # the handle
    mask = np.zeros((H, W), bool)
    mask[106:130, 98:202] = True  # handle + face below
    kept = _proud(mask, _frame(depth), 0.015)
    assert kept[110:118, 100:200].all() and not kept[120:130].any()


def test_a_renamed_piece_joins_the_rest_of_its_object():
    """The front of a bowl renamed 'bowl' by the second look and the back the per-pixel network named bowl: one
    bowl; a third bowl further on stays apart."""
    from spark_core.perception.learned.categories import CATEGORY_INDEX
    from spark_core.perception.learned.segmenter import Instance, _join_renamed

    bowl = CATEGORY_INDEX["bowl"]
    depth = np.ones((H, W))
    front, back, other = (np.zeros((H, W), bool) for _ in range(3))
    front[100:130, 80:120] = True  # 6 x 8 cm
    back[70:100, 80:120] = True
    other[70:130, 200:240] = True  # 24 cm further along x
    insts = [Instance(bowl, m, 0.9, "black") for m in (front, back, other)]
    out = _join_renamed(insts, {bowl}, _frame(depth))
    assert len(out) == 2
    assert (out[0].mask == (front | back)).all() and (out[1].mask == other).all()
