"""The trace store on a real SQLite file and on a real PostgreSQL server (the same SQLAlchemy URL): migrations
both ways, a recorded physics trial, queries, deletion."""

import sqlite3

import pytest
from sqlalchemy import func, inspect, select

from spark_core.trace import TraceStore
from spark_core.trace.models import EventRow


def tables(store):
    return set(inspect(store.engine).get_table_names())


def columns(store, table):
    return {c["name"] for c in inspect(store.engine).get_columns(table)}


def test_migrations_empty_to_head_down_and_up_again(store_url):
    store = TraceStore(store_url)
    assert {"trials", "events", "groundings", "batches", "plan_library", "leases", "alembic_version"} <= tables(store)
    if store_url.startswith("sqlite"):
        with sqlite3.connect(store_url[len("sqlite:///") :]) as c:
            assert c.execute("pragma journal_mode").fetchone()[0] == "wal"
    assert {"artifacts", "deleted_at", "verdict", "scene_states"} <= columns(store, "trials")
    store.create_trial("kept", task="lift_block", status="done", success=True)
    store.downgrade("0001")  # back to the first schema with a row in it: the later columns go, the row stays
    assert "artifacts" not in columns(store, "trials") and "leases" not in tables(store)
    store.downgrade("base")
    assert tables(store) & {"trials", "events", "groundings"} == set()
    store.upgrade("head")
    assert {"trials", "events", "groundings", "leases"} <= tables(store)
    store.create_trial("again", task="lift_block", status="done", success=False)
    assert store.list_trials(task="lift_block", success=False)[0] == 1


@pytest.fixture
def recorded(store_url):
    from spark_core.trace.sink import StoreSink
    from spark_core.trial import TrialConfig, run_trial

    store = TraceStore(store_url)
    out = run_trial(TrialConfig("lift_block", segmenter="sim"), [StoreSink(store)])
    return store, out


def test_a_physics_trial_is_recorded_completely(recorded):
    store, out = recorded
    total, rows = store.list_trials()
    assert total == 1
    trial = store.get_trial(rows[0]["id"])
    assert trial["status"] == "done" and trial["success"] is True and trial["outcome"] == "success"
    assert trial["verdict"] == "success" and trial["segmenter"] == "sim"
    assert trial["task"] == "lift_block" and trial["plan_text"].startswith("task: pick up the red block")
    assert [(e["node_path"], e["kind"]) for e in trial["events"]] == [(e.node_path, e.kind) for e in out.result.events]
    assert trial["groundings"] and trial["groundings"][0]["label"] == "red block"
    assert "chosen" in trial["groundings"][0]["cameras"]["agentview"]
    assert trial["protocol"]["privileged"] is True and "ORACLE" in trial["protocol"]["segmenter_description"]
    traj = trial["trajectory"]
    assert len(traj) > 100 and abs(traj[1][0] - traj[0][0] - 0.01) < 1e-6 and len(traj[0][2]) == 7
    assert trial["nodes"]["tree.children[0]"]["kind"] == "pick"


def test_queries_filter_sort_paginate_and_delete(store_url):
    store = TraceStore(store_url)
    for i in range(7):
        store.create_trial(
            f"t{i}",
            task="stack_two" if i % 2 else "lift_block",
            instruction=f"job {i}",
            success=bool(i % 3),
            status="done",
            wall_time_s=float(i),
        )
    store.add_events("t1", [{"seq": 0, "t": 0.0, "node_path": "tree", "kind": "started", "detail": {}}])
    assert store.list_trials(task="stack_two")[0] == 3
    assert store.list_trials(success=False)[0] == 3
    assert store.list_trials(task="stack_two", success=True)[0] == 2  # success beside a task: its own SQL on SQLite
    assert [r["id"] for r in store.list_trials(search="job 5")[1]] == ["t5"]
    total, page = store.list_trials(sort="wall_time_s", limit=3, offset=3)
    assert total == 7 and [r["id"] for r in page] == ["t3", "t4", "t5"]
    with pytest.raises(ValueError, match="cannot sort by 'nope'"):
        store.list_trials(sort="nope")
    assert store.delete_trial("t1") and store.get_trial("t1") is None and not store.delete_trial("t1")
    assert store.list_trials()[0] == 6 and "t1" not in store.trial_ids()  # hidden, still restorable
    assert store.restore_trial("t1", grace_s=60) and store.get_trial("t1")["id"] == "t1"
    assert store.purge_trial("t1") and not store.restore_trial("t1", grace_s=60)  # purged: gone for good
    with store.Session() as s:
        assert s.scalar(select(func.count()).select_from(EventRow)) == 0


def test_unfinished_trials_are_interrupted_not_lost(store_url):
    url = store_url
    store = TraceStore(url)
    store.create_trial("a", status="running")
    store.create_trial("b", status="queued")
    store.create_trial("c", status="done")
    again = TraceStore(url)  # a restarted server
    assert again.interrupt_unfinished() == 2
    assert again.get_trial("a")["status"] == "interrupted" and "server stopped" in again.get_trial("a")["reason"]
    assert {again.get_trial(t)["verdict"] for t in "ab"} == {"interrupted"}
    assert "before the trial started" in again.get_trial("b")["reason"]  # queued: it never ran
    assert again.get_trial("c")["status"] == "done"


def test_spark_run_records_and_spark_trials_lists(tmp_path, capsys):
    from spark_cli import main

    url = f"sqlite:///{tmp_path / 'cli.db'}"
    assert main(["run", "lift_block", "--segmenter", "privileged-keypoints", "--store", url]) == 0
    assert main(["trials", "--store", url]) == 0
    out = capsys.readouterr().out
    assert "1 trial(s)" in out and "lift_block" in out and "reference" in out
    trial_id = out.strip().splitlines()[-1].split()[2]
    assert main(["trials", "--store", url, "--id", trial_id]) == 0
    assert '"outcome": "success"' in capsys.readouterr().out
    assert main(["trials", "--store", url, "--id", "nope"]) == 1


def test_long_ids_fit_on_every_backend(store_url):
    store = TraceStore(store_url)  # PostgreSQL enforces VARCHAR lengths: a LIBERO-PRO task name alone is 108
    task = "libero_spatial_swap:pick_up_the_black_bowl_between_the_plate_and_the_ramekin_and_place_it_on_the_plate"
    trial_id = f"batch-0123456789-0042-{task}-49"
    store.create_batch("batch-0123456789", {"suite": "liberopro"})
    store.create_trial(trial_id, task=task, seed=49, batch_id="batch-0123456789", status="done")
    assert store.get_batch("batch-0123456789")["trials"][0]["id"] == trial_id


def test_a_retried_attempt_takes_over_its_trial_once(store_url):
    store = TraceStore(store_url)
    started = {"task": "lift_block", "seed": 3, "status": "running", "protocol": {"segmenter": "sim"}}
    assert store.begin_attempt("t-1", **started) == 1
    store.add_events("t-1", [{"seq": i, "t": 0.1 * i, "node_path": "tree", "kind": "started"} for i in range(3)])
    store.add_groundings("t-1", [{"label": "red block"}])
    # the worker died mid-trial; Ray runs it again under the same id
    assert store.begin_attempt("t-1", **started) == 2
    trial = store.get_trial("t-1")
    assert trial["events"] == [] and trial["groundings"] == [] and trial["protocol"]["attempt"] == 2
    assert store.list_trials()[0] == 1
    store.update_trial("t-1", status="done")
    store.create_trial("q-1", status="queued")  # the console's queue: its row is taken over as a first attempt
    assert store.begin_attempt("q-1", **started) == 1 and "attempt" not in store.get_trial("q-1")["protocol"]


def test_the_console_lease_has_one_holder_on_every_backend(store_url):
    from spark_core.trace.lease import LeaseHeld, StoreLease

    store = TraceStore(store_url)
    first, second = StoreLease(store), StoreLease(TraceStore(store_url, migrate=False))
    assert first.acquire() is None and first.renew()
    with pytest.raises(LeaseHeld, match="in use by another SPARK console"):
        second.acquire()
    first.release()
    assert second.acquire() is None and second.holder().owner == second.owner  # free again: taken
    assert not first.renew()


def test_a_plain_file_path_is_a_sqlite_store(tmp_path, capsys):
    """`--store var/x.db` (no URL scheme) is a SQLite file, for the CLI as for the library (it used to end in a
    SQLAlchemy traceback: 'Could not parse SQLAlchemy URL')."""
    from spark_cli import main
    from spark_core.trace.store import TraceStore

    path = tmp_path / "plain.db"
    store = TraceStore(str(path))
    assert store.url == f"sqlite:///{path}" and path.is_file()
    assert main(["trials", "--store", str(path)]) == 0
    assert "0 trial(s)" in capsys.readouterr().out
