"""Pieces too small for their kind that stand on another object are part of that object. The per-pixel network
names some parts of fixtures after the look-alike kind: the thin black fin of LIBERO's stove knob comes out as a
"wine bottle" 6 cm long, while every wine bottle is at least 10 cm. Left alone, the stove loses its tallest part
(the knob, where a top-down grasp to turn it must go) and the scene gains a bottle that is not there."""

from __future__ import annotations

import cv2
import numpy as np

from ..frame import CameraFrame
from ..pixels import mask_pixels
from ..quantiles import percentiles

SPREAD_PCT = (5.0, 95.0)  # robust size: percentiles of the points along each world axis
STANDS_ON_M = 0.02  # a piece stands on an object when its lowest points are within this of the object's top
TOUCH_PX = 3  # ...and its mask comes within this many camera pixels of the object's
EDGE_M = 0.03  # ...and its middle is over the object's footprint, or this close to it (a knob at a stove's edge)


def world_points(mask: np.ndarray, frame: CameraFrame, n: int = 600) -> np.ndarray:
    """Up to n evenly spaced world points (m) of the mask's pixels with a finite depth; (0, 3) when none."""
    vs, us = mask_pixels(mask)
    step = max(1, len(vs) // n)
    vs, us = vs[::step], us[::step]
    z = frame.depth_m[vs, us]
    ok = np.isfinite(z) & (z > 0)
    if not ok.any():
        return np.zeros((0, 3))
    return frame.backproject(us[ok].astype(float), vs[ok].astype(float), z[ok])


def support_of(piece: np.ndarray, others: list[np.ndarray], frame: CameraFrame, min_extent_m: float) -> int | None:
    """Index into `others` (masks of whole objects) of the object the `piece` mask stands on when the piece is
    smaller than `min_extent_m` (m) along every world axis; None when it is not undersized or stands on nothing
    it touches. Of several supports, the one whose top is nearest the piece's bottom."""
    pts = world_points(piece, frame)
    if len(pts) < 5:
        return None
    lo, hi = percentiles(pts, SPREAD_PCT)
    if float((hi - lo).max()) >= min_extent_m:
        return None
    bottom, centre = float(lo[2]), np.median(pts[:, :2], axis=0)
    k = np.ones((2 * TOUCH_PX + 1, 2 * TOUCH_PX + 1), np.uint8)
    near = cv2.dilate(piece.astype(np.uint8), k).astype(bool)
    best: tuple[float, int] | None = None
    for i, other in enumerate(others):
        if not (near & other).any():
            continue
        q = world_points(other, frame)
        if len(q) < 5:
            continue
        olo, ohi = percentiles(q, (2.0, 98.0))
        gap = abs(bottom - float(ohi[2]))
        inside = bool(np.all(centre >= olo[:2] - EDGE_M) and np.all(centre <= ohi[:2] + EDGE_M))
        if gap <= STANDS_ON_M and inside and (best is None or gap < best[0]):
            best = (gap, i)
    return None if best is None else best[1]


STRAY_VOXEL_M = 0.01  # mask points further apart than this in 3D belong to different surfaces
STRAY_SHARE = 0.15  # a 3D-separate piece under this share of the mask is a stray (what stands in front, spilled)


def without_strays(mask: np.ndarray, frame: CameraFrame) -> np.ndarray:
    """The mask without the pixels of small pieces that are apart in 3D from the rest (26-neighbour voxels of
    STRAY_VOXEL_M). A mask found at half resolution and scaled up takes the edge of whatever stands in front of the
    object (a wine bottle before a bowl, a bowl before a bottle): those pixels are centimetres nearer the camera,
    drag the keypoint towards them and, for a bowl, raise its seen top, which then cuts the bowl's own lower half
    away as "support". Pieces touching in space stay (the table
    under the object is cut elsewhere); so does every piece of a mask that falls apart into large ones."""
    vs, us = mask_pixels(mask)
    z = frame.depth_m[vs, us]
    ok = np.isfinite(z) & (z > 0)
    if ok.sum() < 20:
        return mask
    vs, us = vs[ok], us[ok]
    lab = voxel_components(frame.backproject(us.astype(float), vs.astype(float), z[ok]), STRAY_VOXEL_M)
    if lab is None or lab.max() <= 1:  # spread over meters (other filters handle it), or all one piece
        return mask
    share = np.bincount(lab) / len(lab)
    stray = share[lab] < STRAY_SHARE
    if stray.all():
        return mask
    out = mask.copy()
    out[vs[stray], us[stray]] = False
    return out


def voxel_components(pts_m: np.ndarray, voxel_m: float) -> np.ndarray | None:
    """Per point (N, 3 world m), the label (1..n) of the 3D piece it belongs to: points in 26-neighbouring voxels
    of `voxel_m` are one piece. None when the points spread over more than 400 voxels along an axis (meters: not
    one object's surface)."""
    from scipy import ndimage

    vox = np.floor((pts_m - pts_m.min(0)) / voxel_m).astype(np.int64)
    if (vox.max(0) > 400).any():
        return None
    grid = np.zeros(tuple(vox.max(0) + 1), bool)
    grid[tuple(vox.T)] = True
    labels, _ = ndimage.label(grid, structure=np.ones((3, 3, 3)))
    return labels[tuple(vox.T)]
