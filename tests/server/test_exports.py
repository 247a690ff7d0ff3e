"""Export from the console: a batch recorded with capture, or a selection of trials, becomes a LeRobot
dataset zip; bad requests say what was wrong."""

import io
import json
import time
import zipfile

from fastapi.testclient import TestClient

from server.app import create_app
from server.settings import Settings

from .test_api import wait_done


def test_batch_and_selection_export_as_lerobot_zip(tmp_path):
    settings = Settings(
        store_url=f"sqlite:///{tmp_path / 'e.db'}",
        workers=2,
        viser=False,
        artifacts_dir=str(tmp_path / "art"),
        exports_dir=str(tmp_path / "exports"),
    )
    with TestClient(create_app(settings)) as c:
        bid = c.post(
            "/api/batches",
            json={"tasks": ["lift_block"], "trials": 2, "segmenter": "privileged-keypoints", "capture": True},
        ).json()["id"]
        plain = c.post("/api/trials", json={"task": "lift_block", "segmenter": "privileged-keypoints"}).json()["id"]
        for _ in range(1200):
            if c.get(f"/api/batches/{bid}").json()["status"] == "done":
                break
            time.sleep(0.1)
        wait_done(c, plain)
        r = c.post("/api/exports", json={"batch": bid})
        assert r.status_code == 201, r.text
        body = r.json()
        assert body["episodes"] == 2 and body["frames"] > 20 and body["skipped"] == []
        z = zipfile.ZipFile(io.BytesIO(c.get(body["download"]).content))
        info = json.loads(z.read("meta/info.json"))
        assert info["codebase_version"] == "v3.0" and info["total_episodes"] == 2
        assert "videos/observation.images.agentview/chunk-000/file-000.mp4" in z.namelist()
        trials = [t["id"] for t in c.get(f"/api/batches/{bid}").json()["trials"]]
        sel = c.post("/api/exports", json={"trial_ids": [trials[0], plain]}).json()
        assert (
            sel["episodes"] == 1
            and sel["skipped"][0]["id"] == plain
            and "without capture" in sel["skipped"][0]["reason"]
        )
        nothing = c.post("/api/exports", json={"trial_ids": [plain]})
        assert nothing.status_code == 422 and "without capture" in nothing.json()["detail"]
        assert c.post("/api/exports", json={}).status_code == 422
        assert c.get("/api/exports/export-nope.zip").status_code == 404
