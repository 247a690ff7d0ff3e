"""What a new user types as the instruction, through the real app: the reference planner runs the task's own
hand-written plan, so an instruction it would not read is refused (not recorded as what ran while the robot did
something else); a blank instruction is the task's own, not a planner's refusal of "   "."""

import pytest
from fastapi.testclient import TestClient

from server.app import create_app
from tests.server.isolated_settings import isolated_settings
from tests.server.test_api import wait_done


@pytest.fixture()
def client(tmp_path):
    with TestClient(create_app(isolated_settings(tmp_path))) as c:
        yield c


def test_reference_planner_refuses_an_instruction_it_would_ignore(client):
    r = client.post("/api/trials", json={"task": "lift_block", "instruction": "put the red block on the blue block"})
    assert r.status_code == 422
    detail = r.json()["detail"]
    assert detail.startswith("instruction: the reference planner runs 'lift_block'") and "rules planner" in detail
    assert client.get("/api/trials").json()["total"] == 0  # nothing queued
    # the same in a batch's spec (the batch's planner is the reference one by default), named by its spec
    b = client.post("/api/batches", json={"specs": [{"task": "lift_block", "instruction": "wave at the camera"}]})
    assert b.status_code == 422 and b.json()["detail"].startswith("specs[0]: instruction: the reference planner")
    # what still goes: the task's own words, an instruction for a planner that reads it, a plan of one's own
    own = client.post("/api/trials", json={"task": "lift_block", "instruction": " pick up the red block "})
    assert own.status_code == 202
    assert (
        client.post(
            "/api/trials", json={"task": "lift_block", "planner": "rules", "instruction": "lift the red block"}
        ).status_code
        == 202
    )
    plan = "task: nudge\ntree:\n  type: sequence\n  children:\n    - type: move_relative\n      params: {dz: 0.05}\n"
    assert (
        client.post(
            "/api/trials", json={"task": "lift_block", "plan": plan, "instruction": "nudge the hand up"}
        ).status_code
        == 202
    )
    assert wait_done(client, own.json()["id"])["instruction"] == "pick up the red block"


def test_a_blank_instruction_is_the_tasks_own(client):
    r = client.post(
        "/api/trials", json={"task": "lift_block", "instruction": "  \t ", "segmenter": "privileged-keypoints"}
    )
    assert r.status_code == 202
    trial = wait_done(client, r.json()["id"])
    assert trial["instruction"] == "pick up the red block"
    assert trial["verdict"] == "success"


def test_which_planners_read_an_instruction_is_the_catalogs_flag(client, monkeypatch):
    """The catalog says which planners read the instruction (`reads_instruction`); the API's refusal follows that
    flag, not a planner's name."""
    from dataclasses import replace

    from spark_core.catalog import PLANNERS

    flags = {p["name"]: p["reads_instruction"] for p in client.get("/api/catalog").json()["planners"]}
    assert flags == {name: name != "reference" for name in PLANNERS}
    monkeypatch.setitem(PLANNERS, "rules", replace(PLANNERS["rules"], reads_instruction=False))
    r = client.post("/api/trials", json={"task": "lift_block", "planner": "rules", "instruction": "wave"})
    assert r.status_code == 422
    detail = r.json()["detail"]
    assert (
        detail.startswith("instruction: the rules planner runs 'lift_block'")
        and "rules planner (offline)" not in detail
    )
    assert client.get("/api/trials").json()["total"] == 0
