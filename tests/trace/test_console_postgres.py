"""The console on a PostgreSQL trace store (SPARK_STORE_URL=postgresql+psycopg://...): a batch of real trials
runs in the server's worker processes, is recorded with its events and manifest, and reads back through the API."""

import time

from fastapi.testclient import TestClient

from server.app import create_app
from server.settings import Settings


def test_a_console_batch_on_postgresql(postgres_server, tmp_path):
    url = postgres_server.new_database()
    app = create_app(Settings(store_url=url, workers=1, viser=False, artifacts_dir=str(tmp_path / "art")))
    with TestClient(app) as client:
        created = client.post(
            "/api/batches", json={"tasks": ["lift_block"], "trials": 1, "segmenter": "privileged-keypoints"}
        ).json()
        t0 = time.monotonic()
        while time.monotonic() - t0 < 120:
            batch = client.get(f"/api/batches/{created['id']}").json()
            if batch["progress"]["done"] == 1:
                break
            time.sleep(0.2)
        assert batch["progress"] == {"done": 1, "total": 1, "deleted": 0, "purged": 0} and [
            r["successes"] for r in batch["results"]
        ] == [1]
        assert batch["spec"]["manifest"]["id"] == created["manifest_id"]
        listed = client.get("/api/trials", params={"task": "lift_block", "success": True}).json()
        assert listed["total"] == 1
        trial = client.get(f"/api/trials/{batch['trials'][0]['id']}").json()
        assert trial["verdict"] == "success" and trial["events"] and trial["trajectory"]
