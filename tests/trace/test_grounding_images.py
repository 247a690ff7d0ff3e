"""One annotated image per grounding and camera: kept with the frames the grounding used, skipped when the
resolver has captured new frames since (the image would show another moment)."""

import cv2
import numpy as np

from spark_core.perception.detection import Detection
from spark_core.perception.frame import CameraFrame
from spark_core.trace.grounding_images import MAX_WIDTH_PX, GroundingImages


def _frame(t: float, shade: int) -> CameraFrame:
    rgb = np.full((480, 640, 3), shade, np.uint8)
    return CameraFrame("agentview", rgb, np.ones((480, 640), np.float32), np.eye(3), np.eye(4), sim_time_s=t)


def _grounding(label: str, t: float, chosen: str | None) -> dict:
    cams = {"agentview": {"label": label, "chosen": chosen, "candidates": []}}
    return {"label": label, "t_sim_s": t, "cameras": cams}


class FakeResolver:
    def __init__(self):
        self.groundings: list[dict] = []
        self.frames: dict[str, CameraFrame] = {}
        self.detections: dict[str, dict[str, Detection]] = {}


def test_each_grounding_keeps_its_own_image_and_stale_frames_are_skipped(tmp_path):
    r, images = FakeResolver(), GroundingImages()
    mask = np.zeros((480, 640), bool)
    mask[100:200, 100:200] = True
    r.frames = {"agentview": _frame(0.5, 40)}
    r.detections = {"agentview": {"red block": Detection("red block", "red cube", mask, 0.9, "agentview")}}
    r.groundings.append(_grounding("red block", 0.5, "red cube"))
    images.watch(r)
    # two more groundings before the next look; the resolver captured new frames for the second one only
    r.groundings.append(_grounding("blue block", 0.5, None))  # made with the old frames: they are gone
    r.frames = {"agentview": _frame(1.25, 200)}
    r.groundings.append(_grounding("red block", 1.25, None))
    images.watch(r)
    out = images.save(tmp_path)
    assert [(a["grounding"], a["t_sim_s"], a["label"]) for a in out] == [(0, 0.5, "red block"), (2, 1.25, "red block")]
    first, second = (cv2.imread(a["path"]) for a in out)
    assert first.shape == (MAX_WIDTH_PX * 3 // 4, MAX_WIDTH_PX, 3)
    # the first has the kept mask tinted over its dark frame; the second is its own, brighter frame
    assert first[60:90, 60:90].mean() > first[150:, 200:].mean() + 20
    assert second.mean() > first.mean() + 100
    assert all(a["kind"] == "grounding" and a["path"].endswith(".jpg") for a in out)
