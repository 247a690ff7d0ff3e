"""Revision 0009: events' simulated time (t_sim) and trials' wall seconds per phase (phases_s), stored and read
back, and the migration both ways with rows in the tables (SQLite file and PostgreSQL)."""

from sqlalchemy import inspect

from spark_core.trace import TraceStore


def columns(store, table):
    return {c["name"] for c in inspect(store.engine).get_columns(table)}


def test_migration_0009_up_and_down_keeps_the_rows(store_url):
    store = TraceStore(store_url)
    assert "t_sim" in columns(store, "events") and "phases_s" in columns(store, "trials")
    store.create_trial("a", task="lift_block", status="done", phases_s={"setup": 0.5, "execution": 2.0})
    store.add_events("a", [{"seq": 0, "t": 0.1, "t_sim": 1.5, "node_path": "tree", "kind": "started"}])
    got = store.get_trial("a")
    assert got["phases_s"] == {"setup": 0.5, "execution": 2.0}
    assert got["events"][0]["t_sim"] == 1.5 and got["events"][0]["t"] == 0.1
    store.downgrade("0008")
    assert "t_sim" not in columns(store, "events") and "phases_s" not in columns(store, "trials")
    store.upgrade("head")
    assert "t_sim" in columns(store, "events")
    got = store.get_trial("a")  # rows kept; the dropped values are gone, not invented
    assert got["phases_s"] is None and got["events"][0]["t_sim"] is None and got["events"][0]["t"] == 0.1


def test_a_recorded_trial_keeps_each_events_sim_time_and_its_phases(tmp_path):
    from spark_core.trace.sink import StoreSink
    from spark_core.trial import TrialConfig, run_trial

    store = TraceStore(f"sqlite:///{tmp_path / 'trace.db'}")
    out = run_trial(TrialConfig("lift_block", segmenter="sim"), [StoreSink(store, tmp_path / "artifacts")])
    trial = store.get_trial(out.trial_id)
    assert [e["t_sim"] for e in trial["events"]] == [e.t_sim for e in out.result.events]
    assert all(e["t_sim"] is not None for e in trial["events"])
    assert trial["phases_s"] == out.phases_s and {"setup", "execution"} <= set(trial["phases_s"])
