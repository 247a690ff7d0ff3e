"""TraceStore.list_batches (newest first, trials counted, deleted ones too) and sorting trials by batch and
failing module, on a SQLite file and on PostgreSQL."""

import time

from spark_core.trace import TraceStore


def test_batches_are_listed_newest_first_with_their_live_trials_counted(store_url):
    store = TraceStore(store_url)
    assert store.list_batches() == (0, [])
    store.create_batch("b-old", {"suite": "builtin", "manifest": {"id": "m1"}})
    time.sleep(0.01)  # distinct created_at
    store.create_batch("b-new", {"suite": "builtin"})
    rows = [
        ("t1", "b-old", "done", True),
        ("t2", "b-old", "interrupted", False),
        ("t3", "b-old", "running", None),
        ("t4", "b-old", "done", True),  # deleted below: still counted (a delete must not rewrite results)
        ("t5", None, "done", True),  # in no batch
    ]
    for tid, bid, status, success in rows:
        store.create_trial(tid, task="lift_block", batch_id=bid, status=status, success=success)
    store.delete_trial("t4")
    store.set_batch_status("b-new", "cancelled")
    total, items = store.list_batches()
    assert total == 2 and [b["id"] for b in items] == ["b-new", "b-old"]
    new, old = items
    assert new["status"] == "cancelled" and new["progress"] == {"done": 0, "total": 0, "successes": 0}
    assert old["progress"] == {"done": 3, "total": 4, "successes": 2}
    assert old["spec"]["manifest"] == {"id": "m1"} and "T" in old["created_at"]
    assert store.list_batches(limit=1, offset=1)[1][0]["id"] == "b-old"


def test_trials_sort_by_batch_and_by_failing_module(store_url):
    store = TraceStore(store_url)
    for tid, bid, failure in [("a", "b2", "perception"), ("b", "b1", "execution"), ("c", "b3", "planner")]:
        store.create_trial(tid, task="lift_block", batch_id=bid, failure=failure, status="done")
    assert [t["id"] for t in store.list_trials(sort="batch_id")[1]] == ["b", "a", "c"]
    assert [t["id"] for t in store.list_trials(sort="-failure")[1]] == ["c", "a", "b"]


def test_empty_values_sort_as_the_smallest_on_every_backend(store_url):
    store = TraceStore(store_url)
    for tid, failure in [("a", "perception"), ("b", None), ("c", "execution")]:
        store.create_trial(tid, task="lift_block", failure=failure, status="done")
    assert [t["id"] for t in store.list_trials(sort="failure")[1]] == ["b", "c", "a"]
    assert [t["id"] for t in store.list_trials(sort="-failure")[1]] == ["a", "c", "b"]
