"""Stacked drawers seen as one: the per-pixel network paints a cabinet's drawer fronts as one "drawer" region
(they touch, share a colour and a depth), while each drawer's handle is an instance of its own. "The middle
drawer" is then the band of drawer pixels at the height of the handle the qualifier picks, between the midpoints
to the handles above and below it."""

from __future__ import annotations

import numpy as np

from ..frame import CameraFrame
from ..pixels import mask_pixels
from ..qualifiers import QUALIFIERS
from .drawers import mask_points

LONE_HALF_M = 0.04  # half a drawer front's height (m) when only one handle is seen
SAME_LAYER_M = 0.02  # handle pieces whose heights differ by less are one handle


def is_stacked(qualifier: str | None) -> bool:
    """Whether a qualifier picks among instances stacked in height ("top", "middle", "bottom", ...)."""
    return qualifier is not None and qualifier in QUALIFIERS and QUALIFIERS[qualifier][0] == 2


def layer_heights_m(handles: list[np.ndarray], frame: CameraFrame) -> list[float]:
    """World heights (m, ascending) of the handle layers: one per drawer whose handle is seen, a handle seen as
    two pieces counted once."""
    zs: list[float] = []
    for h in sorted(h for h in (median_height_m(m, frame) for m in handles) if h is not None):
        if not zs or h - zs[-1] > SAME_LAYER_M:
            zs.append(h)
    return zs


def _band_m(zs: list[float], k: int) -> tuple[float, float]:
    """The height band (m) of layer k: between the midpoints to the layers below and above; the outermost as tall
    as the rest."""
    half = float(np.median(np.diff(zs))) / 2 if len(zs) > 1 else LONE_HALF_M
    lo = (zs[k - 1] + zs[k]) / 2 if k > 0 else zs[k] - half
    hi = (zs[k] + zs[k + 1]) / 2 if k + 1 < len(zs) else zs[k] + half
    return lo, hi


def _heights_m(drawer: np.ndarray, frame: CameraFrame) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Pixel rows, columns and world heights (m) of the mask's pixels with a finite depth."""
    vs, us, pts = mask_points(drawer, frame)
    return vs, us, pts[:, 2]


def layer_mask(drawer: np.ndarray, handles: list[np.ndarray], qualifier: str, frame: CameraFrame) -> np.ndarray | None:
    """The pixels of the `drawer` mask (one or several stacked drawer fronts) that belong to the drawer whose
    handle `qualifier` picks among `handles` (masks); None when no handle or no drawer pixel is in that band."""
    zs = layer_heights_m(handles, frame)
    if not zs:
        return None
    sign = QUALIFIERS[qualifier][1]
    k = len(zs) // 2 if sign == 0.0 else (len(zs) - 1 if sign > 0 else 0)
    lo, hi = _band_m(zs, k)
    vs, us, height = _heights_m(drawer, frame)
    inside = (height >= lo) & (height < hi)
    if not inside.any():
        return None
    out = np.zeros_like(drawer)
    out[vs[inside], us[inside]] = True
    return out


def split_layers(drawer: np.ndarray, handles: list[np.ndarray], frame: CameraFrame) -> list[np.ndarray]:
    """The `drawer` mask cut into one mask per handle layer, each pixel to the layer whose band holds its height
    (the bottom and top bands open-ended: the mask bounds them); the mask itself when fewer than two layers are
    seen. Instances of drawers, not of one painted region: "the drawer" in a three-drawer cabinet is ambiguous,
    and each front's keypoint is its own."""
    zs = layer_heights_m(handles, frame)
    if len(zs) < 2:
        return [drawer]
    vs, us, height = _heights_m(drawer, frame)
    cuts = [(zs[k] + zs[k + 1]) / 2 for k in range(len(zs) - 1)]
    layer = np.searchsorted(cuts, height, side="right")
    out = []
    for k in range(len(zs)):
        m = np.zeros_like(drawer)
        m[vs[layer == k], us[layer == k]] = True
        if m.any():
            out.append(m)
    return out


def median_height_m(mask: np.ndarray, frame: CameraFrame, n: int = 400) -> float | None:
    """Median world height (m) of up to n evenly spaced pixels of the mask with a finite depth."""
    vs, us = mask_pixels(mask)
    if not len(vs):
        return None
    step = max(1, len(vs) // n)
    vs, us = vs[::step], us[::step]
    z = frame.height_map_m[vs, us]
    ok = np.isfinite(z)
    if not ok.any():
        return None
    return float(np.median(z[ok]))
