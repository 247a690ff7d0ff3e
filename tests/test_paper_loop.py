"""The paper's perception loop for LLM planners, through the trial pipeline: a prompt-synthesis call first (three
alternative prompts per object), perception tries every prompt and keeps the single confident detection, then
the behavior-tree call; both calls are in the trace and the trial's cost counts both."""

from __future__ import annotations

import json

from spark_core.trial import TrialConfig, Verdict, run_trial
from tests.planning.fake_llm import FakeLLM

PLAN = {
    "task": "pick up the red block",
    "tree": {"type": "sequence", "children": [{"type": "pick", "params": {"keypoint_label": "red block"}}]},
}


def test_the_synthesis_call_comes_first_its_prompts_reach_perception_and_both_calls_are_costed():
    variants = {"red block": ["crimson cube", "red wooden cube", "scarlet block"]}
    with FakeLLM("openai") as fake:
        fake.script = [("ok", json.dumps(variants), (50, 20, 0)), ("ok", json.dumps(PLAN), (900, 60, 0))]
        out = run_trial(
            # a model with a price in the table: an OpenAI-compatible proxy serving Gemini
            TrialConfig(
                "lift_block", planner="openai", model="gemini-3.1-pro", base_url=fake.url + "/v1", segmenter="sim"
            )
        )
    assert out.verdict is Verdict.SUCCESS, out.reason
    first, second = (r["body"] for r in fake.requests)
    assert "alternative short text prompts" in first["messages"][0]["content"]  # the synthesis call, first
    assert "red block" in first["messages"][1]["content"]
    content = second["messages"][1]["content"]  # the BT call carries the annotated image
    assert isinstance(content, list) and any(part["type"] == "image_url" for part in content)
    calls = out.protocol["planning"]["calls"]
    assert [c["kind"] for c in calls] == ["prompt_synthesis", "behavior_tree"]
    assert calls[0]["response"] == json.dumps(variants) and calls[0]["usage"]["input_tokens"] == 50
    assert out.cost_usd == calls[0]["cost_usd"] + calls[1]["cost_usd"] > 0
    assert out.usage["input_tokens"] == 950 and out.usage["output_tokens"] == 80


def test_perception_tries_the_llms_prompts(tmp_path):
    from spark_core.trace import TraceStore
    from spark_core.trace.sink import StoreSink

    store = TraceStore(f"sqlite:///{tmp_path / 'p.db'}")
    variants = {"red block": ["crimson cube", "red wooden cube", "scarlet block"]}
    with FakeLLM("openai") as fake:
        fake.script = [("ok", json.dumps(variants)), ("ok", json.dumps(PLAN))]
        out = run_trial(
            TrialConfig("lift_block", planner="openai", model="m", base_url=fake.url + "/v1", segmenter="sim"),
            [StoreSink(store)],
        )
    grounding = store.get_trial(out.trial_id)["groundings"][0]
    prompts = {c["prompt"] for cam in grounding["cameras"].values() for c in cam["candidates"]}
    assert {"red block", "crimson cube", "red wooden cube", "scarlet block"} <= prompts


def test_a_failed_synthesis_call_is_recorded_and_perception_falls_back_to_its_table():
    with FakeLLM("openai") as fake:
        fake.script = [("status", 400), ("ok", json.dumps(PLAN))]
        out = run_trial(
            TrialConfig("lift_block", planner="openai", model="m", base_url=fake.url + "/v1", segmenter="sim")
        )
    calls = out.protocol["planning"]["calls"]
    assert calls[0]["kind"] == "prompt_synthesis" and "error" in calls[0]
    assert out.verdict is Verdict.SUCCESS, out.reason
