"""Reclaiming closed worlds' memory: a full garbage collection every few trials of a process.

A closed robosuite world's MuJoCo model and data sit in reference cycles that only a full collection frees.
robosuite's own close runs one per trial (0.3-0.6 s once torch and the text encoder are loaded), which the worlds
skip; left to the automatic collector, a worker running CaP-Bench trials back to back grew ~70 MB a trial. One
collection every COLLECT_EVERY trials bounds that at a few hundred MB for ~0.05 s a trial."""

from __future__ import annotations

import gc

COLLECT_EVERY = 10  # trials

_closed_since_collect = [0]


def world_closed() -> None:
    """Count a closed world; every COLLECT_EVERY-th runs the full collection."""
    _closed_since_collect[0] += 1
    if _closed_since_collect[0] >= COLLECT_EVERY:
        _closed_since_collect[0] = 0
        gc.collect()
