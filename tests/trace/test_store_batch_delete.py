"""TraceStore.delete_batch removes the batch's record only: its trials stay, each still naming its batch, on a
SQLite file and on PostgreSQL."""

from spark_core.trace import TraceStore


def test_deleting_a_batch_keeps_its_trials(store_url):
    store = TraceStore(store_url)
    store.create_batch("b-1", {"suite": "builtin", "manifest": {"id": "m1"}})
    store.create_batch("b-2", {"suite": "builtin"})
    for tid, bid in (("t1", "b-1"), ("t2", "b-1"), ("t3", "b-2")):
        store.create_trial(tid, task="lift_block", batch_id=bid, status="done", success=True)
    store.add_events("t1", [{"seq": 0, "t": 0.0, "node_path": "tree", "kind": "started", "detail": {}}])
    assert store.has_batch("b-1")

    assert store.delete_batch("b-1") is True
    assert store.get_batch("b-1") is None and not store.has_batch("b-1")
    assert [b["id"] for b in store.list_batches()[1]] == ["b-2"]
    assert store.trial_ids(batch="b-1") == ["t1", "t2"]  # kept, still naming the batch they ran in
    t1 = store.get_trial("t1")
    assert t1 is not None and t1["batch_id"] == "b-1" and t1["success"] is True and len(t1["events"]) == 1
    assert store.list_trials(batch="b-1")[0] == 2
    assert store.get_batch("b-2") is not None and store.trial_ids(batch="b-2") == ["t3"]  # the other untouched
    assert store.delete_batch("b-1") is False and store.delete_batch("nope") is False
