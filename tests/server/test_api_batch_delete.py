"""DELETE /api/batches/{id}: a finished or cancelled batch's record goes, its trials stay in the history naming
it (and saying it was deleted); a batch with trials still queued or running is refused with 409 saying why
(adversarial review L8)."""

from __future__ import annotations

import pytest
from fastapi.testclient import TestClient

from server.app import create_app

from .isolated_settings import isolated_settings


@pytest.fixture
def client(tmp_path):
    with TestClient(create_app(isolated_settings(tmp_path))) as c:
        yield c


def _batch(c: TestClient, batch_id: str, statuses: list[str], status: str = "running") -> None:
    """A batch as the console records one, with a trial per status (none of them live in this console)."""
    store = c.app.state.store
    store.create_batch(batch_id, {"suite": "builtin", "trial_count": len(statuses)})
    if status != "running":
        store.set_batch_status(batch_id, status)
    for n, st in enumerate(statuses):
        done = st == "done"
        store.create_trial(
            f"{batch_id}-{n:04d}-lift_block-{n}",
            task="lift_block",
            seed=n,
            batch_id=batch_id,
            status=st,
            success=done if done else None,
            verdict="success" if done else None,
        )


def test_a_finished_batch_is_deleted_and_its_trials_are_kept(client):
    c = client
    _batch(c, "batch-done", ["done", "done", "done"])
    _batch(c, "batch-other", ["done"])
    assert c.delete("/api/trials/batch-done-0002-lift_block-2").status_code == 200  # a deleted member is kept too
    r = c.delete("/api/batches/batch-done")
    assert r.status_code == 200 and r.json() == {"id": "batch-done", "trials_kept": 3}
    gone = c.get("/api/batches/batch-done")
    assert gone.status_code == 404 and "was deleted; its 2 trials are kept" in gone.json()["detail"]
    assert [b["id"] for b in c.get("/api/batches").json()["items"]] == ["batch-other"]
    listed = c.get("/api/trials", params={"batch": "batch-done"}).json()
    assert listed["total"] == 2 and all(t["success"] for t in listed["items"])
    trial = c.get("/api/trials/batch-done-0000-lift_block-0").json()
    assert trial["batch_id"] == "batch-done" and trial["batch_deleted"] is True and trial["verdict"] == "success"
    assert c.get("/api/trials/batch-other-0000-lift_block-0").json()["batch_deleted"] is False
    assert c.post("/api/trials/batch-done-0002-lift_block-2/restore").status_code == 200  # still restorable
    # its trials can still be exported by the batch's id (these were not captured: 422 saying so, not 404)
    r = c.post("/api/exports", json={"batch": "batch-done", "success_only": False})
    assert r.status_code == 422 and "without capture" in r.json()["detail"]
    assert c.delete("/api/batches/batch-done").status_code == 404


def test_a_cancelled_batch_is_deleted_once_its_trials_have_stopped(client):
    c = client
    _batch(c, "batch-stopping", ["done", "running"], status="cancelled")
    r = c.delete("/api/batches/batch-stopping")
    assert r.status_code == 409 and "cancelled but 1 of its trials are still stopping" in r.json()["detail"]
    c.app.state.store.update_trial("batch-stopping-0001-lift_block-1", status="done", verdict="aborted")
    assert c.delete("/api/batches/batch-stopping").json() == {"id": "batch-stopping", "trials_kept": 2}


def test_a_running_batch_is_not_deleted(client):
    c = client
    _batch(c, "batch-live", ["done", "running", "queued"])
    r = c.delete("/api/batches/batch-live")
    assert r.status_code == 409
    assert r.json()["detail"] == (
        "batch 'batch-live' is still running (2 of its 3 trials queued or running): "
        "cancel it first (POST /api/batches/batch-live/cancel), then delete it"
    )
    assert c.get("/api/batches/batch-live").status_code == 200
    assert c.delete("/api/batches/batch-nope").status_code == 404
