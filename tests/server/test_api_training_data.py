"""History says which trials have training data (a capture: what a LeRobot export takes): each summary has its
frame count (None without one), and the list filters on it."""

from __future__ import annotations

import time

from fastapi.testclient import TestClient

from server.app import create_app

from .isolated_settings import isolated_settings


def _done(c: TestClient, tid: str) -> dict:
    t0 = time.monotonic()
    while (trial := c.get(f"/api/trials/{tid}").json())["status"] != "done":
        assert time.monotonic() - t0 < 180, f"{tid} did not finish"
        time.sleep(0.1)
    return trial


def test_trial_summaries_say_which_trials_have_training_data_and_filter_on_it(tmp_path):
    body = {"task": "lift_block", "segmenter": "privileged-keypoints"}
    with TestClient(create_app(isolated_settings(tmp_path))) as c:
        with_data = c.post("/api/trials", json={**body, "capture": True}).json()["id"]
        without = c.post("/api/trials", json=body).json()["id"]
        trial = _done(c, with_data)
        _done(c, without)
        episode = next(a for a in trial["artifacts"] if a["name"] == "episode.npz")
        items = {t["id"]: t for t in c.get("/api/trials").json()["items"]}
        assert items[with_data]["training_frames"] == episode["frames"] > 0
        assert items[without]["training_frames"] is None
        page = c.get("/api/trials", params={"training": "true"}).json()
        assert page["total"] == 1 and [t["id"] for t in page["items"]] == [with_data]
        page = c.get("/api/trials", params={"training": "false"}).json()
        assert page["total"] == 1 and [t["id"] for t in page["items"]] == [without]
        r = c.get("/api/trials", params={"training": "maybe"})
        assert r.status_code == 422 and "training" in r.text
