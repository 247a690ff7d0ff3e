"""A drawer's mask kept to where a drawer can be: below its cabinet's top and centred on its handle.

The per-pixel network paints the cabinet face around a drawer as drawer where the wood looks the same: an open
drawer's mask seen from above takes part of the cabinet's top, and a drawer front seen edge-on takes the strip of
face above or beside it. The keypoint comes from the mask's highest points (lifting.keypoint_from_points), so those
spills moved a builtin drawer's keypoint 4-7 cm (the perception bench's keypoint tail). Two facts about drawers,
from the frame's depth and camera pose only: a drawer slides inside its cabinet, so none of it reaches the
cabinet's top face; and a drawer's handle sits at the middle of its front, so the drawer reaches equally far to
both sides of it across the front's width. The second is used only where the mask's own ends say little: a front
seen edge-on, where one pixel of mask error spans centimetres of the front (seen more squarely, a LIBERO drawer's
mask is better than the handle's centre, which sits a centimetre or two off the seen front's middle)."""

from __future__ import annotations

import numpy as np

from ..frame import CameraFrame
from ..pixels import mask_pixels
from ..quantiles import percentile, percentiles

BELOW_TOP_M = 0.01  # drawer points within this of the cabinet's top height (m) are the cabinet's top face
MIN_POINTS = 20  # fewer finite-depth pixels than this: too little to judge, the mask is kept
EDGE_ON_COS = 0.5  # a front is seen edge-on when the horizontal view ray is within 60 deg of lying in its plane
FRONT_DEPTH_M = 0.03  # a mask this thin across the front's plane (m) is the front alone: the drawer is shut


def mask_points(mask: np.ndarray, frame: CameraFrame, n: int = 0) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Rows, columns and world points (m) of the mask's pixels with a finite depth (n > 0: about n of them,
    evenly spaced)."""
    vs, us = mask_pixels(mask)
    if n and len(vs) > n:
        vs, us = vs[:: len(vs) // n], us[:: len(vs) // n]
    z = frame.depth_m[vs, us]
    ok = np.isfinite(z) & (z > 0)
    vs, us = vs[ok], us[ok]
    return vs, us, frame.backproject(us.astype(float), vs.astype(float), z[ok])


def _mask_of(shape: tuple[int, ...], vs: np.ndarray, us: np.ndarray) -> np.ndarray:
    out = np.zeros(shape, bool)
    out[vs, us] = True
    return out


def below_cabinet_top(drawer: np.ndarray, cabinets: list[np.ndarray], frame: CameraFrame) -> np.ndarray:
    """The drawer mask without the pixels at or above the top of the cabinet it is in (the highest of the touching
    cabinets' seen tops, m): those are the cabinet's top face. The mask itself when nothing would be left."""
    tops = []
    for c in cabinets:
        _, _, pts = mask_points(c, frame, n=2000)  # a percentile of its heights: a sample does
        if len(pts) >= MIN_POINTS:
            tops.append(float(percentile(pts[:, 2], 98)))
    vs, us, pts = mask_points(drawer, frame)
    if not tops or len(pts) < MIN_POINTS:
        return drawer
    keep = pts[:, 2] < max(tops) - BELOW_TOP_M
    if keep.sum() < MIN_POINTS:
        return drawer
    return _mask_of(drawer.shape, vs[keep], us[keep])


def front_width_axis(handle_points_m: np.ndarray) -> np.ndarray | None:
    """Unit world xy direction across a drawer front, from its handle's points (m): a handle is a bar along the
    front, lying (its xy spread is the front's width) or standing (its xy spread is how far it stands off the
    front, so the width is across that). None when the handle shows no clear long axis in xy."""
    xy = handle_points_m[:, :2] - handle_points_m[:, :2].mean(0)
    evals, evecs = np.linalg.eigh(xy.T @ xy / len(xy))
    if evals[1] < 4 * max(evals[0], 1e-12):
        return None
    lo, hi = percentiles(handle_points_m, (2, 98))
    across_lo, across_hi = percentiles(xy @ evecs[:, 1], (2, 98))
    spread = across_hi - across_lo
    standing = hi[2] - lo[2] > spread
    return evecs[:, 0] if standing else evecs[:, 1]


def centred_on_handle(drawer: np.ndarray, handle: np.ndarray, frame: CameraFrame) -> np.ndarray:
    """A shut drawer's front seen edge-on: its mask cut to the same reach on both sides of its handle across the
    front's width (front_width_axis): the side that reaches further took the cabinet face beside the drawer. The
    mask itself when the front is seen more squarely, when the width direction is not observable, or when the
    mask reaches back from the front (an open drawer's side wall: there the front's far end is hidden behind the
    wall, not spilled, and cutting to it would drop the wall)."""
    _, _, h = mask_points(handle, frame)
    vs, us, pts = mask_points(drawer, frame)
    if len(h) < MIN_POINTS or len(pts) < MIN_POINTS:
        return drawer
    axis = front_width_axis(h)
    if axis is None:
        return drawer
    ray = np.median(h[:, :2], axis=0) - frame.T_world_camera[:2, 3]
    normal = np.array([-axis[1], axis[0]])
    if abs(float(ray @ normal)) >= EDGE_ON_COS * float(np.linalg.norm(ray)):
        return drawer
    across = pts[:, :2] @ normal
    across_lo, across_hi = percentiles(across, (2, 98))
    if float(across_hi - across_lo) > FRONT_DEPTH_M:
        return drawer
    centre = float(np.median(h[:, :2] @ axis))
    s = pts[:, :2] @ axis - centre
    s_lo, s_hi = percentiles(s, (2, 98))
    reach = min(float(s_hi), float(-s_lo))
    if reach <= 0:  # the handle is past the drawer's seen end: nothing to centre on
        return drawer
    keep = np.abs(s) <= reach
    if keep.sum() < MIN_POINTS:
        return drawer
    return _mask_of(drawer.shape, vs[keep], us[keep])
