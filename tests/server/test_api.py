"""The REST API against a real SQLite file, with real trials running in the server's worker processes."""

import time

import pytest
from fastapi.testclient import TestClient

from server.app import create_app
from server.settings import Settings


@pytest.fixture()
def client(tmp_path):
    app = create_app(
        Settings(store_url=f"sqlite:///{tmp_path / 'api.db'}", workers=2, artifacts_dir=str(tmp_path / "art"))
    )
    with TestClient(app) as c:
        yield c


def wait_done(client, trial_id, timeout=120.0):
    t0 = time.monotonic()
    while time.monotonic() - t0 < timeout:
        trial = client.get(f"/api/trials/{trial_id}").json()
        if trial["status"] in ("done", "interrupted"):
            return trial
        time.sleep(0.1)
    raise AssertionError(f"trial {trial_id} did not finish: {trial['status']}")


def wait_batch(client, batch_id, until, timeout=180.0):
    """Poll the batch until `until(batch)` holds; returns the last batch seen."""
    t0 = time.monotonic()
    while time.monotonic() - t0 < timeout:
        b = client.get(f"/api/batches/{batch_id}").json()
        if until(b):
            return b
        time.sleep(0.1)
    return b


def test_health_grammar_tasks_validate(client):
    assert client.get("/api/health").json() == {"status": "ok"}
    g = client.get("/api/grammar").json()
    assert len(g["primitives"]) >= 35 and "$defs" in g["json_schema"]
    assert any(t["name"] == "stack_two" for t in client.get("/api/tasks").json())
    bad = client.post(
        "/api/plans/validate", json={"text": "task: t\ntree: {primitive: grasp, params: {force: high}}"}
    ).json()
    assert not bad["ok"] and bad["errors"] == [
        {"path": "tree.params.force", "message": 'expected number in [0, 140], got "high"'}
    ]
    good = client.post("/api/plans/validate", json={"text": "task: t\ntree: {primitive: wait}"}).json()
    assert good["ok"] and good["canonical_yaml"].startswith("task: t")
    assert "/api/trials" in client.get("/openapi.json").json()["paths"]


def test_create_run_get_list_delete(client):
    r = client.post("/api/trials", json={"task": "lift_block", "segmenter": "privileged-keypoints", "seed": 2})
    assert r.status_code == 202 and r.json()["status"] == "queued"
    trial_id = r.json()["id"]
    trial = wait_done(client, trial_id)
    assert trial["success"] is True and trial["outcome"] == "success" and trial["plan_text"].startswith("task:")
    assert trial["events"][0]["kind"] == "started" and trial["events"][-1] == {
        **trial["events"][-1],
        "kind": "succeeded",
    }
    assert len(trial["trajectory"]) > 100
    page = client.get("/api/trials", params={"task": "lift_block"}).json()
    assert page["total"] == 1 and page["items"][0]["id"] == trial_id and "trajectory" not in page["items"][0]
    assert client.get("/api/trials", params={"sort": "bogus"}).status_code == 422
    assert client.delete(f"/api/trials/{trial_id}").json()["purged"] is False  # undoable: test_deletion.py
    assert client.get(f"/api/trials/{trial_id}").status_code == 404


def test_rules_planner_trial_and_planner_refusal(client):
    ok = client.post(
        "/api/trials",
        json={
            "task": "stack_two",
            "planner": "rules",
            "segmenter": "sim",
            "instruction": "put the crimson cube on top of the navy cube",
        },
    ).json()
    refused = client.post(
        "/api/trials", json={"task": "stack_two", "planner": "rules", "instruction": "sing a song"}
    ).json()
    assert wait_done(client, ok["id"])["success"] is True
    bad = wait_done(client, refused["id"])
    assert bad["success"] is False and bad["failure"] == "planner" and "did not understand" in bad["reason"]


def test_breakpoint_step_resume_and_live_events(client):
    r = client.post(
        "/api/trials",
        json={"task": "stack_two", "segmenter": "privileged-keypoints", "breakpoints": ["tree.children[1]"]},
    ).json()
    trial_id = r["id"]
    with client.websocket_connect(f"/api/trials/{trial_id}/events") as ws:
        seen = []
        while True:
            ev = ws.receive_json()
            seen.append((ev.get("node_path"), ev["kind"]))
            if ev["kind"] == "paused" and ev["node_path"] == "tree.children[1]":
                assert client.get(f"/api/trials/{trial_id}").json()["control_state"] == "paused"
                state = client.post(f"/api/trials/{trial_id}/control", json={"action": "step"}).json()
                assert state["id"] == trial_id and state["breakpoints"] == ["tree.children[1]"]
            if ev["kind"] == "paused" and ev["node_path"] == "tree.children[2]":
                client.post(f"/api/trials/{trial_id}/control", json={"action": "resume"})
            if ev["kind"] == "closed":
                break
    assert ("tree.children[1]", "paused") in seen and ("tree.children[2]", "paused") in seen
    assert ("tree", "succeeded") in seen
    assert wait_done(client, trial_id)["success"] is True
    assert client.post(f"/api/trials/{trial_id}/control", json={"action": "pause"}).status_code == 409


def test_a_stream_opened_mid_trial_stamps_its_replayed_history_with_the_send_time(client):
    """A page that connects after the trial began gets the history first: each message says when the server sent it,
    since a replayed event's own wall_s is as old as the event (the page's live clock reads the server's time from
    it)."""
    r = client.post(
        "/api/trials",
        json={"task": "stack_two", "segmenter": "privileged-keypoints", "breakpoints": ["tree.children[1]"]},
    ).json()
    trial_id = r["id"]
    deadline = time.time() + 120
    while client.get(f"/api/trials/{trial_id}").json().get("control_state") != "paused":
        assert time.time() < deadline, "the trial never reached its breakpoint"
        time.sleep(0.05)
    time.sleep(0.3)  # the history is now at least this old
    with client.websocket_connect(f"/api/trials/{trial_id}/events") as ws:
        t_connect = time.time()
        first = ws.receive_json()
        assert first["kind"] == "started"
        assert first["wall_s"] < t_connect - 0.25 and t_connect - 0.05 <= first["sent_s"] <= time.time() + 0.05
        client.post(f"/api/trials/{trial_id}/control", json={"action": "abort"})
        while (ev := ws.receive_json())["kind"] != "closed":
            assert ev["sent_s"] >= ev.get("wall_s", 0.0)
    wait_done(client, trial_id)


def test_bad_requests_are_clear(client):
    r = client.post("/api/trials", json={"task": "juggle"})
    assert r.status_code == 422 and "unknown task 'juggle'" in r.json()["detail"]
    assert client.post("/api/trials", json={"task": "lift_block", "planner": "magic"}).status_code == 422
    assert client.get("/api/trials/nope").status_code == 404


def test_mutations_need_a_token_beyond_loopback(tmp_path):
    app = create_app(
        Settings(host="0.0.0.0", store_url=f"sqlite:///{tmp_path / 'x.db'}", workers=1, api_token="s3cret")
    )
    with TestClient(app) as c:
        assert c.post("/api/plans/validate", json={"text": "x"}).status_code == 401
        assert c.get("/api/health").status_code == 200
        ok = c.post(
            "/api/plans/validate",
            json={"text": "task: t\ntree: {primitive: wait}"},
            headers={"Authorization": "Bearer s3cret"},
        )
        assert ok.status_code == 200 and ok.json()["ok"]


def test_restart_interrupts_unfinished_trials(tmp_path):
    from spark_core.trace import TraceStore

    url = f"sqlite:///{tmp_path / 'r.db'}"
    TraceStore(url).create_trial("stuck-1", status="running", task="lift_block")
    with TestClient(create_app(Settings(store_url=url, workers=1))) as c:
        t = c.get("/api/trials/stuck-1").json()
        assert t["status"] == "interrupted" and "server stopped" in t["reason"]


def test_api_benchmark_runs_over_real_http_on_a_bulk_store():
    from spark_cli.console_bench.api import run, section

    r = run(n_trials=300, n_requests=5, n_concurrent=10, trajectory_rows=50)
    assert r["trials"] == 300 and r["within_1s"] <= 10
    assert all(0 < p50 <= p99 <= mx for p50, p99, mx in r["ms"].values())
    assert "| get one trial with its events |" in section(r, "spark bench api")


def test_twenty_submissions_with_two_workers_all_complete(client):
    ids = [
        client.post("/api/trials", json={"task": "lift_block", "segmenter": "privileged-keypoints", "seed": i}).json()[
            "id"
        ]
        for i in range(20)
    ]
    queued = client.get("/api/trials", params={"limit": 500}).json()
    assert queued["total"] == 20  # every submission is recorded at once, before any runs
    done = [wait_done(client, i, timeout=300) for i in ids]
    assert all(t["status"] == "done" and t["success"] for t in done)
    assert client.get("/api/trials", params={"status": "done", "limit": 500}).json()["total"] == 20


def test_mutating_calls_are_rate_limited(tmp_path):
    app = create_app(Settings(store_url=f"sqlite:///{tmp_path / 'rl.db'}", workers=1, rate_per_s=0.5, rate_burst=3))
    with TestClient(app) as c:
        codes = [
            c.post("/api/plans/validate", json={"text": "task: t\ntree: {primitive: wait}"}).status_code
            for _ in range(5)
        ]
        assert codes[:3] == [200, 200, 200] and codes[3:] == [429, 429]
        assert c.get("/api/health").status_code == 200  # reads are not limited
        r = c.post("/api/plans/validate", json={"text": "x"})
        assert r.status_code == 429 and "too many requests" in r.json()["detail"]


def test_detection_images_are_stored_with_their_hash(client):
    import hashlib

    tid = client.post("/api/trials", json={"task": "stack_two", "segmenter": "sim"}).json()["id"]
    trial = wait_done(client, tid)
    arts = {a["camera"]: a for a in trial["artifacts"] if a["kind"] == "detections"}
    assert set(arts) == {"agentview", "side"}
    r = client.get(f"/api/trials/{tid}/artifacts/{arts['agentview']['name']}")
    assert r.status_code == 200 and r.content[:4] == b"\x89PNG"
    assert hashlib.sha256(r.content).hexdigest() == arts["agentview"]["sha256"]
    # and one small JPEG per grounding and camera, at that grounding's simulated time
    per = [a for a in trial["artifacts"] if a["kind"] == "grounding"]
    groundings = trial["groundings"]
    assert {(a["grounding"], a["camera"]) for a in per} == {
        (i, cam) for i, g in enumerate(groundings) for cam in g["cameras"]
    }
    assert all(a["t_sim_s"] == groundings[a["grounding"]]["t_sim_s"] for a in per)
    assert len({a["sha256"] for a in per}) == len(per)  # different frames or masks: no two images alike
    r = client.get(f"/api/trials/{tid}/artifacts/{per[-1]['name']}")
    assert r.status_code == 200 and r.headers["content-type"] == "image/jpeg" and len(r.content) < 40_000
    assert hashlib.sha256(r.content).hexdigest() == per[-1]["sha256"]
    assert client.get(f"/api/trials/{tid}/artifacts/..%2F..%2Fetc%2Fpasswd").status_code == 404


def test_batch_progress_results_and_cancel(client):
    r = client.post(
        "/api/batches", json={"tasks": ["lift_block", "push_to_zone"], "trials": 2, "segmenter": "privileged-keypoints"}
    )
    assert r.status_code == 202 and r.json()["trials"] == 4
    bid = r.json()["id"]
    b = wait_batch(client, bid, lambda b: b["status"] == "done")
    assert b["progress"] == {"done": 4, "total": 4, "deleted": 0, "purged": 0}
    assert {row["task"]: (row["successes"], row["total"]) for row in b["results"]} == {
        "lift_block": (2, 2),
        "push_to_zone": (2, 2),
    }
    assert client.get("/api/trials", params={"batch": bid}).json()["total"] == 4

    big = client.post(
        "/api/batches", json={"tasks": ["stack_three"], "trials": 8, "segmenter": "privileged-keypoints"}
    ).json()["id"]
    cancel = client.post(f"/api/batches/{big}/cancel").json()
    assert cancel["cancelled"] >= 6  # with 2 workers most of the 8 were still queued
    b = wait_batch(client, big, lambda b: b["progress"]["done"] == 8)
    assert b["status"] == "cancelled" and b["progress"]["done"] == 8  # every trial accounted for, none lost
    assert sum(t["outcome"] == "aborted" for t in b["trials"]) >= 6
    assert client.post("/api/batches", json={"tasks": ["juggle"]}).status_code == 422
    assert client.get("/api/batches/nope").status_code == 404


def test_dashboard_stream_announces_every_status_change(client):
    with client.websocket_connect("/api/events") as ws:
        tid = client.post("/api/trials", json={"task": "lift_block", "segmenter": "privileged-keypoints"}).json()["id"]
        seen = []
        while not seen or seen[-1][1] != "done":
            ev = ws.receive_json()
            if ev["id"] == tid:
                seen.append((ev["kind"], ev["status"]))
    assert seen == [("trial", "queued"), ("trial", "running"), ("trial", "done")]


def test_a_planner_that_cannot_run_fails_its_trial_with_the_reason_and_the_worker_lives_on(client, monkeypatch):
    no_model = client.post("/api/trials", json={"task": "lift_block", "planner": "openai"})
    assert no_model.status_code == 422 and "model: the openai planner needs a model name" in no_model.text
    monkeypatch.delenv("OPENAI_API_KEY", raising=False)  # before the first trial spawns a worker
    bad = client.post("/api/trials", json={"task": "lift_block", "planner": "openai", "model": "m"}).json()["id"]
    trial = wait_done(client, bad)
    assert trial["success"] is False and trial["verdict"] == "planner_error" and trial["failure"] == "planner"
    assert "planner 'openai' unavailable: the openai planner needs OPENAI_API_KEY" in trial["reason"]
    assert client.get("/api/health").json() == {"status": "ok"}
    again = client.post("/api/trials", json={"task": "lift_block", "segmenter": "privileged-keypoints"}).json()["id"]
    assert wait_done(client, again)["success"] is True  # the same worker processes keep serving


def test_batch_from_an_explicit_spec_list_exports_csv(client):
    specs = [
        {"task": "lift_block", "seed": 3, "segmenter": "privileged-keypoints"},
        # an instruction needs a planner that reads it (the reference planner refuses one)
        {"task": "lift_block", "seed": 4, "instruction": "lift the red block", "planner": "rules", "segmenter": "sim"},
        {"task": "push_to_zone", "seed": 1, "segmenter": "privileged-keypoints"},
    ]
    bid = client.post("/api/batches", json={"specs": specs}).json()["id"]
    for _ in range(1200):
        b = client.get(f"/api/batches/{bid}").json()
        if b["status"] == "done":
            break
        time.sleep(0.1)
    assert b["progress"] == {"done": 3, "total": 3, "deleted": 0, "purged": 0}
    assert sorted((t["task"], t["seed"]) for t in b["trials"]) == [
        ("lift_block", 3),
        ("lift_block", 4),
        ("push_to_zone", 1),
    ]
    assert "lift the red block" in [t["instruction"] for t in b["trials"]]
    results = client.get(f"/api/batches/{bid}/results.csv")
    assert results.headers["content-type"].startswith("text/csv")
    lines = results.text.strip().splitlines()
    assert lines[0] == "task,done,total,successes,success_rate,ci95_low,ci95_high,judged,not_judged,deleted"
    by_task = {ln.split(",")[0]: ln.split(",") for ln in lines[1:]}
    table = {r["task"]: r for r in b["results"]}
    assert by_task["lift_block"][1:4] == ["2", "2", str(table["lift_block"]["successes"])]
    trials = client.get(f"/api/batches/{bid}/trials.csv").text.strip().splitlines()
    assert trials[0].startswith("id,task,seed,") and len(trials) == 4
    assert client.post("/api/batches", json={"specs": []}).status_code == 422
    bad = client.post("/api/batches", json={"specs": [{"task": "juggle"}]})
    assert bad.status_code == 422 and "juggle" in bad.json()["detail"]
    assert client.get("/api/batches/nope/results.csv").status_code == 404


def test_trials_on_other_embodiments(client):
    ur = client.post(
        "/api/trials", json={"task": "stack_two", "segmenter": "privileged-keypoints", "embodiment": "ur10"}
    ).json()["id"]
    two = client.post("/api/trials", json={"task": "handover_bar", "segmenter": "privileged-keypoints"}).json()["id"]
    bad = client.post("/api/trials", json={"task": "lift_tray", "embodiment": "ur10"})
    assert bad.status_code == 422 and "runs on bimanual" in bad.json()["detail"]
    done = wait_done(client, ur)
    assert done["success"] is True and done["protocol"]["embodiment"] == "ur10"
    assert wait_done(client, two)["success"] is True
    tasks = {t["name"]: t for t in client.get("/api/tasks").json()}
    assert tasks["lift_tray"]["suite"] == "bimanual" and tasks["lift_tray"]["embodiments"] == ["bimanual"]


def test_a_suite_without_reference_plans_needs_a_planner(client):
    r = client.post("/api/batches", json={"suite": "liberopro", "trials": 1, "planner": "reference"})
    assert r.status_code == 422 and "no reference plan" in r.json()["detail"]
    task = next(t for t in client.get("/api/tasks").json() if t["suite"] == "liberopro")["name"]
    r = client.post("/api/trials", json={"task": task, "planner": "reference"})
    assert r.status_code == 422 and "choose a planner" in r.json()["detail"]


def test_a_capbench_batch_runs_in_the_console(client):
    pytest.importorskip("robosuite", reason="benchmark extras: make bench-deps")
    r = client.post(
        "/api/batches", json={"suite": "capbench", "tasks": ["Lift"], "trials": 2, "segmenter": "privileged-keypoints"}
    )
    assert r.status_code == 202
    b = wait_batch(client, r.json()["id"], lambda b: b["status"] == "done")
    assert b["progress"] == {"done": 2, "total": 2, "deleted": 0, "purged": 0}
    assert all(t["outcome"] in ("success", "failure") for t in b["trials"])
