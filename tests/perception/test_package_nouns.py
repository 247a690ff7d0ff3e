"""A package noun names what comes in that package ("the carton": the milk and the juice, not the box of butter
beside them); a negation rules out what each thing it names grounds to ("the box that is neither cream cheese nor
chocolate pudding"). Synthetic top-down frame: a camera 1 m above the table looking straight down (1 px = 1 cm;
pixel (u, v) is world x = (u - 50) cm, y = (50 - v) cm)."""

from __future__ import annotations

import numpy as np
import pytest

from spark_core.perception.frame import CameraFrame
from spark_core.perception.naming import package_members
from spark_core.perception.sim_segmenter import SimSegmenter

H = W = 100


def _frame(where_cm: dict[str, tuple[int, int]]) -> CameraFrame:
    """Each label a 6 x 6 cm square centred at (x, y) cm on the table."""
    K = np.array([[100.0, 0, W / 2], [0, 100.0, H / 2], [0, 0, 1]])
    T = np.eye(4)
    T[:3, :3] = np.diag([1.0, -1.0, -1.0])  # camera x = world x, y = -world y, z = -world z
    T[2, 3] = 1.0
    ids = np.zeros((H, W), np.int32)
    labels = {}
    for i, (label, (x, y)) in enumerate(where_cm.items(), start=1):
        u, v = x + W // 2, H // 2 - y
        ids[v - 3 : v + 3, u - 3 : u + 3] = i
        labels[i] = label
    return CameraFrame("top", np.zeros((H, W, 3), np.uint8), np.ones((H, W), np.float32), K, T, 0.0, ids, labels)


# A LIBERO-PRO object scene: its objects are described by their names alone; what each comes in is its category's
# (perception/learned/categories.py: "carton of milk", "small box of butter").
GROCERIES = {
    "milk": (-30, 20),
    "orange juice": (-10, 20),
    "butter": (10, 20),
    "cream cheese": (30, 20),
    "chocolate pudding": (-30, -20),
    "tomato sauce": (-10, -20),
    "basket": (20, -25),
}


@pytest.fixture(scope="module")
def groceries() -> tuple[SimSegmenter, CameraFrame]:
    return SimSegmenter({name: name for name in GROCERIES}), _frame(GROCERIES)


def _found(seg: SimSegmenter, frame: CameraFrame, prompt: str) -> set[str]:
    return {d.detail["object"] for d in seg.segment(frame, [prompt])}


@pytest.mark.parametrize(
    ("prompt", "names"),
    [
        # the package it comes in, not another package of its kind (a carton and a box are both boxes)
        ("the carton", {"milk", "orange juice"}),
        ("box", {"butter", "cream cheese", "chocolate pudding"}),
        ("a tin", {"tomato sauce"}),  # a tin is a can
        ("the can", {"tomato sauce"}),
        # a thing named by its product is that product alone
        ("milk carton", {"milk"}),
        ("the butter", {"butter"}),
    ],
)
def test_a_package_noun_names_what_comes_in_it(groceries, prompt, names):
    seg, frame = groceries
    assert _found(seg, frame, prompt) == names


@pytest.mark.parametrize(
    ("prompt", "names"),
    [
        ("carton not orange juice", {"milk"}),
        ("box not chocolate pudding", {"butter", "cream cheese"}),
        ("box not cream cheese nor chocolate pudding", {"butter"}),
        ("box not cream cheese, chocolate pudding", {"butter"}),
        ("carton not milk or orange juice", set()),
        # a thing named in full keeps itself: what the ruled-out words name alone is ruled out, not "orange juice
        # milk carton"
        ("milk carton not orange juice", {"milk"}),
    ],
)
def test_a_negation_rules_out_what_each_thing_it_names_grounds_to(groceries, prompt, names):
    seg, frame = groceries
    assert _found(seg, frame, prompt) == names


def test_a_negated_colour_still_rules_out_by_the_words():
    """ "block not blue": the blue block, whether "blue block" grounds to it or the words contradict the rest."""
    catalog = {
        "red block": "small red wooden cube block",
        "blue block": "small blue wooden cube block",
        "green block": "small green wooden cube block",
    }
    seg = SimSegmenter(catalog)
    frame = _frame({"red block": (-20, 0), "blue block": (0, 0), "green block": (20, 0)})
    assert _found(seg, frame, "block not blue") == {"red block", "green block"}
    assert _found(seg, frame, "block not blue nor green") == {"red block"}


def test_a_package_noun_the_scene_has_no_such_package_for_names_its_kind_or_nothing():
    descriptions = ["carton of milk", "small box of butter", "bottle of ketchup", "wooden box-shaped cube"]
    assert package_members("carton", descriptions) == {0}
    assert package_members("the packet", descriptions) == {0, 1}  # no packet: a package of its kind
    assert package_members("jar", descriptions) is None  # a jar is a kind of thing: the kinds decide
    assert package_members("tub", descriptions) is None  # nothing comes in one
    assert package_members("milk carton", descriptions) is None  # a product named: not the package's own question
    assert package_members("box", ["wooden box-shaped cube"]) is None  # a shape is no package
