"""Ray loses nothing: a batch on a real two-node Ray cluster on this machine (`ray start --head` and a second
`ray start --address`), its workers killed with SIGKILL mid-trial; the trials they ran are retried and the trace
store (SQLite and PostgreSQL) ends with every trial exactly once, each with one attempt's events.

The default run kills the workers running trials; killing the whole second node is the slow variant (Ray must
first notice the node is gone)."""

from __future__ import annotations

import threading
import time

import pytest

from spark_core.bench import reference_suite
from spark_core.trace import TraceStore
from spark_core.trial import TrialConfig
from tests.bench.ray_cluster import ENV, RayCluster

# Paced at 2x real time: a trial lasts a few wall seconds (long enough to be caught running) at little CPU
TEMPLATE = TrialConfig("", segmenter="privileged-keypoints", pacing=0.5)
TASKS = ["lift_block", "push_to_zone"]


@pytest.fixture(scope="module")
def cluster():
    c = RayCluster()
    try:
        c.start()
    except Exception:
        c.stop()
        raise
    yield c
    c.stop()


@pytest.fixture(autouse=True)
def ray_env(monkeypatch):
    for k, v in ENV.items():
        monkeypatch.setenv(k, v)


def _kill_mid_trial(store_url: str, kill, stop: threading.Event, killed: list[int]) -> None:
    """Once a trial of the batch has recorded events (it is mid-trial), kill once."""
    store = TraceStore(store_url, migrate=False)
    while not stop.is_set():
        try:
            running = store.list_trials(status="running")[1]
        except Exception:  # the batch's tables may not exist yet
            running = []
        if any(store.get_trial(t["id"])["events"] for t in running):
            killed.extend(kill())
            if killed:
                return
        time.sleep(0.05)


def _run_killing(cluster: RayCluster, store_url: str, kill, seeds: int) -> tuple[list[dict], list[int]]:
    TraceStore(store_url)  # migrated before the killer looks
    stop, killed = threading.Event(), []
    killer = threading.Thread(target=_kill_mid_trial, args=(store_url, kill, stop, killed), daemon=True)
    killer.start()
    try:
        rows = reference_suite.run(
            TASKS, seeds, seed=0, template=TEMPLATE, executor="ray", ray_address=cluster.address, store_url=store_url
        )
    finally:
        stop.set()
        killer.join(5)
    return rows, killed


def _assert_exactly_once(store_url: str, rows: list[dict], seeds: int) -> list[dict]:
    expected = {(t, s) for t in TASKS for s in range(seeds)}
    assert len(rows) == len(expected) and {(r["task"], r["seed"]) for r in rows} == expected
    store = TraceStore(store_url)
    ids = store.trial_ids()
    assert sorted(ids) == sorted(r["trial_id"] for r in rows)  # one record per trial, under the id decided up front
    trials = [store.get_trial(i) for i in ids]
    (batch,) = {t["batch_id"] for t in trials}
    assert len(store.get_batch(batch)["trials"]) == len(expected)
    for t, r in zip(trials, sorted(rows, key=lambda r: ids.index(r["trial_id"]))):
        assert t["status"] == "done" and t["verdict"] == r["verdict"] and t["success"] == r["success"]
        seqs = [e["seq"] for e in t["events"]]
        assert seqs == list(range(len(seqs))) and seqs  # one attempt's events: no duplicates, no gaps
    return trials


def test_killed_workers_trials_are_retried_and_stored_exactly_once(cluster, store_url):
    rows, killed = _run_killing(cluster, store_url, cluster.kill_trial_workers, seeds=1)
    assert killed, "no Ray worker was caught running a trial"
    trials = _assert_exactly_once(store_url, rows, seeds=1)
    retried = [t for t in trials if t["protocol"].get("attempt", 1) > 1]
    assert retried, "a killed worker's trial should have run again (attempt 2 in its record)"


@pytest.mark.slow
@pytest.mark.parametrize("backend", ["sqlite", "postgresql"])
def test_a_killed_node_loses_no_trial(backend, tmp_path, request):
    url = (
        f"sqlite:///{tmp_path / 'trace.db'}"
        if backend == "sqlite"
        else request.getfixturevalue("postgres_server").new_database()
    )
    c = RayCluster().start()
    try:
        rows, killed = _run_killing(c, url, c.kill_node2, seeds=2)
        assert killed
        _assert_exactly_once(url, rows, seeds=2)
    finally:
        c.stop()
