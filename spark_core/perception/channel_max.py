"""The largest channel per pixel, fast: the learned segmenter takes it over 40 category probabilities per frame."""

from __future__ import annotations

import numpy as np


def channel_max(probs: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(C, h, w) scores -> the largest per pixel (h, w) and the first channel that holds it (int64): exactly
    torch's `max(0)` on CPU (ties go to the lower channel).

    Reducing over the leading, strided axis is slow in torch (values and indices at once) and numpy's argmax
    along it is slower still; numpy's max along it is vectorised over pixels, and one comparison per channel,
    highest first, leaves the lowest channel that equals the max. NaN is refused (torch would propagate it)."""
    if probs.ndim != 3 or probs.shape[0] == 0:
        raise ValueError(f"channel_max wants (C, h, w) scores with C >= 1, got shape {probs.shape}")
    best = probs.max(0)
    if np.isnan(best).any():
        raise ValueError("channel_max: scores contain NaN")
    index = np.zeros(best.shape, np.int64)
    for c in range(probs.shape[0] - 1, 0, -1):
        index[probs[c] == best] = c
    index[probs[0] == best] = 0
    return best, index
