"""Closed worlds' memory is reclaimed: a full garbage collection every few trials of a process (a closed robosuite
world's MuJoCo memory sits in reference cycles only a full collection frees: without it a CaP-Bench worker grew
~70 MB a trial)."""

from __future__ import annotations

import gc

from spark_core.sim import reclaim
from spark_core.trial import TrialConfig, run_trial


def test_every_tenth_closed_world_runs_a_full_collection(monkeypatch):
    collections: list[int] = []
    monkeypatch.setattr(gc, "collect", lambda *a: collections.append(1) or 0)
    monkeypatch.setattr(reclaim, "_closed_since_collect", [0])
    for _ in range(25):
        reclaim.world_closed()
    assert len(collections) == 25 // reclaim.COLLECT_EVERY == 2


def test_the_trial_pipeline_counts_the_world_it_closes(monkeypatch):
    monkeypatch.setattr(reclaim, "_closed_since_collect", [0])
    run_trial(TrialConfig("lift_block", segmenter="privileged-keypoints", time_limit_s=0.5))
    assert reclaim._closed_since_collect == [1]
