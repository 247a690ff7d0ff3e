"""Sided relations ("the bowl left of the cookie box"): perception picks the instance on that side of the anchor,
not the nearest one, with the oracle and with the camera-only segmenter alike."""

import numpy as np

from spark_core.perception.qualifiers import on_side, relation_holds, split_relation


def test_a_sided_relation_splits_and_holds_on_its_side_only():
    assert split_relation("black bowl left of cookie box") == ("black bowl", "left of", ["cookie box"])
    assert split_relation("bowl not right of plate") == ("bowl", "not right of", ["plate"])
    box = (np.array([0.70, 0.00]), 0.05)
    left, right = np.array([0.70, 0.16]), np.array([0.72, -0.12])  # +y is the robot's left
    assert relation_holds("left of", left, [box]) and not relation_holds("left of", right, [box])
    assert relation_holds("right of", right, [box]) and not relation_holds("right of", left, [box])
    assert relation_holds("not left of", right, [box])
    assert on_side("next to", right, box[0])  # a relation that names no side holds on any side


def _frame(h: int, w: int):
    from spark_core.perception.frame import CameraFrame

    K = np.array([[500.0, 0, w / 2], [0, 500.0, h / 2], [0, 0, 1]])
    T = np.eye(4)
    T[:3, :3] = np.diag([1.0, -1.0, -1.0])  # looking down from 1 m: image rows run along -y (the robot's right)
    T[2, 3] = 1.0
    return CameraFrame("top", np.zeros((h, w, 3), np.uint8), np.ones((h, w), np.float32), K, T)


def test_the_learned_segmenter_picks_the_side_said_over_the_nearer_instance(monkeypatch):
    """Top-down synthetic frame (1 px = 2 mm): a cookie box, a bowl 16 cm to its left and one 14 cm to its right.
    "next to" picks the nearer (right) bowl; "left of" the left one, though it is farther; each records that its pick
    stands in the relation."""
    from spark_core.perception.learned.categories import CATEGORY_INDEX
    from spark_core.perception.learned.segmenter import Instance, LearnedSegmenter

    H, W = 320, 320
    frame = _frame(H, W)

    def box(r0, r1, c0, c1):
        m = np.zeros((H, W), bool)
        m[r0:r1, c0:c1] = True
        return m

    cookies = Instance(CATEGORY_INDEX["cookie box"], box(140, 180, 140, 180), 0.99, "brown")
    left = Instance(CATEGORY_INDEX["bowl"], box(60, 100, 140, 180), 0.9, "black")  # row 80: y = +0.16 m
    right = Instance(CATEGORY_INDEX["bowl"], box(215, 255, 140, 180), 0.9, "black")  # row 235: y = -0.15 m
    seg = LearnedSegmenter()
    monkeypatch.setattr(seg, "instances", lambda f: [cookies, left, right])
    for prompt, expected in (
        ("bowl next to cookie box", right),
        ("bowl left of cookie box", left),
        ("bowl right of cookie box", right),
        ("bowl not left of cookie box", right),
    ):
        (det,) = seg.segment(frame, [prompt])
        assert det.mask is expected.mask, prompt
        assert det.detail["relation_holds"] is True, prompt


def test_the_sim_oracle_picks_the_side_said_in_a_libero_scene():
    """LIBERO-PRO spatial (swap), seed 0: two black bowls either side of the cookies, the right one nearer."""
    from spark_core.perception.factory import make_resolver
    from spark_core.planning.observe import observe
    from spark_core.sim.tasks import SUITES

    task = "libero_spatial_swap:pick_up_the_black_bowl_next_to_the_cookie_box_and_place_it_on_the_plate"
    world = SUITES["liberopro"][task].make_world(0)
    try:
        resolver = make_resolver(world, "sim", 0)
        cookies = observe("pick up the cookie box", resolver).keypoints["cookie box"].position_m
        for side, sign in (("left", 1.0), ("right", -1.0)):
            label = f"black bowl {side} of cookie box"
            bowl = observe(f"pick up the {label}", resolver).keypoints[label].position_m
            assert sign * (bowl[1] - cookies[1]) > 0.05, (side, bowl, cookies)
    finally:
        world.close()
