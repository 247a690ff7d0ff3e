"""A given plan with an LLM planner and no model: a 422 naming the `model` field and why it is asked for although
the planner will not be called, never a 500, and nothing queued (adversarial review L4)."""

from __future__ import annotations

from fastapi.testclient import TestClient

from server.app import create_app

from .isolated_settings import isolated_settings

PLAN = "task: lift\ntree:\n  type: pick\n  params: {keypoint_label: red block}\n"


def test_a_plan_with_an_llm_planner_and_no_model_names_the_model_field(tmp_path):
    with TestClient(create_app(isolated_settings(tmp_path))) as c:
        # openai has no default model (gemini has one: it needs none)
        r = c.post("/api/trials", json={"task": "lift_block", "plan": PLAN, "planner": "openai"})
        assert r.status_code == 422
        assert r.json()["detail"] == (
            "model: the openai planner needs a model name "
            "(a given plan runs without calling it: name a model, or leave the planner out)"
        )
        r = c.post("/api/trials", json={"task": "lift_block", "planner": "openai"})  # no plan: no hint about one
        assert r.status_code == 422 and r.json()["detail"] == "model: the openai planner needs a model name"
        r = c.post("/api/trials", json={"task": "lift_block", "plan": PLAN + "  bogus: 1\n", "planner": "openai"})
        assert r.status_code == 422 and r.json()["detail"].startswith("plan: ")  # the plan is checked first
        assert c.get("/api/trials").json()["total"] == 0
