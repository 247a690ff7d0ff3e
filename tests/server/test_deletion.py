"""Issue 20, finding 7: a delete can be undone for a grace period and hides the trial everywhere meanwhile; a
purge (after the grace period, or asked for) removes the record and the trial's files on disk."""

import time

from fastapi.testclient import TestClient
from starlette.testclient import WebSocketDenialResponse

from server.app import create_app
from server.settings import Settings


def _client(tmp_path, **kw) -> TestClient:
    settings = Settings(
        store_url=f"sqlite:///{tmp_path / 'd.db'}",
        workers=1,
        viser=False,
        artifacts_dir=str(tmp_path / "art"),
        exports_dir=str(tmp_path / "exports"),
        **kw,
    )
    return TestClient(create_app(settings))


def _recorded(c: TestClient, tmp_path, trial_id: str, batch: str = "batch-d") -> None:
    """A finished trial of a batch, with an artifact file in its directory, as a worker would record it."""
    store = c.app.state.store  # type: ignore[attr-defined]
    if store.get_batch(batch) is None:
        store.create_batch(batch, {"suite": "builtin"})
    art = tmp_path / "art" / trial_id
    art.mkdir(parents=True)
    (art / "detection.png").write_bytes(b"png")
    store.create_trial(
        trial_id,
        status="done",
        task="lift_block",
        success=True,
        verdict="success",
        batch_id=batch,
        artifacts=[{"name": "detection.png", "path": str(art / "detection.png"), "sha256": "x"}],
    )


def _visible(c: TestClient, trial_id: str) -> dict[str, bool]:
    """Where the trial shows up: its page, the list, its batch's pages, an export selection, its event stream."""
    try:
        with c.websocket_connect(f"/api/trials/{trial_id}/events"):
            stream = True
    except WebSocketDenialResponse:
        stream = False
    export = c.post("/api/exports", json={"trial_ids": [trial_id], "success_only": False})
    return {
        "get": c.get(f"/api/trials/{trial_id}").status_code == 200,
        "list": trial_id in [t["id"] for t in c.get("/api/trials").json()["items"]],
        "batch": trial_id in [t["id"] for t in c.get("/api/batches/batch-d").json()["trials"]],
        "batch_csv": trial_id in c.get("/api/batches/batch-d/trials.csv").text,
        "artifact": c.get(f"/api/trials/{trial_id}/artifacts/detection.png").status_code == 200,
        "export": export.status_code != 404,
        "stream": stream,
    }


def test_a_deleted_trial_is_hidden_everywhere_and_can_be_restored(tmp_path):
    with _client(tmp_path) as c:
        _recorded(c, tmp_path, "t-keep")
        _recorded(c, tmp_path, "t-del")
        assert all(_visible(c, "t-del").values())
        r = c.delete("/api/trials/t-del")
        assert r.status_code == 200 and r.json()["purged"] is False and r.json()["restore_until"]
        assert not any(_visible(c, "t-del").values()), _visible(c, "t-del")
        assert all(_visible(c, "t-keep").values())
        assert c.delete("/api/trials/t-del").status_code == 404  # already deleted
        assert (tmp_path / "art" / "t-del" / "detection.png").exists()  # kept while it can be restored
        assert c.post("/api/trials/t-del/restore").json() == {"id": "t-del", "restored": True}
        assert all(_visible(c, "t-del").values())
        assert c.post("/api/trials/t-keep/restore").status_code == 404  # nothing to undo


def test_purge_removes_the_record_and_its_files_at_once_or_after_the_grace_period(tmp_path):
    with _client(tmp_path, delete_grace_s=1.0, purge_every_s=0.2) as c:
        _recorded(c, tmp_path, "t-now")
        _recorded(c, tmp_path, "t-later")
        r = c.delete("/api/trials/t-now", params={"purge": "true"})
        assert r.status_code == 200 and r.json() == {"id": "t-now", "purged": True, "restore_until": None}
        assert not (tmp_path / "art" / "t-now").exists()
        assert not c.app.state.store.has_trial("t-now")  # type: ignore[attr-defined]
        assert c.post("/api/trials/t-now/restore").status_code == 404
        assert c.delete("/api/trials/t-later").status_code == 200
        deadline = time.monotonic() + 10
        while (tmp_path / "art" / "t-later").exists() and time.monotonic() < deadline:
            time.sleep(0.1)
        assert not (tmp_path / "art" / "t-later").exists()  # the purge thread, once the grace period passed
        assert not c.app.state.store.has_trial("t-later")  # type: ignore[attr-defined]
        assert c.post("/api/trials/t-later/restore").status_code == 404
        assert (tmp_path / "art").is_dir()  # only the trials' own directories went


def test_a_purge_never_removes_files_outside_the_artifacts_directory(tmp_path):
    outside = tmp_path / "elsewhere.png"
    outside.write_bytes(b"keep me")
    with _client(tmp_path) as c:
        store = c.app.state.store  # type: ignore[attr-defined]
        store.create_trial("t-odd", status="done", artifacts=[{"name": "x.png", "path": str(outside)}])
        assert c.delete("/api/trials/t-odd?purge=true").status_code == 200
        assert outside.read_bytes() == b"keep me" and not store.has_trial("t-odd")
