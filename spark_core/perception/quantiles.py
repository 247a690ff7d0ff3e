"""Percentiles, fast: the learned segmenter's clean-ups take thousands of them per frame on small point sets, where
`np.percentile`'s own bookkeeping costs more than the partition it does."""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np


def percentiles(values: np.ndarray, qs_percent: Sequence[float]) -> list[np.ndarray]:
    """For each q in qs_percent (0-100), exactly `np.percentile(values, q, axis=0)` (numpy's default "linear"
    method, q a Python number): one partition shared by every q.

    values: (n,) or (n, k) with n >= 1; each result has the shape of one row (a 0-d array for 1-D values). The
    order statistics a percentile interpolates between are the same numbers whichever kth the partition is given,
    and the interpolation below is numpy's own (its `_lerp`, with the weight as a Python float), so the results
    are bit-identical; a test pins that against `np.percentile`. NaN is not supported (numpy propagates it; the
    clean-ups' points are finite), and is refused."""
    n = values.shape[0]
    if n == 0:
        raise ValueError("percentiles of an empty array")
    if np.isnan(values).any():
        raise ValueError("percentiles: values contain NaN")
    spots = _spots(n, qs_percent)
    part = np.partition(values, sorted({i for lo, hi, _ in spots for i in (lo, hi)}), axis=0)
    return _interpolated(part, spots)


def percentiles_of_sorted(sorted_values: np.ndarray, qs_percent: Sequence[float]) -> list[np.ndarray]:
    """`percentiles` of values already sorted along axis 0 (each column on its own): the same order statistics
    read by index, no partition, so the same numbers bit for bit. The caller keeps the columns sorted (e.g. two
    sorted sets joined by a stable sort, which merges the runs in linear time); not checked here."""
    n = sorted_values.shape[0]
    if n == 0:
        raise ValueError("percentiles of an empty array")
    return _interpolated(sorted_values, _spots(n, qs_percent))


def _spots(n: int, qs_percent: Sequence[float]) -> list[tuple[int, int, float]]:
    """Per q: the two order statistics (0-based ranks) numpy's linear percentile interpolates between, and the
    weight of the upper one."""
    spots: list[tuple[int, int, float]] = []
    for q in qs_percent:
        if not 0.0 <= q <= 100.0:
            raise ValueError(f"percentile {q} is outside 0..100")
        at = (n - 1) * (q / 100)  # numpy: virtual index (n - 1) * q, q = np.true_divide(q, 100)
        if at >= n - 1:
            spots.append((n - 1, n - 1, at + 1))  # numpy takes the last element twice (its weight is moot)
        else:
            lo = math.floor(at)
            spots.append((lo, lo + 1, at - lo))
    return spots


def _interpolated(ordered: np.ndarray, spots: list[tuple[int, int, float]]) -> list[np.ndarray]:
    """numpy's `_lerp` between the order statistics at each spot's ranks (`ordered` holds them at those ranks)."""
    out = []
    for lo, hi, t in spots:
        a, b = ordered[lo], ordered[hi]
        diff = b - a
        out.append(np.asarray(b - diff * (1 - t) if t >= 0.5 else a + diff * t))
    return out


def percentile(values: np.ndarray, q_percent: float) -> np.ndarray:
    """Exactly `np.percentile(values, q_percent, axis=0)` (see `percentiles`)."""
    return percentiles(values, (q_percent,))[0]
