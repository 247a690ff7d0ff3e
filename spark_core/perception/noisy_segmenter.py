"""`sim-noisy`: the sim segmenter plus a seeded detector-failure model, to measure recovery and adaptive
prompting under controlled perception error. Still privileged underneath (masks from ground truth)."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import cv2
import numpy as np

from .detection import Detection
from .frame import CameraFrame
from .sim_segmenter import SimSegmenter


@dataclass(frozen=True)
class NoiseModel:
    miss_rate: float = 0.2  # probability a true detection is dropped
    erode_px: int = 0  # mask erosion (negative values dilate)
    confusion_rate: float = 0.0  # probability the mask is swapped for the most similar other object in view
    depth_noise_m: float = 0.0  # std of Gaussian noise added to depth before lifting

    def describe(self) -> str:
        return (
            f"miss {self.miss_rate:.0%}, erode {self.erode_px} px, confusion {self.confusion_rate:.0%}, "
            f"depth noise {self.depth_noise_m * 1000:.0f} mm"
        )


class SimNoisySegmenter:
    name = "sim-noisy"
    privileged = True

    def __init__(self, base: SimSegmenter, noise: NoiseModel, seed: int = 0):
        self.base = base
        self.noise = noise
        self.rng = np.random.default_rng(seed)

    def perturb_frame(self, frame: CameraFrame) -> CameraFrame:
        """Depth noise is part of the failure model; applied once per captured frame."""
        if self.noise.depth_noise_m <= 0:
            return frame
        depth = frame.depth_m + self.rng.normal(0.0, self.noise.depth_noise_m, frame.depth_m.shape).astype(np.float32)
        return CameraFrame(
            frame.camera,
            frame.rgb,
            depth,
            frame.K,
            frame.T_world_camera,
            frame.sim_time_s,
            frame.object_ids,
            frame.labels,
        )

    def segment(self, frame: CameraFrame, prompts: Sequence[str]) -> list[Detection]:
        out = []
        ids = {v: k for k, v in frame.labels.items()}
        for det in self.base.segment(frame, prompts):
            if self.rng.random() < self.noise.miss_rate:
                continue
            mask = det.mask
            detail = dict(det.detail)
            if self.noise.confusion_rate and self.rng.random() < self.noise.confusion_rate:
                other = self._confuser(det, frame, ids)
                if other is not None:
                    assert frame.object_ids is not None  # the base segmenter refuses frames without object ids
                    mask = frame.object_ids == ids[other]
                    detail.update(object=other, confused_from=det.detail.get("object"))
            k = abs(self.noise.erode_px)
            if k:
                kernel = np.ones((2 * k + 1, 2 * k + 1), np.uint8)
                op = cv2.erode if self.noise.erode_px > 0 else cv2.dilate
                mask = op(mask.astype(np.uint8), kernel).astype(bool)
            if mask.any():
                out.append(Detection(det.label, det.prompt, mask, det.score, det.camera, True, detail))
        return out

    def _confuser(self, det: Detection, frame: CameraFrame, ids: dict[str, int]) -> str | None:
        truth = det.detail.get("object")
        assert frame.object_ids is not None  # only called on detections of the base segmenter, which needs them
        visible = {frame.labels[i] for i in np.unique(frame.object_ids) if i and i in frame.labels}
        sims = {k: v for k, v in self.base.similarities(det.prompt).items() if k in visible and k != truth}
        return max(sims, key=sims.__getitem__) if sims else None
