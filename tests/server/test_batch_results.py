"""Batch input and results that hold up (adversarial review M2, M3, M4, L9): an empty or repeated task list is
refused, specs stay in their suite, trials that never got a fair attempt are reported apart from the success
rate, deleting a member does not rewrite the result, and a finished batch cannot be cancelled."""

from __future__ import annotations

import pytest
from fastapi.testclient import TestClient

from server.app import create_app
from server.settings import Settings


@pytest.fixture()
def client(tmp_path):
    settings = Settings(
        store_url=f"sqlite:///{tmp_path / 'b.db'}", workers=1, viser=False, artifacts_dir=str(tmp_path / "art")
    )
    with TestClient(create_app(settings)) as c:
        yield c


def _batch(c: TestClient, batch_id: str, trials: list[tuple[str, int, str, str]]) -> None:
    """A recorded batch: (task, seed, status, verdict) per trial, as the workers would have left it."""
    store = c.app.state.store  # type: ignore[attr-defined]
    store.create_batch(batch_id, {"suite": "builtin", "trial_count": len(trials)})
    for n, (task, seed, status, verdict) in enumerate(trials):
        store.create_trial(
            f"{batch_id}-{n:04d}-{task}-{seed}",
            status=status,
            task=task,
            seed=seed,
            verdict=verdict,
            success=verdict == "success",
            batch_id=batch_id,
        )


@pytest.mark.parametrize(
    "body,message",
    [
        ({"tasks": []}, "omit `tasks` to run the whole builtin suite"),
        ({"tasks": ["lift_block", "lift_block", "block_on_plate"]}, "tasks: lift_block listed more than once"),
        ({"suite": "builtin", "specs": [{"task": "lift_block"}, {"task": "Lift"}]}, "specs[1]: 'Lift' not in suite"),
    ],
)
def test_unsafe_batch_input_is_refused_and_nothing_is_queued(client, body, message):
    r = client.post("/api/batches", json=body)
    assert r.status_code == 422 and message in r.json()["detail"], r.text
    assert client.get("/api/batches").json()["total"] == 0


def test_cancelled_and_interrupted_trials_are_not_failures(client):
    _batch(
        client,
        "batch-m2",
        [
            ("lift_block", 0, "done", "success"),
            ("lift_block", 1, "done", "tree_failed"),
            ("lift_block", 2, "done", "aborted"),
            ("lift_block", 3, "interrupted", "interrupted"),
            ("block_on_plate", 0, "done", "aborted"),
        ],
    )
    rows = {r["task"]: r for r in client.get("/api/batches/batch-m2").json()["results"]}
    lift, plate = rows["lift_block"], rows["block_on_plate"]
    assert (lift["judged"], lift["not_judged"], lift["successes"], lift["success_rate"]) == (2, 2, 1, 0.5)
    # no judged trial: no rate and no interval (it said ci95 [0, 0] beside success_rate null)
    assert (plate["judged"], plate["not_judged"], plate["success_rate"], plate["ci95"]) == (0, 1, None, None)
    assert lift["ci95"] is not None and lift["ci95"][0] < 0.5 < lift["ci95"][1]
    csv = client.get("/api/batches/batch-m2/results.csv").text.splitlines()
    assert csv[1] == "block_on_plate,1,1,0,,,,0,1,0"  # success_rate, ci95_low, ci95_high all empty
    assert csv[2].startswith("lift_block,4,4,1,0.5,") and csv[2].endswith(",2,2,0")


def test_deleting_a_member_does_not_rewrite_the_batch_result(client):
    _batch(client, "batch-del", [("lift_block", 0, "done", "success"), ("lift_block", 1, "done", "tree_failed")])
    before = client.get("/api/batches/batch-del").json()
    assert client.delete("/api/trials/batch-del-0001-lift_block-1").status_code == 200
    after = client.get("/api/batches/batch-del").json()
    assert after["results"][0]["success_rate"] == before["results"][0]["success_rate"] == 0.5
    assert after["results"][0]["deleted"] == 1 and after["progress"] == {
        "done": 2,
        "total": 2,
        "deleted": 1,
        "purged": 0,
    }
    listed = client.get("/api/batches").json()["items"][0]
    assert listed["progress"] == {"done": 2, "total": 2, "successes": 1}  # the batch list agrees
    assert client.delete("/api/trials/batch-del-0000-lift_block-0?purge=true").status_code == 200
    assert client.get("/api/batches/batch-del").json()["progress"]["purged"] == 1  # gone for good, and said so


def test_a_finished_or_cancelled_batch_cannot_be_cancelled(client):
    _batch(client, "batch-fin", [("lift_block", 0, "done", "success")])
    r = client.post("/api/batches/batch-fin/cancel")
    assert r.status_code == 409 and "already finished" in r.json()["detail"]
    assert client.get("/api/batches/batch-fin").json()["status"] == "done"
    store = client.app.state.store  # type: ignore[attr-defined]
    store.set_batch_status("batch-fin", "cancelled")
    r = client.post("/api/batches/batch-fin/cancel")
    assert r.status_code == 409 and "already cancelled" in r.json()["detail"]
