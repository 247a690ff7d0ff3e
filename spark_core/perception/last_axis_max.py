"""The largest channel per pixel of a channels-last score map: the learned segmenter's category map (the network's
output is channels-last, so one pixel's 40 probabilities are contiguous and numpy's argmax along them is fast)."""

from __future__ import annotations

import numpy as np


def last_axis_max(scores: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(h, w, C) scores -> the largest per pixel (h, w) and the first channel that holds it (int64): exactly
    torch's `max(-1)` on CPU (numpy's argmax returns the first maximum, so ties go to the lower channel). NaN is
    refused (argmax would name its channel)."""
    if scores.ndim != 3 or scores.shape[-1] == 0:
        raise ValueError(f"last_axis_max wants (h, w, C) scores with C >= 1, got shape {scores.shape}")
    index = scores.argmax(-1)
    best = np.take_along_axis(scores, index[..., None], -1)[..., 0]
    if np.isnan(best).any():
        raise ValueError("last_axis_max: scores contain NaN")
    return best, index
