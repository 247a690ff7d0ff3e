"""A running trial's groundings and their annotated images are in its record as each grounding is made (the
camera panel of a live trial shows them), and the end of the trial neither loses nor repeats any of them."""

from __future__ import annotations

import hashlib
import time

from fastapi.testclient import TestClient

from server.app import create_app

from .isolated_settings import isolated_settings
from .paused import paused_at


def _pairs(trial: dict) -> list[tuple[int, str]]:
    return [(a["grounding"], a["camera"]) for a in trial["artifacts"] if a["kind"] == "grounding"]


def test_groundings_and_their_images_are_stored_while_the_trial_runs(tmp_path):
    body = {"task": "stack_two", "segmenter": "sim", "start_paused": True}
    with TestClient(create_app(isolated_settings(tmp_path))) as c:
        tid = c.post("/api/trials", json=body).json()["id"]
        paused_at(c, tid, "tree.children[0]")
        assert c.post(f"/api/trials/{tid}/control", json={"action": "step"}).status_code == 200
        live = paused_at(c, tid, "tree.children[1]")  # the first node ran (and grounded its label): paused
        assert live["status"] == "running"
        assert live["groundings"], "a running trial's groundings are in its record"
        pairs = _pairs(live)
        assert set(pairs) == {(i, cam) for i, g in enumerate(live["groundings"]) for cam in g["cameras"]}
        for a in (a for a in live["artifacts"] if a["kind"] == "grounding"):
            r = c.get(f"/api/trials/{tid}/artifacts/{a['name']}")
            assert r.status_code == 200 and r.headers["content-type"] == "image/jpeg"
            assert hashlib.sha256(r.content).hexdigest() == a["sha256"]

        assert c.post(f"/api/trials/{tid}/control", json={"action": "resume"}).status_code == 200
        t0 = time.monotonic()
        while (done := c.get(f"/api/trials/{tid}").json())["status"] != "done":
            assert time.monotonic() - t0 < 120
            time.sleep(0.1)
    assert done["success"]
    # at the end: what was stored live is still there, once, followed by the later groundings
    assert done["groundings"][: len(live["groundings"])] == live["groundings"]
    assert len(done["groundings"]) > len(live["groundings"])
    end_pairs = _pairs(done)
    assert len(end_pairs) == len(set(end_pairs))  # no image twice
    assert set(end_pairs) == {(i, cam) for i, g in enumerate(done["groundings"]) for cam in g["cameras"]}
    assert set(pairs) <= set(end_pairs)
    names = [a["name"] for a in done["artifacts"]]
    assert len(names) == len(set(names))
    assert {a["kind"] for a in done["artifacts"]} >= {"grounding", "detections"}
