"""Waiting, in API tests, for a trial under step control to pause before a given node."""

from __future__ import annotations

import time

from fastapi.testclient import TestClient


def paused_at(c: TestClient, trial_id: str, node: str, timeout_s: float = 120.0) -> dict:
    """The trial record once the trial is paused before `node` (polls every 50 ms); fails if the trial ends first
    or does not pause there within `timeout_s` wall seconds."""
    t0 = time.monotonic()
    while True:
        trial = c.get(f"/api/trials/{trial_id}").json()
        paused = [e["node_path"] for e in trial.get("events", []) if e["kind"] == "paused"]
        if trial.get("control_state") == "paused" and paused and paused[-1] == node:
            return trial
        assert trial["status"] in ("queued", "running"), f"{trial_id} ended without pausing at {node}: {paused}"
        assert time.monotonic() - t0 < timeout_s, f"{trial_id} never paused at {node} (pauses so far: {paused})"
        time.sleep(0.05)
