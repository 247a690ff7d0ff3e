"""A segmenter's answer to one text prompt: a mask with a score."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .pixels import mask_pixels


@dataclass(frozen=True)
class Detection:
    """`label` is what was asked for (a plan's label); `prompt` the text actually sent to the segmenter.

    `privileged` is True when the mask came from simulator ground truth (the `sim` backends).
    `detail` may carry backend specifics; `detail["object"]` (sim only) names the true object, for evaluation.
    """

    label: str
    prompt: str
    mask: np.ndarray  # (H, W) bool, image resolution
    score: float  # [0, 1]
    camera: str
    privileged: bool = False
    detail: dict[str, Any] = field(default_factory=dict)

    @property
    def area_px(self) -> int:
        return int(self.mask.sum())

    @property
    def centroid_px(self) -> tuple[float, float]:
        vs, us = mask_pixels(self.mask)
        return (float(us.mean()), float(vs.mean())) if len(us) else (float("nan"), float("nan"))

    @property
    def bbox_px(self) -> tuple[int, int, int, int]:
        """(u_min, v_min, u_max, v_max), inclusive."""
        vs, us = mask_pixels(self.mask)
        return (int(us.min()), int(vs.min()), int(us.max()), int(vs.max())) if len(us) else (0, 0, -1, -1)

    def with_label(self, label: str) -> Detection:
        return Detection(label, self.prompt, self.mask, self.score, self.camera, self.privileged, dict(self.detail))
