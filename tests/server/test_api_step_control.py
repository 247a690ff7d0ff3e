"""`step` answers the state it leads to: "pausing" (one more node runs, then the trial pauses), however many
steps are already under way, and each step lets exactly one more node run; a step asked for while the trial is
still queued is kept for when it starts (adversarial review L5)."""

from __future__ import annotations

from fastapi.testclient import TestClient

from server.app import create_app

from .isolated_settings import isolated_settings
from .paused import paused_at

# five quick nodes: where the trial pauses says how many nodes the steps let run
PLAN = "task: wait\ntree:\n  type: sequence\n  children:\n" + "    - type: wait\n      params: {duration: 0.2}\n" * 5


def _control(c: TestClient, trial_id: str, action: str) -> str:
    r = c.post(f"/api/trials/{trial_id}/control", json={"action": action})
    assert r.status_code == 200, r.text
    return r.json()["state"]


def test_each_step_runs_one_node_and_answers_pausing(tmp_path):
    body = {"task": "lift_block", "segmenter": "privileged-keypoints", "plan": PLAN, "start_paused": True}
    with TestClient(create_app(isolated_settings(tmp_path))) as c:
        first = c.post("/api/trials", json=body).json()["id"]
        queued = c.post("/api/trials", json=body).json()["id"]  # one worker: waits for the first
        paused_at(c, first, "tree.children[0]")
        assert _control(c, first, "step") == "pausing"  # not "paused": the worker is leaving that pause
        assert _control(c, first, "step") == "pausing"  # a second step while pausing: still on its way to a pause
        paused = paused_at(c, first, "tree.children[2]")  # two steps, two nodes
        assert [e["node_path"] for e in paused["events"] if e["kind"] == "paused"][0] == "tree.children[0]"
        assert _control(c, first, "step") == "pausing"
        paused_at(c, first, "tree.children[3]")

        assert _control(c, queued, "step") == "pausing"  # kept until the trial starts
        assert _control(c, first, "abort") == "aborted"
        trial = paused_at(c, queued, "tree.children[1]")  # the first node ran, as the step asked
        assert [e["node_path"] for e in trial["events"] if e["kind"] == "paused"] == ["tree.children[1]"]
        assert _control(c, queued, "resume") == "running"
