"""From masks and depth to 3D keypoints in the world frame."""

from __future__ import annotations

from dataclasses import dataclass

import cv2
import numpy as np

from .detection import Detection
from .frame import CameraFrame
from .keypoint import Keypoint
from .pixels import mask_pixels
from .quantiles import percentiles

MAX_DEPTH_M = 5.0
MIN_POINTS = 12
TRIM_MIN_POINTS = 20  # top faces with this many points lose their 2 % outermost in x and y
FOOTPRINT_CELL_M = 0.01  # footprint points: one per 1 cm cell of the top face


@dataclass(frozen=True)
class PointEvidence:
    """World points of one detection and where they came from."""

    detection: Detection
    points_world: np.ndarray  # (N, 3)
    surface_point: np.ndarray  # back-projected centroid pixel at the median masked depth (visible surface)


def masked_points(det: Detection, frame: CameraFrame, exclude: np.ndarray | None = None) -> PointEvidence | None:
    mask = det.mask if exclude is None else det.mask & ~exclude
    vs, us = mask_pixels(mask)
    z = frame.depth_m[vs, us]
    ok = (z > 0.01) & (z < MAX_DEPTH_M)
    if ok.sum() < MIN_POINTS:
        return None
    us, vs, z = us[ok].astype(float), vs[ok].astype(float), z[ok]
    pts = frame.backproject(us, vs, z)
    surface = frame.backproject(np.array([us.mean()]), np.array([vs.mean()]), np.array([np.median(z)]))[0]
    return PointEvidence(det, pts, surface)


def keypoint_from_points(label: str, evidence: list[PointEvidence], source: str) -> Keypoint:
    """Object centre, extent and yaw from the fused masked point cloud.

    The visible surface lies toward the camera (for a cube ~half a side from the centre), so the centre is
    taken from robust bounds of the cloud: xy from the middle of the top-face footprint, z halfway between the
    lowest and highest visible points. Yaw comes from an oriented box around the top face; it is None
    ("unstable") when the box is nearly square or the object is too thin to tell.
    """
    pts = np.concatenate([e.points_world for e in evidence])
    lo, hi = percentiles(pts, (2, 98))
    extent = hi - lo
    top = pts[pts[:, 2] > hi[2] - max(0.3 * extent[2], 0.004)]
    if len(top) >= TRIM_MIN_POINTS:  # one stray pixel (a thin handle's edge seeing past it) must not move the box
        t_lo, t_hi = percentiles(top[:, :2], (2, 98))
        top = top[np.all((top[:, :2] >= t_lo) & (top[:, :2] <= t_hi), axis=1)]
    (cx, cy), (w, h), angle = cv2.minAreaRect(top[:, :2].astype(np.float32)) if len(top) >= 5 else ((0, 0), (0, 0), 0)
    if len(top) >= 5:
        centre_xy = np.array([cx, cy])
    else:
        centre_xy = (lo[:2] + hi[:2]) / 2
    box_yaw = np.radians(angle)
    yaw: float | None = box_yaw
    if w < 0.01 or h < 0.01 or abs(w - h) < 0.15 * max(w, h):
        yaw = None  # nearly square or too thin from this view: the principal axis is not observable
    elif w < h:
        yaw = box_yaw + np.pi / 2  # long side along the principal axis
    extent_xy = np.array([max(w, h), min(w, h)]) if len(top) >= 5 else extent[:2]
    centre = np.array([centre_xy[0], centre_xy[1], (lo[2] + hi[2]) / 2])
    best = max(evidence, key=lambda e: e.detection.score)
    return Keypoint(
        label,
        centre,
        extent,
        None if yaw is None else float(yaw),
        source,
        float(best.detection.score),
        {
            "surface_point_m": [round(float(x), 4) for x in best.surface_point],
            "principal_extent_m": [round(float(x), 4) for x in extent_xy],
            "cameras": sorted({e.detection.camera for e in evidence}),
            "prompt": best.detection.prompt,
            "n_points": int(len(pts)),
            "footprint_xy_m": _footprint(top[:, :2] if len(top) >= 5 else pts[:, :2]),
        },
    )


def _footprint(xy: np.ndarray) -> list[list[float]]:
    """The top face's xy cover, one point per occupied 1 cm cell (what a wipe or sweep has to pass over)."""
    cells = np.unique(np.floor(xy / FOOTPRINT_CELL_M).astype(np.int64), axis=0)
    return [[round(float(x), 3), round(float(y), 3)] for x, y in (cells + 0.5) * FOOTPRINT_CELL_M]


def merge_duplicates(
    dets: list[Detection], radius_px: float = 30.0, keep_apart: frozenset[str] = frozenset()
) -> list[Detection]:
    """Detections of the same label whose mask centroids are within `radius_px` are one object (union mask).
    Labels in `keep_apart` are never merged (two objects that must stay distinct)."""
    out: list[Detection] = []
    for det in sorted(dets, key=lambda d: -d.score):
        if det.label not in keep_apart:
            for i, kept in enumerate(out):
                if kept.label == det.label and kept.camera == det.camera:
                    du = np.subtract(kept.centroid_px, det.centroid_px)
                    if float(np.hypot(*du)) <= radius_px:
                        out[i] = Detection(
                            kept.label,
                            kept.prompt,
                            kept.mask | det.mask,
                            kept.score,
                            kept.camera,
                            kept.privileged,
                            {**kept.detail, "merged": kept.detail.get("merged", 1) + 1},
                        )
                        break
            else:
                out.append(det)
        else:
            out.append(det)
    return out


def wrist_self_occlusion(shape: tuple[int, int], band: float = 0.2) -> np.ndarray:
    """Pixels of the wrist image where the robot's own fingers appear (the outer left/right bands): excluded
    from lifting so finger pixels never become object points."""
    h, w = shape
    m = np.zeros((h, w), bool)
    k = int(band * w)
    m[:, :k] = True
    m[:, w - k :] = True
    return m
