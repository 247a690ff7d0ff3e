"""How the `sim` grounding reads the phrases the rules planner writes for one of several things: an ordinal counted
from one end ("second leftmost"), "middle" along the row the things stand in, a qualifier ruled out ("not
leftmost"), "on" and "in" said by what a thing rests on or sits inside, and names that are near an object's but
name another thing ("cheddar" beside cream cheese, a "whiskey flask" beside a wine bottle).

The frames are synthetic: a camera 1 m above the table looking straight down, so a pixel's depth sets its height.
"""

import numpy as np
import pytest

from spark_core.perception.frame import CameraFrame
from spark_core.perception.naming import mismatch
from spark_core.perception.sim_segmenter import SimSegmenter

H, W, F = 200, 200, 200.0
# camera x (image right) = world -y (the robot's right), camera y (image down) = world -x (toward the robot)
T_DOWN = np.array([[0, -1, 0, 0.5], [-1, 0, 0, 0.0], [0, 0, -1, 1.0], [0, 0, 0, 1]], float)


def frame(objects: dict[str, tuple[float, float, float, float, float]]) -> CameraFrame:
    """objects: label -> (x, y, half size, bottom z, top z) in the world (m), drawn in order (later ones on top)."""
    depth = np.full((H, W), 1.0, np.float32)  # the table at z = 0
    ids = np.zeros((H, W), np.int32)
    labels = {}
    K = np.array([[F, 0, W / 2], [0, F, H / 2], [0, 0, 1]], float)
    for i, (label, (x, y, half, _, top)) in enumerate(objects.items(), start=1):
        d = 1.0 - top
        u0, u1 = (W / 2 - (y + half) * F / d, W / 2 - (y - half) * F / d)
        v0, v1 = (H / 2 - (x + half - 0.5) * F / d, H / 2 - (x - half - 0.5) * F / d)
        sl = (slice(int(round(v0)), int(round(v1))), slice(int(round(u0)), int(round(u1))))
        depth[sl], ids[sl], labels[i] = d, i, label
    return CameraFrame("top", np.zeros((H, W, 3), np.uint8), depth, K, T_DOWN, object_ids=ids, labels=labels)


def found(seg: SimSegmenter, f: CameraFrame, prompt: str) -> list[str]:
    return sorted(d.detail["object"] for d in seg.segment(f, [prompt]))


@pytest.fixture(scope="module")
def row():
    """Three black bowls in a row across the table (left to right: 1, 2, 3), the middle one a little farther and
    lower than the others (the left one the tallest)."""
    objects = {
        "black bowl 1": (0.45, 0.15, 0.03, 0.0, 0.07),
        "black bowl 2": (0.55, 0.0, 0.03, 0.0, 0.05),
        "black bowl 3": (0.47, -0.15, 0.03, 0.0, 0.06),
    }
    return SimSegmenter({k: "a black bowl" for k in objects}), frame(objects)


def test_an_ordinal_counts_from_the_end_the_qualifier_names(row):
    seg, f = row
    assert found(seg, f, "leftmost black bowl") == ["black bowl 1"]
    assert found(seg, f, "second leftmost black bowl") == ["black bowl 2"]
    assert found(seg, f, "third leftmost black bowl") == ["black bowl 3"]
    assert found(seg, f, "second rightmost black bowl") == ["black bowl 2"]
    assert found(seg, f, "fourth leftmost black bowl") == []  # fewer than that: nothing to point at


def test_middle_is_along_the_row_the_things_stand_in(row):
    seg, f = row
    # across the table (y) they spread 30 cm, along it (x) 10 cm, in height 2 cm: the middle of the row, not of
    # the heights (that is the middle of stacked drawers)
    assert found(seg, f, "middle black bowl") == ["black bowl 2"]


def test_a_qualifier_ruled_out_keeps_the_others(row):
    seg, f = row
    assert found(seg, f, "black bowl not leftmost") == ["black bowl 2", "black bowl 3"]
    assert found(seg, f, "black bowl not farthest") == ["black bowl 1", "black bowl 3"]


@pytest.fixture(scope="module")
def cabinet():
    """A cabinet (top 23 cm); one bowl on top of it, the other in its drawer, pulled out to its left: in the table
    plane the bowl on top is the nearer to the cabinet's middle."""
    objects = {
        "wooden cabinet": (0.7, -0.25, 0.08, 0.0, 0.23),
        "black bowl 1": (0.7, -0.22, 0.03, 0.23, 0.28),
        "black bowl 2": (0.7, -0.1, 0.03, 0.16, 0.21),
    }
    catalog = {"wooden cabinet": "a wooden cabinet", "black bowl 1": "a black bowl", "black bowl 2": "a black bowl"}
    return SimSegmenter(catalog), frame(objects)


def test_on_and_in_are_said_by_support_not_by_nearness(cabinet):
    seg, f = cabinet
    assert found(seg, f, "black bowl on wooden cabinet") == ["black bowl 1"]
    assert found(seg, f, "black bowl inside wooden cabinet") == ["black bowl 2"]
    assert found(seg, f, "black bowl not on wooden cabinet") == ["black bowl 2"]


@pytest.mark.parametrize(
    "prompt,name",
    [
        ("cheddar", "cream cheese"),  # a food noun only near this food's: another food (groceries: a closed set)
        ("oil", "butter"),
        ("vodka", "wine bottle"),  # a drink noun only near the bottle's: another drink
        ("mozzarella", "cream cheese"),
        ("lemonade", "orange juice"),
        ("whiskey flask", "wine bottle"),  # the same kind of noun, and a word of its own where the object has another
        ("margarine", "butter"),  # a substitute for a food is another food, not a name for it
        ("marmalade", "jam"),
        ("pencil", "pen"),  # another product of the same use
    ],
)
def test_a_near_name_of_another_thing_does_not_ground(prompt, name):
    assert mismatch(prompt, name, name) is not None


@pytest.mark.parametrize(
    "prompt,name",
    [
        ("cheese", "cream cheese"),
        ("wine flask", "wine bottle"),
        ("pudding", "chocolate pudding"),
        ("oj", "orange juice"),
        ("coffee cup", "mug"),
    ],
)
def test_the_objects_own_words_and_kinds_still_ground(prompt, name):
    assert mismatch(prompt, name, name) is None
