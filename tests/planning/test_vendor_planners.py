"""The gemini and openai planners through the real google-genai and openai SDKs over real HTTP, against loopback
servers that answer like the vendors (tests/doubles): a plan in the paper's format, malformed JSON, an unknown
primitive (one repair round), 429 and 5xx with bounded retries, a body that is not JSON, and the prompt-synthesis
call returning bad phrases."""

from __future__ import annotations

import base64
import json

import numpy as np
import pytest

from spark_core.perception import Keypoint
from spark_core.planning import PlanRequest, SceneView
from spark_core.planning.llm import SYNTHESIS_MAX_OUTPUT_TOKENS, LLMSettings, PlannerUnavailable, TransientError
from tests.doubles.fake_gemini import FakeGemini
from tests.doubles.fake_openai import FakeOpenAI

# The paper's leaf form: `type: <primitive>` with params, arm inside params.
PAPER_PLAN = json.dumps(
    {
        "task": "put the red block on the plate",
        "tree": {
            "type": "sequence",
            "children": [
                {"type": "pick", "params": {"keypoint_label": "red block", "arm": "right"}},
                {"type": "place", "params": {"target_label": "plate"}},
            ],
        },
    }
)
UNKNOWN_PRIMITIVE = json.dumps(
    {
        "task": "t",
        "tree": {"type": "sequence", "children": [{"type": "pick_up", "params": {"keypoint_label": "red block"}}]},
    }
)
MALFORMED = '{"task": "put the red block on the plate", "tree": {"type": "sequence", "children": [{"type": "pick"'


def request(with_image: bool = True) -> PlanRequest:
    kps = {
        "red block": Keypoint("red block", np.array([0.5, 0.0, 0.02]), np.full(3, 0.04)),
        "plate": Keypoint("plate", np.array([0.5, 0.2, 0.008]), np.array([0.18, 0.18, 0.016])),
    }
    image = np.zeros((48, 64, 3), np.uint8) if with_image else None
    return PlanRequest("put the red block on the plate", SceneView(kps, "- red block: (0.500, 0.000, 0.020)", image))


class Vendor:
    """One vendor: its fake server, its planner built on its SDK, and where its requests keep things."""

    def __init__(self, name: str):
        self.name = name

    def server(self):
        return FakeGemini() if self.name == "gemini" else FakeOpenAI()

    def planner(self, fake, model: str = "gemini-3.1-pro-preview", **kw):
        settings = LLMSettings(model, backoff_s=0.01, **kw)
        if self.name == "gemini":
            from spark_core.planning.gemini import GeminiPlanner

            return GeminiPlanner(model, api_key="test-key", base_url=fake.url, settings=settings)
        from spark_core.planning.openai_compat import OpenAIPlanner

        return OpenAIPlanner(model, base_url=fake.url + "/v1", api_key="test-key", settings=settings)

    def max_tokens(self, body: dict) -> int:
        return body["generationConfig"]["maxOutputTokens"] if self.name == "gemini" else body["max_tokens"]

    def schema(self, body: dict) -> dict:
        if self.name == "gemini":
            return body["generationConfig"]["responseJsonSchema"]
        return body["response_format"]["json_schema"]["schema"]

    def images(self, body: dict) -> list[bytes]:
        if self.name == "gemini":
            return [_b64(p["inlineData"]["data"]) for c in body["contents"] for p in c["parts"] if "inlineData" in p]
        out = []
        for m in body["messages"]:
            if isinstance(m["content"], list):
                for part in m["content"]:
                    if part["type"] == "image_url":
                        out.append(base64.b64decode(part["image_url"]["url"].split(",", 1)[1]))
        return out

    def turns(self, body: dict) -> list[tuple[str, str]]:
        """(role, text) of every turn after the system prompt."""
        if self.name == "gemini":
            return [(c["role"], c["parts"][0]["text"]) for c in body["contents"]]
        out = []
        for m in body["messages"][1:]:
            text = m["content"] if isinstance(m["content"], str) else m["content"][0]["text"]
            out.append(({"assistant": "model"}.get(m["role"], m["role"]), text))
        return out


def _b64(data: str) -> bytes:
    """google-genai sends URL-safe base64 (OpenAI's data URLs the standard alphabet)."""
    return base64.urlsafe_b64decode(data.replace("+", "-").replace("/", "_"))


VENDORS = [Vendor("gemini"), Vendor("openai")]


@pytest.fixture(params=VENDORS, ids=lambda v: v.name)
def vendor(request) -> Vendor:
    return request.param


def test_a_plan_in_the_papers_format(vendor):
    with vendor.server() as fake:
        fake.script = [("ok", PAPER_PLAN, (1000, 200, 50))]
        res = vendor.planner(fake).plan(request())
    assert res.ok, res.error
    assert [(n.primitive, n.arm) for _, n, _ in res.plan.primitives()] == [("pick", "right"), ("place", None)]
    (req,) = fake.requests
    body = req["body"]
    assert vendor.max_tokens(body) == 2048
    assert "primitive_pick" in vendor.schema(body)["$defs"]
    (png,) = vendor.images(body)
    assert png[:4] == b"\x89PNG"
    assert (res.usage.input_tokens, res.usage.output_tokens, res.usage.reasoning_tokens) == (1000, 200, 50)
    assert res.cost_usd == pytest.approx((1000 * 2.0 + 250 * 12.0) / 1e6)  # the paper's Gemini 3.1 Pro rates


def test_malformed_json_gets_one_repair_round(vendor):
    with vendor.server() as fake:
        fake.script = [("ok", MALFORMED), ("ok", PAPER_PLAN)]
        res = vendor.planner(fake).plan(request())
    assert res.ok and res.detail["rounds"] == 2 and len(fake.requests) == 2
    turns = vendor.turns(fake.requests[1]["body"])
    assert [r for r, _ in turns] == ["user", "model", "user"] and turns[1][1] == MALFORMED
    assert "does not type-check" in turns[2][1] and "JSON" in turns[2][1]


def test_an_unknown_primitive_gets_exactly_one_repair_round_then_a_clear_error(vendor):
    with vendor.server() as fake:
        fake.script = [("ok", UNKNOWN_PRIMITIVE), ("ok", PAPER_PLAN)]
        res = vendor.planner(fake).plan(request())
    assert res.ok and len(fake.requests) == 2
    assert "unknown primitive 'pick_up'" in vendor.turns(fake.requests[1]["body"])[2][1]
    assert res.usage.input_tokens == 240  # both rounds counted

    with vendor.server() as fake:
        fake.script = [("ok", UNKNOWN_PRIMITIVE)] * 3
        res = vendor.planner(fake).plan(request())
    assert not res.ok and len(fake.requests) == 2  # one repair round, not more
    assert res.error == f"the {vendor.name} plan did not type-check after 1 repair round(s)"
    assert res.text == UNKNOWN_PRIMITIVE and any("pick_up" in str(i) for i in res.issues)


@pytest.mark.parametrize("codes", [(429,), (503, 500)])
def test_429_and_5xx_are_retried(vendor, codes):
    with vendor.server() as fake:
        fake.script = [*(("status", c) for c in codes), ("ok", PAPER_PLAN)]
        res = vendor.planner(fake, max_retries=2).plan(request())
    assert res.ok and len(fake.requests) == len(codes) + 1


def test_retries_give_up_after_the_limit_with_the_vendors_message(vendor):
    with vendor.server() as fake:
        fake.script = [("status", 429)] * 5
        res = vendor.planner(fake, max_retries=2).plan(request())
    assert not res.ok and len(fake.requests) == 3
    assert "HTTP 429" in res.error and "gave up after 3 attempts" in res.error
    assert ("exceeded your current quota" if vendor.name == "gemini" else "Rate limit reached") in res.error


def test_the_vendors_retry_hint_is_honoured(vendor, monkeypatch):
    """429 with the vendor's hint (OpenAI's retry-after header, Gemini's RetryInfo): never retried sooner; a hint
    beyond MAX_RETRY_AFTER_S gives up at once, saying so."""
    import spark_core.planning.llm as llm

    slept: list[float] = []
    monkeypatch.setattr(llm.time, "sleep", slept.append)
    with vendor.server() as fake:
        fake.script = [("status", 429, 7), ("status", 503), ("ok", PAPER_PLAN)]
        res = vendor.planner(fake, max_retries=2).plan(request())
    assert res.ok and slept == [7.0, 0.02]  # the hint, then our own backoff (0.01 doubled)
    slept.clear()
    with vendor.server() as fake:
        fake.script = [("status", 429, 3600)]
        res = vendor.planner(fake, max_retries=2).plan(request())
    assert not res.ok and len(fake.requests) == 1 and slept == []
    assert "gave up after 1 attempts; the vendor asked to wait 3600 s" in res.error


def test_a_permanent_error_is_not_retried(vendor):
    with vendor.server() as fake:
        fake.script = [("status", 400)]
        res = vendor.planner(fake).plan(request())
    assert not res.ok and len(fake.requests) == 1 and "HTTP 400" in res.error


def test_a_body_that_is_not_json_is_a_clean_planner_error(vendor):
    """A proxy's HTML page with status 200: the SDK cannot decode it; the planner reports it, never raises."""
    with vendor.server() as fake:
        fake.script = [("raw", 200, b"<html><body>Bad gateway</body></html>")]
        res = vendor.planner(fake).plan(request())
    assert not res.ok and vendor.name in res.error and "not JSON" in res.error


# -- the prompt-synthesis call ----------------------------------------------------------------------------------
BAD_PHRASES = json.dumps(
    [
        {
            "object": "red block",
            "prompts": [
                "",
                "a small cube painted bright red sitting on the left side of the wooden table top",
                42,
                "crimson cube",
                "Crimson   cube",
                "red block",
                "scarlet wooden cube",
                "red box",
                "fourth prompt",
            ],
        },
        {"object": "   "},
        {"object": "plate", "prompts": "white dish"},
        {"object": "Plate", "prompts": ["round dish"]},
        "bowl",
    ]
)


def test_the_synthesis_call_sends_the_image_and_filters_bad_phrases(vendor):
    with vendor.server() as fake:
        fake.script = [("ok", BAD_PHRASES, (300, 90, 0))]
        planner = vendor.planner(fake)
        syn = planner.synthesise("put the red block on the plate", b"\x89PNG fake", 3)
    assert syn.objects == ("red block", "plate", "bowl")
    assert syn.variants == {"red block": ["crimson cube", "scarlet wooden cube", "red box"]}
    dropped = "\n".join(syn.dropped)
    for why in ("[0].prompts[0]: empty", "[0].prompts[1]: too long", "[0].prompts[2]: not a string (int)"):
        assert why in dropped
    assert "[0].prompts[4]: duplicate" in dropped and "[0].prompts[5]: duplicate" in dropped  # case, the object
    assert "[1].object: empty" in dropped and "[2].prompts: expected a list, got str" in dropped
    assert "[3].object: duplicate" in dropped
    (req,) = fake.requests
    body = req["body"]
    assert vendor.max_tokens(body) == SYNTHESIS_MAX_OUTPUT_TOKENS == 512
    assert vendor.schema(body)["type"] == "array" and "prompts" in vendor.schema(body)["items"]["required"]
    assert vendor.images(body) == [b"\x89PNG fake"]
    assert "Task: put the red block on the plate" in vendor.turns(body)[0][1]
    (call,) = planner.calls
    assert call["kind"] == "prompt_synthesis" and call["image_attached"] and call["usage"]["input_tokens"] == 300
    assert call["objects"] == ["red block", "plate", "bowl"] and call["dropped"] == list(syn.dropped)


def test_the_synthesis_call_without_variants_asks_for_objects_only(vendor):
    with vendor.server() as fake:
        fake.script = [("ok", json.dumps([{"object": "red block"}, {"object": "plate"}]))]
        syn = vendor.planner(fake).synthesise("put the red block on the plate", None, 0)
    assert syn.objects == ("red block", "plate") and syn.variants == {}
    body = fake.requests[0]["body"]
    assert "prompts" not in vendor.schema(body)["items"]["properties"] and vendor.images(body) == []


@pytest.mark.parametrize("answer", ["not json", json.dumps({"objects": 3}), json.dumps("red block")])
def test_a_synthesis_answer_of_the_wrong_shape_gives_nothing_to_use(vendor, answer):
    with vendor.server() as fake:
        fake.script = [("ok", answer)]
        syn = vendor.planner(fake).synthesise("put the red block on the plate", None, 3)
    assert syn.objects in ((), ("objects",)) and syn.variants == {} and syn.dropped


def test_a_synthesis_answer_cut_at_512_tokens_is_refused_not_half_used(vendor):
    long = json.dumps([{"object": f"object {i}", "prompts": [f"red thing {i}"] * 3} for i in range(200)])
    with vendor.server() as fake:
        fake.script = [("ok", long)]
        syn = vendor.planner(fake).synthesise("tidy up", None, 3)
    assert syn.objects == () and "not JSON" in syn.dropped[0]  # the vendor cut the answer at the limit


def test_the_synthesis_call_retries_then_raises_for_the_caller_to_record(vendor):
    with vendor.server() as fake:
        fake.script = [("status", 429), ("ok", json.dumps([{"object": "mug", "prompts": ["white cup"]}]))]
        assert vendor.planner(fake, max_retries=1).synthesise("pick up the mug", None, 3).objects == ("mug",)
    with vendor.server() as fake:
        fake.script = [("status", 503)] * 2
        with pytest.raises(TransientError, match="gave up after 2 attempts"):
            vendor.planner(fake, max_retries=1).synthesise("pick up the mug", None, 3)
    with vendor.server() as fake:
        fake.script = [("status", 400)]
        with pytest.raises(PlannerUnavailable, match="HTTP 400"):
            vendor.planner(fake).synthesise("pick up the mug", None, 3)


def test_the_vendors_refuse_a_request_without_a_key():
    """The fakes check what the vendors check, so a planner that stopped sending its key would be caught."""
    import httpx

    with FakeGemini() as g, FakeOpenAI() as o:
        r1 = httpx.post(g.url + "/v1beta/models/m:generateContent", json={"contents": []})
        r2 = httpx.post(o.url + "/v1/chat/completions", json={"model": "m", "messages": []})
    assert r1.status_code == 403 and r1.json()["error"]["status"] == "PERMISSION_DENIED"
    assert r2.status_code == 401 and r2.json()["error"]["type"] == "invalid_request_error"


@pytest.mark.parametrize(
    ("body", "why"),
    [
        ({"promptFeedback": {"blockReason": "SAFETY"}}, "the prompt was blocked (SAFETY)"),
        (
            {"candidates": [{"content": {"role": "model", "parts": []}, "finishReason": "SAFETY"}]},
            "finish reason SAFETY",
        ),
    ],
)
def test_gemini_without_an_answer_says_why_and_is_not_repaired(body, why):
    import json as _json

    with FakeGemini() as fake:
        payload = {**body, "usageMetadata": {"promptTokenCount": 10, "totalTokenCount": 10}, "modelVersion": "m"}
        fake.script = [("raw", 200, _json.dumps(payload).encode())] * 2
        res = Vendor("gemini").planner(fake).plan(request())
    assert not res.ok and len(fake.requests) == 1 and f"Gemini gave no answer: {why}" in res.error


def test_an_openai_refusal_says_so_and_is_not_repaired():
    with FakeOpenAI() as fake:
        refusal = fake.success("", (10, 0, 0), {"model": "m"})
        refusal["choices"][0]["message"] |= {"content": None, "refusal": "I can't help with that."}
        fake.script = [("raw", 200, json.dumps(refusal).encode())] * 2
        res = Vendor("openai").planner(fake).plan(request())
    assert not res.ok and len(fake.requests) == 1 and "the model refused: I can't help with that." in res.error
