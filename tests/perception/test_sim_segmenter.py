"""`sim` grounding: synonyms, colours, duplicate instances, spatial qualifiers; `sim-noisy` failure model."""

import numpy as np
import pytest

from spark_core.control.panda import panda
from spark_core.perception.noisy_segmenter import NoiseModel, SimNoisySegmenter
from spark_core.perception.qualifiers import split_qualifier
from spark_core.perception.sim_segmenter import SimSegmenter
from spark_core.sim.scene import ObjectRequest as O
from spark_core.sim.scene import build_scene
from spark_core.sim.world import MujocoWorld


@pytest.fixture(scope="module")
def scene():
    reqs = [
        O("red block", "block", "red", (0.4, 0.45), (-0.25, -0.2)),
        O("blue block", "block", "blue", (0.4, 0.45), (0.2, 0.25)),
        O("black bowl 1", "bowl", "black", (0.58, 0.62), (0.18, 0.22)),
        O("black bowl 2", "bowl", "black", (0.58, 0.62), (-0.22, -0.18)),
        O("plate", "plate", "white", (0.5, 0.55), (-0.03, 0.03)),
        O("mug", "mug", "red", (0.7, 0.72), (-0.02, 0.02)),
    ]
    w = MujocoWorld(build_scene({"right": (panda(), np.eye(4))}, reqs, seed=0))
    w.settle(0.2)
    seg = SimSegmenter(w.scene.catalog())
    yield w, seg, w.render("agentview")
    w.close()


def objects(dets):
    return sorted(d.detail["object"] for d in dets)


@pytest.mark.parametrize(
    "prompt,expected",
    [
        ("red block", ["red block"]),
        ("crimson cube", ["red block"]),
        ("blue cube", ["blue block"]),
        ("dinner plate", ["plate"]),
        ("coffee cup", ["mug"]),
        ("white ceramic plate", ["plate"]),
    ],
)
def test_prompt_grounds_to_one_object(scene, prompt, expected):
    w, seg, frame = scene
    dets = seg.segment(frame, [prompt])
    assert objects(dets) == expected
    d = dets[0]
    assert d.privileged and d.label == prompt and d.prompt == prompt and 0.5 < d.score <= 1.0
    assert d.mask.shape == frame.shape and d.mask.sum() > 50


def test_two_matching_instances_give_two_detections(scene):
    w, seg, frame = scene
    assert objects(seg.segment(frame, ["black bowl"])) == ["black bowl 1", "black bowl 2"]


@pytest.mark.parametrize(
    "prompt,expected", [("the left black bowl", "black bowl 1"), ("the right bowl", "black bowl 2")]
)
def test_spatial_qualifier_picks_the_instance(scene, prompt, expected):
    w, seg, frame = scene
    assert objects(seg.segment(frame, [prompt])) == [expected]  # bowl 1 is at +y: the robot's left


@pytest.mark.parametrize(
    "prompt,expected", [("block not blue", ["red block"]), ("black bowl not black", []), ("bowl not red", None)]
)
def test_a_negated_attribute_keeps_the_instances_it_contradicts(scene, prompt, expected):
    w, seg, frame = scene
    got = objects(seg.segment(frame, [prompt]))
    assert got == (expected if expected is not None else ["black bowl 1", "black bowl 2"])
    assert all(d.label == prompt for d in seg.segment(frame, [prompt]))


def test_unrelated_prompt_finds_nothing(scene):
    w, seg, frame = scene
    assert seg.segment(frame, ["giraffe"]) == []


def test_frame_without_ids_is_refused(scene):
    w, seg, frame = scene
    from dataclasses import replace

    with pytest.raises(ValueError, match="needs per-pixel object ids"):
        seg.segment(replace(frame, object_ids=None), ["plate"])


def test_split_qualifier():
    assert split_qualifier("the left mug") == ("left", "mug")
    assert split_qualifier("bowl nearest the robot") == ("nearest", "bowl")
    assert split_qualifier("red block") == (None, "red block")


def test_noisy_miss_rate_and_determinism(scene):
    w, seg, frame = scene
    noisy = SimNoisySegmenter(seg, NoiseModel(miss_rate=0.3), seed=3)
    kept = sum(len(noisy.segment(frame, ["plate"])) for _ in range(300))
    assert 0.6 < kept / 300 < 0.8
    a = [len(SimNoisySegmenter(seg, NoiseModel(miss_rate=0.5), seed=9).segment(frame, ["plate"])) for _ in range(5)]
    b = [len(SimNoisySegmenter(seg, NoiseModel(miss_rate=0.5), seed=9).segment(frame, ["plate"])) for _ in range(5)]
    assert a == b


def test_noisy_erosion_confusion_and_depth(scene):
    w, seg, frame = scene
    clean = seg.segment(frame, ["plate"])[0]
    eroded = SimNoisySegmenter(seg, NoiseModel(miss_rate=0.0, erode_px=3)).segment(frame, ["plate"])[0]
    assert eroded.mask.sum() < clean.mask.sum() and not (eroded.mask & ~clean.mask).any()
    confused = SimNoisySegmenter(seg, NoiseModel(miss_rate=0.0, confusion_rate=1.0)).segment(frame, ["red block"])[0]
    assert confused.detail["object"] != "red block" and confused.detail["confused_from"] == "red block"
    noisy = SimNoisySegmenter(seg, NoiseModel(miss_rate=0.0, depth_noise_m=0.01)).perturb_frame(frame)
    assert 0.008 < float(np.std(noisy.depth_m - frame.depth_m)) < 0.012


def test_split_relation():
    from spark_core.perception.qualifiers import split_relation

    assert split_relation("black bowl between the plate and the ramekin") == (
        "black bowl",
        "between",
        ["plate", "ramekin"],
    )
    assert split_relation("bowl next to the cookie box") == ("bowl", "next to", ["cookie box"])
    assert split_relation("red block") == ("red block", None, [])


def test_split_relation_negated():
    from spark_core.perception.qualifiers import split_relation

    assert split_relation("bowl not between the plate and the ramekin") == ("bowl", "not between", ["plate", "ramekin"])


def test_copies_of_a_kind_ground_alike_but_numbered_parts_stay_apart():
    from spark_core.perception.sim_segmenter import _instance_names

    names = _instance_names(
        {
            "bowl": "black bowl",
            "bowl 2": "black bowl",
            "pot handle 0": "one handle of the pot",
            "pot handle 1": "the other handle of the pot",
        }
    )
    assert names == {"bowl": "bowl", "bowl 2": "bowl", "pot handle 0": "pot handle 0", "pot handle 1": "pot handle 1"}


def test_stacked_qualifiers_split_off():
    assert split_qualifier("drawer middle layer handle") == ("middle", "drawer layer handle")
    assert split_qualifier("the top drawer") == ("top", "drawer")
    assert split_qualifier("bottom shelf") == ("bottom", "shelf")
