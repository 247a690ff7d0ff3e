"""Masks refined at camera resolution by depth: the per-pixel network works at half resolution and loses thin parts
(a wine bottle's neck, 1-2 network pixels wide, comes out as background), which moves the object's seen top
down by centimetres and a top-down grasp into its shoulder. A mask grows into neighbouring pixels the network
called background or table when their depth continues the mask's (a surface, not a jump to what lies behind)
and they stand above the table top (the table the object stands on continues its depth at the contact line).
Growth only climbs (each new pixel higher in the world than the one it continues): it recovers tops, and does not
spread sideways over a surface the object touches."""

from __future__ import annotations

import numpy as np

from ..pixels import mask_pixels

GROW_STEPS = 24  # camera pixels a mask may grow (a 4 cm neck at 1 m is about 24 px)
GROW_DEPTH_M = 0.01  # a neighbour continues the surface when its depth differs by less than this
ABOVE_TABLE_M = 0.01  # grown pixels stand at least this far above the table top


def grow_by_depth(
    mask: np.ndarray, free: np.ndarray, depth_m: np.ndarray, height_m: np.ndarray, table_z_m: float
) -> np.ndarray:
    """`mask` grown by up to GROW_STEPS pixels (4-connected) into `free` pixels whose depth (m) is within
    GROW_DEPTH_M of the mask neighbour they touch and whose world height (`height_m`, m) is ABOVE_TABLE_M over
    `table_z_m`, and higher than that neighbour. Works on the mask's bounding box widened by GROW_STEPS."""
    vs, us = mask_pixels(mask)
    if not len(vs):
        return mask
    H, W = mask.shape
    r0, r1 = max(0, vs.min() - GROW_STEPS), min(H, vs.max() + GROW_STEPS + 1)
    c0, c1 = max(0, us.min() - GROW_STEPS), min(W, us.max() + GROW_STEPS + 1)
    m = mask[r0:r1, c0:c1].copy()
    d = np.nan_to_num(depth_m[r0:r1, c0:c1].astype(np.float64), nan=np.inf, posinf=np.inf)
    ok = free[r0:r1, c0:c1] & (height_m[r0:r1, c0:c1] > table_z_m + ABOVE_TABLE_M) & np.isfinite(d)
    h = height_m[r0:r1, c0:c1]
    dp = np.pad(d, 1, constant_values=np.inf)
    hp = np.pad(h, 1, constant_values=np.inf)
    shifts = (
        (slice(0, -2), slice(1, -1)),
        (slice(2, None), slice(1, -1)),
        (slice(1, -1), slice(0, -2)),
        (slice(1, -1), slice(2, None)),
    )
    # per neighbour (above, below, left, right of each pixel): whether a pixel may grow from it; fixed while the
    # mask grows, so computed once
    may = [ok & (np.abs(d - dp[rows, cols]) < GROW_DEPTH_M) & (h > hp[rows, cols]) for rows, cols in shifts]
    for _ in range(GROW_STEPS):
        mp = np.pad(m, 1)
        added = np.zeros_like(m)
        for (rows, cols), may_k in zip(shifts, may):
            added |= mp[rows, cols] & may_k
        added &= ~m
        if not added.any():
            break
        m |= added
    out = mask.copy()
    out[r0:r1, c0:c1] = m
    return out
