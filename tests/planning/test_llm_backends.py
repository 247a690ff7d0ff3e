"""gemini and openai planners through their real SDKs over real HTTP against fake servers on 127.0.0.1."""

import base64
import json

import numpy as np
import pytest

from spark_core.perception import Keypoint
from spark_core.planning import PlanRequest, SceneView
from spark_core.planning.llm import LLMSettings, PlannerUnavailable
from tests.doubles.fake_gemini import FakeGemini
from tests.doubles.fake_openai import FakeOpenAI

GOOD = json.dumps(
    {
        "task": "put the red block on the plate",
        "tree": {
            "type": "sequence",
            "children": [
                {"primitive": "pick", "params": {"keypoint_label": "red block"}},
                {"primitive": "place", "params": {"target_label": "plate"}},
            ],
        },
    }
)
BAD = json.dumps(
    {
        "task": "t",
        "tree": {
            "type": "sequence",
            "children": [
                {"primitive": "pick_up", "params": {"keypoint_label": "red block"}},
                {"primitive": "grasp", "params": {"force": "high"}},
            ],
        },
    }
)


def request(with_image=True):
    kps = {
        "red block": Keypoint("red block", np.array([0.5, 0.0, 0.02]), np.full(3, 0.04)),
        "plate": Keypoint("plate", np.array([0.5, 0.2, 0.008]), np.array([0.18, 0.18, 0.016])),
    }
    image = np.zeros((48, 64, 3), np.uint8) if with_image else None
    return PlanRequest("put the red block on the plate", SceneView(kps, "- red block: (0.500, 0.000, 0.020)", image))


def gemini(fake, **kw):
    from spark_core.planning.gemini import GeminiPlanner

    settings = LLMSettings("gemini-3.1-pro-preview", backoff_s=0.01, **kw)
    return GeminiPlanner(api_key="test-key", base_url=fake.url, settings=settings)


def openai_planner(fake, **kw):
    from spark_core.planning.openai_compat import OpenAIPlanner

    return OpenAIPlanner(
        "local-model",
        base_url=fake.url + "/v1",
        api_key="test-key",
        settings=LLMSettings("local-model", backoff_s=0.01, **kw),
    )


# -- gemini ---------------------------------------------------------------------------------------------------
def test_gemini_request_carries_schema_temperature_and_image():
    with FakeGemini() as fake:
        fake.script = [("ok", GOOD, (1000, 200, 50))]
        res = gemini(fake).plan(request())
    assert res.ok and [p for _, p, _ in [(0, c.primitive, 0) for _, c, _ in res.plan.primitives()]] == ["pick", "place"]
    (req,) = fake.requests
    assert req["path"].endswith("/models/gemini-3.1-pro-preview:generateContent")
    assert req["headers"].get("x-goog-api-key") == "test-key"
    body = req["body"]
    cfg = body["generationConfig"]
    assert (
        cfg["temperature"] == 0.3 and cfg["maxOutputTokens"] == 2048 and cfg["responseMimeType"] == "application/json"
    )
    assert "primitive_move_to_keypoint" in cfg["responseJsonSchema"]["$defs"]
    parts = body["contents"][0]["parts"]
    assert "Task: put the red block on the plate" in parts[0]["text"] and "red block" in parts[0]["text"]
    inline = parts[1]["inlineData"]
    assert (
        inline.get("mimeType", inline.get("mime_type")) == "image/png"
        and base64.b64decode(inline["data"])[:4] == b"\x89PNG"
    )
    assert "move_to_keypoint{keypoint_label*" in body["systemInstruction"]["parts"][0]["text"]
    assert (res.usage.input_tokens, res.usage.output_tokens, res.usage.reasoning_tokens) == (1000, 200, 50)
    assert res.cost_usd == pytest.approx((1000 * 2.0 + 250 * 12.0) / 1e6)


def test_gemini_repair_round_trip():
    with FakeGemini() as fake:
        fake.script = [("ok", BAD), ("ok", GOOD)]
        res = gemini(fake).plan(request())
    assert res.ok and res.detail["rounds"] == 2 and len(fake.requests) == 2
    second = fake.requests[1]["body"]["contents"]
    assert [c["role"] for c in second] == ["user", "model", "user"]
    assert second[1]["parts"][0]["text"] == BAD
    repair = second[2]["parts"][0]["text"]
    assert "tree.children[0].primitive: unknown primitive 'pick_up'" in repair
    assert 'tree.children[1].params.force: expected number in [0, 140], got "high"' in repair
    assert res.usage.input_tokens == 240  # both rounds counted


def test_gemini_fails_cleanly_when_repair_does_not_help():
    with FakeGemini() as fake:
        fake.script = [("ok", BAD), ("ok", BAD)]
        res = gemini(fake).plan(request())
    assert not res.ok and res.text == BAD and "did not type-check after 1 repair round" in res.error
    assert any(i.path == "tree.children[0].primitive" for i in res.issues)


def test_gemini_retries_429_then_succeeds():
    with FakeGemini() as fake:
        fake.script = [("status", 429), ("ok", GOOD)]
        res = gemini(fake).plan(request())
    assert res.ok and len(fake.requests) == 2


def test_gemini_gives_up_on_repeated_500_with_a_clear_message():
    with FakeGemini() as fake:
        fake.script = [("status", 500)] * 3
        res = gemini(fake, max_retries=2).plan(request())
    assert not res.ok and len(fake.requests) == 3
    assert "HTTP 500 from Gemini" in res.error and "gave up after 3 attempts" in res.error


def test_gemini_permanent_error_is_not_retried():
    with FakeGemini() as fake:
        fake.script = [("status", 403)]
        res = gemini(fake).plan(request())
    assert not res.ok and len(fake.requests) == 1 and "HTTP 403" in res.error


def test_gemini_timeout():
    with FakeGemini() as fake:
        fake.script = [("sleep", 2.5, GOOD)]
        res = gemini(fake, timeout_s=1.0, max_retries=0).plan(request(with_image=False))
    assert not res.ok and "did not answer within 1 s" in res.error


def test_gemini_without_key_says_what_is_missing(monkeypatch):
    from spark_core.planning.gemini import GeminiPlanner

    monkeypatch.delenv("GEMINI_API_KEY", raising=False)
    monkeypatch.delenv("GOOGLE_API_KEY", raising=False)
    with pytest.raises(PlannerUnavailable, match="set GEMINI_API_KEY"):
        GeminiPlanner()


# -- openai-compatible ----------------------------------------------------------------------------------------
def test_openai_request_carries_schema_temperature_and_image():
    with FakeOpenAI() as fake:
        fake.script = [("ok", GOOD, (500, 100, 20))]
        res = openai_planner(fake).plan(request())
    assert res.ok
    (req,) = fake.requests
    assert req["path"] == "/v1/chat/completions"
    body = req["body"]
    assert body["model"] == "local-model" and body["temperature"] == 0.3 and body["max_tokens"] == 2048
    fmt = body["response_format"]
    assert fmt["type"] == "json_schema" and "primitive_pick" in fmt["json_schema"]["schema"]["$defs"]
    assert body["messages"][0]["role"] == "system" and "Slots marked * are required" in body["messages"][0]["content"]
    content = body["messages"][1]["content"]
    assert content[0]["type"] == "text" and content[1]["image_url"]["url"].startswith("data:image/png;base64,")
    assert (res.usage.input_tokens, res.usage.output_tokens, res.usage.reasoning_tokens) == (500, 100, 20)
    assert res.cost_usd == 0.0  # local model: no price in the table


def test_openai_repair_round_trip_and_retries():
    with FakeOpenAI() as fake:
        fake.script = [("status", 429), ("ok", BAD), ("status", 500), ("ok", GOOD)]
        res = openai_planner(fake).plan(request())
    assert res.ok and len(fake.requests) == 4
    msgs = fake.requests[-1]["body"]["messages"]
    assert [m["role"] for m in msgs] == ["system", "user", "assistant", "user"]
    assert "unknown primitive 'pick_up'" in msgs[3]["content"]


def test_openai_timeout_and_exhausted_retries():
    with FakeOpenAI() as fake:
        fake.script = [("sleep", 2.5, GOOD)]
        res = openai_planner(fake, timeout_s=1.0, max_retries=0).plan(request(with_image=False))
    assert not res.ok and "did not answer within 1 s" in res.error
    with FakeOpenAI() as fake:
        fake.script = [("status", 500)] * 2
        res = openai_planner(fake, max_retries=1).plan(request())
    assert not res.ok and "HTTP 500" in res.error and "gave up after 2 attempts" in res.error


def test_openai_needs_a_key_or_a_local_server(monkeypatch):
    from spark_core.planning.openai_compat import OpenAIPlanner

    monkeypatch.delenv("OPENAI_API_KEY", raising=False)
    with pytest.raises(PlannerUnavailable, match="OPENAI_API_KEY, or --base-url"):
        OpenAIPlanner("gpt-4.1")


def test_variant_call_over_the_wire():
    with FakeOpenAI() as fake:
        fake.script = [
            (
                "ok",
                json.dumps(
                    {
                        "red block": ["crimson cube", "red wooden block", "red block", "scarlet box"],
                        "plate": ["white dish"],
                    }
                ),
            )
        ]
        out = openai_planner(fake).prompt_variants(["red block", "plate", "mug"], k=3)
    assert out == {"red block": ["crimson cube", "red wooden block", "scarlet box"], "plate": ["white dish"], "mug": []}
    schema = fake.requests[0]["body"]["response_format"]["json_schema"]["schema"]
    assert schema["required"] == ["red block", "plate", "mug"]
    with FakeGemini() as fake:
        fake.script = [("ok", "not json")]
        assert gemini(fake).prompt_variants(["cup"]) == {"cup": []}


def test_rules_variants_are_deterministic():
    from spark_core.planning.rules import RulesPlanner

    assert RulesPlanner().prompt_variants(["red block"]) == {"red block": ["red cube", "red wooden block"]}


def test_cli_plans_through_an_openai_compatible_server(capsys):
    from spark_cli import main

    with FakeOpenAI() as fake:
        fake.script = [("ok", json.dumps([{"object": "red block"}, {"object": "plate"}])), ("ok", GOOD)]
        code = main(
            [
                "plan",
                "put the red block on the plate",
                "--task",
                "block_on_plate",
                "--planner",
                "openai",
                "--model",
                "local-model",
                "--base-url",
                fake.url + "/v1",
            ]
        )
    out = capsys.readouterr().out
    assert code == 0 and "type: place" in out and "usage: 120 in" in out
    content = fake.requests[1]["body"]["messages"][1]["content"]  # after the prompt-synthesis call
    assert "red block: (" in content[0]["text"]  # what perception saw, from the scene's cameras
    assert content[1]["image_url"]["url"].startswith("data:image/png;base64,")  # the annotated agentview image
