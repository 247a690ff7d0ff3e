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


def test_a_bowls_halves_on_a_support_rejoin_though_their_masks_spill_onto_it():
    """A bowl (12 cm wide, 5 cm tall) standing on a stove top (4 cm up), its mask cut into a left and a right half,
    each half spilling 4 cm onto the stove top beside it: on all points the two halves span 20 cm, more than a bowl
    (18 cm), so they stayed apart; measured on their upper band (the rim) they span 12 cm and join."""
    depth = np.ones((H, W))
    yy, xx = np.mgrid[:H, :W]
    r = np.hypot(yy - 120, xx - 160)
    depth[60:180, 90:230] = 0.96  # the stove top
    depth[r < 30] = 0.94  # the bowl's inside, 6 cm up
    depth[(r < 30) & (r >= 24)] = 0.91  # its rim, 9 cm up
    spill_left = (np.abs(yy - 120) < 10) & (xx >= 110) & (xx < 131)
    spill_right = (np.abs(yy - 120) < 10) & (xx > 189) & (xx <= 210)
    comp = np.zeros((H, W), np.int32)
    comp[((r < 30) & (xx < 160)) | spill_left] = 1
    comp[((r < 30) & (xx >= 160)) | spill_right] = 2
    frame = _frame(depth)
    apart, _ = _rejoin(comp, 3, 0.18, depth, frame, 1)
    assert apart[120, 150] != apart[120, 170]  # without the height band: too wide for one bowl
    out, _ = _rejoin(comp, 3, 0.18, depth, frame, 1, max_height_m=0.06)
    assert out[120, 150] == out[120, 170]


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


def test_a_part_counts_only_on_what_it_is_part_of():
    """A drawer touching the cabinet anchors handles; a 'drawer' blob alone on the table does not, so a handle on
    it does not count either."""
    from spark_core.perception.learned.categories import CATEGORY_INDEX
    from spark_core.perception.learned.segmenter import _anchored, _touches

    cat = np.zeros((H, W), np.uint8)
    cat[20:100, 20:100] = CATEGORY_INDEX["cabinet"]
    cat[40:60, 100:120] = CATEGORY_INDEX["drawer"]  # on the cabinet's side
    cat[150:170, 200:220] = CATEGORY_INDEX["drawer"]  # alone
    parents = _anchored(cat, ("drawer", "cabinet"))
    on_cabinet, alone = np.zeros((H, W), bool), np.zeros((H, W), bool)
    on_cabinet[45:55, 121:124] = True
    alone[155:165, 221:224] = True
    assert _touches(on_cabinet, parents)
    assert not _touches(alone, parents)


def test_mask_pixels_on_the_wall_behind_are_dropped():
    from spark_core.perception.learned.segmenter import _one_surface

    depth = np.ones((H, W))
    depth[100:140, 100:140] = 0.9
    depth[100:140, 140:150] = 3.0  # the mask spilled past the silhouette onto the far wall
    mask = np.zeros((H, W), bool)
    mask[100:140, 100:150] = True
    kept = _one_surface(mask, _frame(depth))
    assert kept[100:140, 100:140].all() and not kept[:, 140:150].any()


def test_an_instance_under_the_table_top_is_dropped():
    """The network's table pixels give the table top's height; an 'object' 30 cm under it is the floor behind."""
    from spark_core.perception.learned.categories import CATEGORY_INDEX, TABLE
    from spark_core.perception.learned.segmenter import Instance, _above_table, _table_top_z

    depth = np.full((H, W), 0.8)  # table top 20 cm above the floor (camera 1 m above the floor)
    depth[10:40, 10:40] = 1.1  # seen through a gap: 10 cm under the floor level, 30 cm under the table
    cat = np.full((H, W), TABLE, np.uint8)
    on, under = np.zeros((H, W), bool), np.zeros((H, W), bool)
    on[100:120, 100:120] = True
    under[10:40, 10:40] = True
    bowl = CATEGORY_INDEX["bowl"]
    frame = _frame(depth)
    out = _above_table(
        [Instance(bowl, on, 0.9, "red"), Instance(bowl, under, 0.9, "red")], _table_top_z(cat, frame), frame
    )
    assert [i.mask is on for i in out] == [True]


def test_a_part_seen_nowhere_falls_back_to_the_parent_the_prompt_names():
    from spark_core.perception.learned.categories import CATEGORY_INDEX
    from spark_core.perception.learned.segmenter import _parent_named

    knob, stove = CATEGORY_INDEX["knob"], CATEGORY_INDEX["stove"]
    assert _parent_named({knob: 0.8}, "stove knob") == {stove: 0.8}
    assert _parent_named({knob: 0.8}, "knob") == {}  # no parent named: nothing to fall back to


def test_a_bowl_on_a_box_loses_what_lies_further_below_than_a_bowl_is_tall():
    """A bowl 5 cm tall on a box 2 cm tall; the mask spilled over the box top and past it onto the floor (the
    network painted the support as bowl). Pixels more than a bowl's height (6 cm) below the bowl's top go (the
    floor); the box top within that height cannot be told from the bowl's foot by height and stays. A bowl on the
    floor is left whole."""
    from spark_core.perception.learned.categories import CATEGORY_INDEX
    from spark_core.perception.learned.segmenter import Instance, _standing_part

    depth = np.ones((H, W))
    depth[60:180, 80:240] = 0.98  # the box top, 2 cm up
    depth[90:150, 130:190] = 0.93  # the bowl, top 7 cm up
    mask = np.zeros((H, W), bool)
    mask[50:190, 70:250] = True  # bowl + box top + a floor ring
    bowl = CATEGORY_INDEX["bowl"]
    out = _standing_part(Instance(bowl, mask, 0.9, "black"), _frame(depth))
    assert out.mask[60:180, 80:240].all() and out.mask.sum() == 120 * 160
    floor = np.ones((H, W))
    floor[90:150, 130:190] = 0.95
    whole = np.zeros((H, W), bool)
    whole[85:155, 125:195] = True  # the bowl and a thin floor ring: 5 cm below its top, within a bowl's height
    assert _standing_part(Instance(bowl, whole, 0.9, "black"), _frame(floor)).mask.sum() == whole.sum()


def test_a_part_touching_its_parent_only_in_the_image_is_not_on_it():
    """A handle-coloured fringe next to a cabinet in the image but 30 cm behind it (the floor seen past a small
    handle) is not a handle on the cabinet; one at the cabinet's depth is, and so is one beside a cabinet side
    face that is nearer the camera as long as some cabinet pixel beside it is at its depth."""
    from spark_core.perception.learned.segmenter import _on_parent

    depth = np.full((40, 40), 1.45, np.float32)
    parent = np.zeros((40, 40), bool)
    parent[10:30, 5:20] = True
    part = np.zeros((40, 40), bool)
    part[15:20, 20:23] = True  # right of the parent, touching
    assert _on_parent(part, parent, depth)
    far = depth.copy()
    far[part] = 1.75
    assert not _on_parent(part, parent, far)
    side = depth.copy()
    side[10:30, 5:19] = 1.25  # the parent's nearer side face, but its front edge column is at the part's depth
    assert _on_parent(part, parent, side)
    away = np.zeros((40, 40), bool)
    away[35:38, 35:38] = True
    assert not _on_parent(away, parent, depth)


def test_a_handle_seen_at_an_angle_keeps_its_far_end():
    """A handle receding along its length (5 cm over 100 px, as a LIBERO handle seen by agentview), 2 cm proud
    of the face, the mask spilled onto the face below it: the whole length stays, the face goes. (Measured
    against the whole mask's nearest depth, the far half of the handle was cut.)"""
    depth = np.empty((H, W))
    cols = np.arange(W)
    depth[:] = 0.80 + 0.0005 * (cols - 100)  # the face recedes to the right
    depth[110:118, 100:200] = (0.78 + 0.0005 * (cols[100:200] - 100))[None]  # the handle, 2 cm in front
    mask = np.zeros((H, W), bool)
    mask[106:130, 98:202] = True
    kept = _proud(mask, _frame(depth), 0.015)
    assert kept[110:118, 100:200].all()  # near and far end alike
    assert not kept[121:130].any()  # the face below, along the whole length
