"""Batch executors: the local process pool and a local Ray cluster run the same trials to an outcome, with
per-phase timings, and return rows in job order (a smoke of each, not a benchmark)."""

import pytest

from spark_core.bench import reference_suite
from spark_core.bench.executors import run_jobs
from spark_core.trial import TrialConfig

PRIVILEGED = TrialConfig("", segmenter="privileged-keypoints")


@pytest.mark.parametrize("executor,workers", [("local", 1), ("local", 2), ("ray", 2)])
def test_executor_runs_trials_to_an_outcome_in_job_order(executor, workers, tmp_path):
    from spark_core.trace import TraceStore

    seen = []
    url = f"sqlite:///{tmp_path / 'bench.db'}"
    rows = reference_suite.run(
        ["lift_block", "push_to_zone"],
        1,
        seed=3,
        workers=workers,
        progress=seen.append,
        template=PRIVILEGED,
        executor=executor,
        store_url=url,
    )
    store = TraceStore(url)
    recorded = [store.get_trial(i) for i in store.trial_ids()]
    (batch_id,) = {t["batch_id"] for t in recorded}  # one batch, which the console's batch page can show
    assert len(store.get_batch(batch_id)["trials"]) == 2 and all(t["events"] for t in recorded)
    assert sorted((t["task"], t["seed"], t["success"]) for t in recorded) == sorted(
        (r["task"], r["seed"], r["success"]) for r in rows
    )
    assert [(r["task"], r["seed"]) for r in rows] == [("lift_block", 3), ("push_to_zone", 3)]
    assert len(seen) == 2 and all(r["tree_status"] in ("success", "failure") for r in rows)
    for r in rows:
        assert set(r["phases_s"]) == set(reference_suite.PHASES) and r["phases_s"]["simulation"] > 0
        assert sum(r["phases_s"].values()) <= r["wall_time_s"] + 0.05


def test_unknown_executor_is_named():
    with pytest.raises(ValueError, match="unknown executor 'slurm'; available: local, ray"):
        run_jobs(len, [], executor="slurm")
