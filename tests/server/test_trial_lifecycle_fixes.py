"""Deleted trials leave every cache and the LLM plan library; control answers say what is wrong (adversarial
review M5, L5, L6)."""

from __future__ import annotations

import time

import pytest
from fastapi.testclient import TestClient

from server.app import create_app
from server.settings import Settings


def _client(tmp_path) -> TestClient:
    settings = Settings(
        store_url=f"sqlite:///{tmp_path / 'l.db'}", workers=1, viser=False, artifacts_dir=str(tmp_path / "art")
    )
    return TestClient(create_app(settings))


def _finished_with_states(c: TestClient, trial_id: str) -> None:
    """A finished lift_block trial with one recorded scene state (its start), as a worker would record it."""
    from spark_core import TASKS

    world = TASKS["lift_block"].make_world(0)
    qpos = world.data.qpos.round(5).tolist()
    world.close()
    store = c.app.state.store  # type: ignore[attr-defined]
    store.create_trial(trial_id, status="done", task="lift_block", seed=0, verdict="success", success=True)
    store.update_trial(trial_id, scene_states=[[0.0, qpos]])


@pytest.mark.parametrize("purge", [False, True])
def test_a_deleted_trial_is_not_served_from_the_replay_cache(tmp_path, purge):
    with _client(tmp_path) as c:
        _finished_with_states(c, "t-replay")
        assert c.get("/api/trials/t-replay/camera.png?t_sim_s=0").status_code == 200  # builds and keeps its world
        assert c.delete(f"/api/trials/t-replay?purge={str(purge).lower()}").status_code == 200
        r = c.get("/api/trials/t-replay/camera.png?t_sim_s=0")
        assert r.status_code == 404 and "t-replay" in r.json()["detail"]


def test_a_deleted_trial_leaves_the_plan_library_and_a_purged_one_for_good(tmp_path):
    with _client(tmp_path) as c:
        store = c.app.state.store  # type: ignore[attr-defined]
        _finished_with_states(c, "t-lib")
        store.add_library_plan("lift the red block", "task: t\ntree: {primitive: wait}", trial_id="t-lib")
        store.add_library_plan("an operator's own example", "task: t\ntree: {primitive: wait}")
        assert c.delete("/api/trials/t-lib").status_code == 200
        assert [p["trial_id"] for p in store.library_plans()] == [None]  # hidden while it may be restored
        assert c.post("/api/trials/t-lib/restore").status_code == 200
        assert [p["trial_id"] for p in store.library_plans()] == ["t-lib", None]
        assert c.delete("/api/trials/t-lib?purge=true").status_code == 200
        assert [p["trial_id"] for p in store.library_plans()] == [None]
        assert c.post("/api/trials/t-lib/restore").status_code == 404  # and it cannot come back


def test_control_of_an_unknown_trial_is_404_and_of_a_finished_one_409(tmp_path):
    with _client(tmp_path) as c:
        _finished_with_states(c, "t-done")
        r = c.post("/api/trials/nope/control", json={"action": "pause"})
        assert r.status_code == 404 and "no trial 'nope'" in r.json()["detail"]
        assert c.post("/api/trials/t-done/control", json={"action": "pause"}).status_code == 409


def test_breakpoints_must_name_nodes_of_the_plan(tmp_path):
    with _client(tmp_path) as c:
        r = c.post("/api/trials", json={"task": "lift_block", "breakpoints": ["../../x"]})
        assert (
            r.status_code == 422
            and "no node '../../x'" in r.json()["detail"]
            and "tree.children[0]" in r.json()["detail"]
        )
        assert c.get("/api/trials").json()["total"] == 0


@pytest.mark.parametrize("bad", ["zzz", "", "tree.children[01]", "tree.children[-1]", "tree/children/0"])
def test_breakpoints_for_a_plan_not_yet_written_must_be_node_paths(tmp_path, bad):
    """The rules planner (and an LLM) write the plan when the trial runs, so its node names cannot be checked when
    it is queued; a breakpoint that is no node path at all could never fire, and was accepted silently."""
    with _client(tmp_path) as c:
        body = {"task": "lift_block", "planner": "rules", "breakpoints": ["tree.children[0]", bad]}
        r = c.post("/api/trials", json=body)
        assert r.status_code == 422 and f"breakpoints: {bad!r} is not a node path" in r.json()["detail"], r.text
        assert c.get("/api/trials").json()["total"] == 0


def _wait(c: TestClient, trial_id: str, state: str) -> None:
    t0 = time.monotonic()
    while c.get(f"/api/trials/{trial_id}").json().get("control_state") != state:
        assert time.monotonic() - t0 < 60, f"{trial_id} never became {state}"
        time.sleep(0.1)


def test_control_and_delete_of_live_trials_say_what_is_wrong(tmp_path):
    with _client(tmp_path) as c:
        body = {"task": "lift_block", "segmenter": "privileged-keypoints", "start_paused": True}
        first = c.post("/api/trials", json=body).json()["id"]
        second = c.post("/api/trials", json=body).json()["id"]  # one worker: this one waits in the queue
        _wait(c, first, "paused")
        r = c.delete(f"/api/trials/{second}")
        assert r.status_code == 409 and "still queued" in r.json()["detail"]
        r = c.post(f"/api/trials/{first}/control", json={"action": "breakpoints", "breakpoints": ["tree.children[9]"]})
        assert r.status_code == 422 and "tree.children[9]" in r.json()["detail"]
        r = c.post(f"/api/trials/{first}/control", json={"action": "pause", "breakpoints": ["tree.children[0]"]})
        assert r.status_code == 422 and "only with action 'breakpoints'" in r.json()["detail"]
        ok = c.post(f"/api/trials/{first}/control", json={"action": "breakpoints", "breakpoints": ["tree.children[0]"]})
        assert ok.status_code == 200 and ok.json()["breakpoints"] == ["tree.children[0]"]
        r = c.post(f"/api/trials/{first}/control", json={"action": "breakpoints"})  # no list: not "clear them all"
        assert r.status_code == 422 and "[] clears them" in r.json()["detail"]
        assert c.get(f"/api/trials/{first}").json()["breakpoints"] == ["tree.children[0]"]
        assert c.post(f"/api/trials/{second}/control", json={"action": "abort"}).status_code == 200
        resumed = c.post(f"/api/trials/{first}/control", json={"action": "resume"})
        assert resumed.status_code == 200 and resumed.json()["state"] == "running"  # not the pause it left
        assert c.post(f"/api/trials/{first}/control", json={"action": "abort"}).status_code in (200, 409)
        # aborted (still winding down) or already finished: either way nothing to resume
        assert c.post(f"/api/trials/{first}/control", json={"action": "resume"}).status_code == 409


def test_a_trial_cancelled_while_queued_is_not_run_by_the_next_start(tmp_path):
    """Cancelled while it waited for a worker (here: none), then the console stopped before a slot reached it: it
    stayed queued in the store, and the next start ran it (a cancelled batch came back after a restart)."""
    settings = Settings(
        store_url=f"sqlite:///{tmp_path / 'q.db'}", workers=0, viser=False, artifacts_dir=str(tmp_path / "art")
    )
    with TestClient(create_app(settings)) as c:
        cancelled = c.post("/api/trials", json={"task": "lift_block"}).json()["id"]
        kept = c.post("/api/trials", json={"task": "lift_block", "seed": 1}).json()["id"]
        assert c.post(f"/api/trials/{cancelled}/control", json={"action": "abort"}).status_code == 200
    with TestClient(create_app(settings)) as c:
        runner = c.app.state.runner  # type: ignore[attr-defined]
        assert cancelled not in runner.live and kept in runner.live  # only the one still wanted is queued again
        t = c.get(f"/api/trials/{cancelled}").json()
        assert (t["status"], t["verdict"], t["reason"]) == ("done", "aborted", "cancelled before it started")
        assert c.get(f"/api/trials/{kept}").json()["status"] == "queued"


def test_a_cancelled_batch_s_trials_left_queued_by_a_dead_server_are_not_run_at_the_next_start(tmp_path):
    """The batch is recorded cancelled, but its server died before it recorded the queued trials so: the next start
    queued them again and ran them. A trial of another batch, and one of no batch, still run."""
    from server.trials.runner import TrialRunner
    from spark_core import TraceStore, TrialConfig

    store = TraceStore(f"sqlite:///{tmp_path / 'b.db'}")
    dead = TrialRunner(store, workers=0)  # a console that queued them, then died without shutting down
    for batch in ("batch-cancelled", "batch-running"):
        store.create_batch(batch, {"suite": "builtin", "trial_count": 1})
        dead.submit(f"{batch}-0000-lift_block-0", TrialConfig("lift_block", batch_id=batch).check())
    dead.submit("solo", TrialConfig("lift_block").check())
    store.set_batch_status("batch-cancelled", "cancelled")

    again = TrialRunner(store, workers=0)
    assert again.requeue_recorded() == (2, 0)
    assert sorted(again.live) == ["batch-running-0000-lift_block-0", "solo"]
    t = store.get_trial("batch-cancelled-0000-lift_block-0")
    assert (t["status"], t["verdict"], t["reason"]) == ("done", "aborted", "cancelled before it started")
