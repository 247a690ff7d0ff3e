"""A bench worker runs a full garbage collection every few trials (closed robosuite worlds' MuJoCo memory sits in
reference cycles only a full collection frees: without it a CaP-Bench worker grew ~70 MB a trial)."""

from __future__ import annotations

import gc

from spark_core.bench import reference_suite
from spark_core.trial import TrialConfig


class _Outcome:
    def row(self) -> dict:
        return {"success": True}


def test_a_worker_collects_every_ten_trials(monkeypatch):
    collections: list[int] = []
    monkeypatch.setattr(reference_suite, "run_trial", lambda *a, **k: _Outcome())
    monkeypatch.setattr(gc, "collect", lambda *a: collections.append(1) or 0)
    monkeypatch.setattr(reference_suite, "_TRIALS_SINCE_COLLECT", [0])
    for i in range(25):
        assert reference_suite._one((TrialConfig("lift_block", seed=i), None, f"t{i}", None)) == {"success": True}
    assert len(collections) == 25 // reference_suite.COLLECT_EVERY == 2
