"""Annotated images (masks, labels, keypoints) for the planner and the UI, drawn with OpenCV."""

from __future__ import annotations

import cv2
import numpy as np

from .detection import Detection
from .frame import CameraFrame
from .keypoint import Keypoint

PALETTE = [
    (230, 25, 75),
    (60, 180, 75),
    (255, 225, 25),
    (0, 130, 200),
    (245, 130, 48),
    (145, 30, 180),
    (70, 240, 240),
    (240, 50, 230),
    (210, 245, 60),
    (250, 190, 212),
]


def annotate(
    frame: CameraFrame, detections: list[Detection], keypoints: dict[str, Keypoint] | None = None, alpha: float = 0.45
) -> np.ndarray:
    """RGB image with each mask tinted, its outline drawn, its label written, and keypoints as crosses."""
    img = frame.rgb.copy()
    for i, det in enumerate(detections):
        color = np.array(PALETTE[i % len(PALETTE)], np.uint8)
        m = det.mask
        img[m] = (img[m] * (1 - alpha) + color * alpha).astype(np.uint8)
        contours, _ = cv2.findContours(m.astype(np.uint8), cv2.RETR_EXTERNAL, cv2.CHAIN_APPROX_SIMPLE)
        cv2.drawContours(img, contours, -1, tuple(int(c) for c in color), 2)
        u, v = det.centroid_px
        if np.isfinite(u):
            text = f"{det.label} {det.score:.2f}"
            cv2.putText(img, text, (int(u) + 6, int(v) - 6), cv2.FONT_HERSHEY_SIMPLEX, 0.45, (0, 0, 0), 3, cv2.LINE_AA)
            cv2.putText(
                img, text, (int(u) + 6, int(v) - 6), cv2.FONT_HERSHEY_SIMPLEX, 0.45, (255, 255, 255), 1, cv2.LINE_AA
            )
    for _label, kp in (keypoints or {}).items():
        ((u, v),) = frame.project(kp.position_m[None])
        if 0 <= u < frame.shape[1] and 0 <= v < frame.shape[0]:
            cv2.drawMarker(img, (int(u), int(v)), (255, 255, 255), cv2.MARKER_CROSS, 14, 2)
    return img
