"""The paper's perception loop for LLM planners, through the trial pipeline and `spark plan`, against a loopback
server that answers like OpenAI: (a) the prompt-synthesis call on the task language and the agentview image gives
the objects to detect and three alternative prompts each; (b, c) perception tries every prompt on every camera and
keeps the single confident detection; (d) the BT call gets the annotated image. Both calls are in the trace
(prompt, response, usage, cost, latency; the BT call's image by SHA-256) and the trial's cost counts both."""

from __future__ import annotations

import base64
import hashlib
import json
from collections.abc import Callable
from pathlib import Path

import pytest

from spark_core.trial import TrialConfig, Verdict, run_trial
from tests.doubles.fake_openai import FakeOpenAI

PLAN = {
    "task": "pick up the red block",
    "tree": {"type": "sequence", "children": [{"type": "pick", "params": {"keypoint_label": "red block"}}]},
}
SYNTHESIS = [{"object": "red block", "prompts": ["crimson cube", "red wooden cube", "scarlet block"]}]


def _config(fake, **kw) -> TrialConfig:
    kw.setdefault("model", "m")
    return TrialConfig("lift_block", planner="openai", base_url=fake.url + "/v1", segmenter="sim", **kw)


def _images(body: dict) -> list[bytes]:
    content = body["messages"][1]["content"]
    if isinstance(content, str):
        return []
    return [base64.b64decode(p["image_url"]["url"].split(",", 1)[1]) for p in content if p["type"] == "image_url"]


def _prompts_tried(store, trial_id: str) -> set[str]:
    groundings = store.get_trial(trial_id)["groundings"]
    return {c["prompt"] for g in groundings for cam in g["cameras"].values() for c in cam["candidates"]}


def test_the_synthesis_call_comes_first_with_the_image_and_both_calls_are_traced_and_costed():
    with FakeOpenAI() as fake:
        fake.script = [("ok", json.dumps(SYNTHESIS), (50, 20, 0)), ("ok", json.dumps(PLAN), (900, 60, 0))]
        # a model with a price in the table: an OpenAI-compatible proxy serving Gemini
        out = run_trial(_config(fake, model="gemini-3.1-pro"))
    assert out.verdict is Verdict.SUCCESS, out.reason
    first, second = (r["body"] for r in fake.requests)
    assert "open-vocabulary object detector" in first["messages"][0]["content"]  # the synthesis call, first
    assert first["max_tokens"] == 512 and first["response_format"]["json_schema"]["schema"]["type"] == "array"
    assert "Task: pick up the red block" in first["messages"][1]["content"][0]["text"]
    (agentview,) = _images(first)  # the raw agentview image goes with the synthesis call
    (annotated,) = _images(second)  # the annotated one with the BT call
    assert agentview[:4] == annotated[:4] == b"\x89PNG" and agentview != annotated
    calls = out.protocol["planning"]["calls"]
    assert [c["kind"] for c in calls] == ["prompt_synthesis", "behavior_tree"]
    syn, bt = calls
    assert syn["response"] == json.dumps(SYNTHESIS) and syn["usage"]["input_tokens"] == 50 and syn["image_attached"]
    assert syn["objects"] == ["red block"] and syn["variants"] == {"red block": SYNTHESIS[0]["prompts"]}
    assert bt["image"]["sha256"] == hashlib.sha256(annotated).hexdigest() and bt["image"]["camera"] == "agentview"
    assert "Task: pick up the red block" in bt["prompt"] and bt["response"] == json.dumps(PLAN)
    assert out.cost_usd == syn["cost_usd"] + bt["cost_usd"] and syn["cost_usd"] > 0 and bt["cost_usd"] > 0
    assert out.usage["input_tokens"] == 950 and out.usage["output_tokens"] == 80
    assert "two calls" in out.protocol["planner"]


def test_perception_tries_the_llms_prompts(tmp_path):
    from spark_core.trace import TraceStore
    from spark_core.trace.sink import StoreSink

    store = TraceStore(f"sqlite:///{tmp_path / 'p.db'}")
    with FakeOpenAI() as fake:
        fake.script = [("ok", json.dumps(SYNTHESIS)), ("ok", json.dumps(PLAN))]
        out = run_trial(_config(fake), [StoreSink(store, tmp_path / "artifacts")])
    assert {"red block", "crimson cube", "red wooden cube", "scarlet block"} <= _prompts_tried(store, out.trial_id)
    grounding = store.get_trial(out.trial_id)["groundings"][0]
    chosen = [cam["chosen"] for cam in grounding["cameras"].values()]
    assert any(c is not None for c in chosen)  # the one kept is named, with every candidate's score
    assert all("best_score" in c for cam in grounding["cameras"].values() for c in cam["candidates"])
    trial = store.get_trial(out.trial_id)
    _check_planner_image(trial, trial["protocol"]["planning"]["calls"][-1])


def test_bad_phrases_are_filtered_and_perception_falls_back_to_its_table(tmp_path):
    from spark_core.trace import TraceStore
    from spark_core.trace.sink import StoreSink

    store = TraceStore(f"sqlite:///{tmp_path / 'p.db'}")
    bad = [{"object": "red block", "prompts": ["", 7, "a " * 30, "red block", "Red  Block"]}]
    with FakeOpenAI() as fake:
        fake.script = [("ok", json.dumps(bad)), ("ok", json.dumps(PLAN))]
        out = run_trial(_config(fake), [StoreSink(store, tmp_path / "artifacts")])
    assert out.verdict is Verdict.SUCCESS, out.reason
    syn = out.protocol["planning"]["calls"][0]
    assert syn["variants"] == {} and len(syn["dropped"]) == 5
    assert {"red cube", "red wooden block"} <= _prompts_tried(store, out.trial_id)  # the synonym table's


def test_a_failed_synthesis_call_is_recorded_and_perception_falls_back_to_its_table():
    with FakeOpenAI() as fake:
        fake.script = [("status", 400), ("ok", json.dumps(PLAN))]
        out = run_trial(_config(fake))
    calls = out.protocol["planning"]["calls"]
    assert calls[0]["kind"] == "prompt_synthesis" and "HTTP 400" in calls[0]["error"]
    assert out.verdict is Verdict.SUCCESS, out.reason


def test_an_instruction_the_rules_parser_cannot_read_still_gives_the_llm_detections():
    from spark_core.planning.observe import phrases_for

    instruction = "make it fly"
    assert phrases_for(instruction) == []  # nothing for perception without the synthesis call (no noun either)
    with FakeOpenAI() as fake:
        fake.script = [("ok", json.dumps(SYNTHESIS)), ("ok", json.dumps(PLAN))]
        out = run_trial(_config(fake, instruction=instruction))
    assert "red block: (" in fake.requests[1]["body"]["messages"][1]["content"][0]["text"]
    assert out.verdict is Verdict.SUCCESS, out.reason


def test_without_adaptive_prompts_the_synthesis_call_asks_for_objects_only():
    with FakeOpenAI() as fake:
        fake.script = [("ok", json.dumps([{"object": "red block"}])), ("ok", json.dumps(PLAN))]
        out = run_trial(_config(fake, adaptive=False))
    assert out.verdict is Verdict.SUCCESS, out.reason
    schema = fake.requests[0]["body"]["response_format"]["json_schema"]["schema"]
    assert "prompts" not in schema["items"]["properties"]


def test_spark_plan_makes_the_synthesis_call_too(capsys):
    from spark_cli import main

    with FakeOpenAI() as fake:
        fake.script = [("ok", json.dumps(SYNTHESIS), (40, 10, 0)), ("ok", json.dumps(PLAN))]
        code = main(
            ["plan", "make the red block fly", "--task", "lift_block", "--planner", "openai", "--model", "m"]
            + ["--base-url", fake.url + "/v1"]
        )
    out = capsys.readouterr().out
    assert code == 0 and len(fake.requests) == 2
    assert "prompt synthesis: objects red block" in out and "crimson cube, red wooden cube, scarlet block" in out
    assert "red block: (" in out and "type: pick" in out and "cost of both calls" in out
    assert len(_images(fake.requests[0]["body"])) == 1


# -- end to end: planner gemini (the real google-genai client, loopback server), segmenter sam3 (tiny checkpoint) --
def _gemini_endpoint(tmp_path, monkeypatch, fake) -> None:
    config = tmp_path / "spark.yaml"
    config.write_text(
        f"endpoints:\n  fake: {{planner: gemini, base_url: '{fake.url}', api_key_env: FAKE_GEMINI_KEY}}\n"
    )
    monkeypatch.setenv("SPARK_CONFIG", str(config))
    monkeypatch.setenv("FAKE_GEMINI_KEY", "test-key")


@pytest.fixture(scope="module")
def tiny_sam3(tmp_path_factory):
    from spark_core.perception.sam3_segmenter import build_tiny_checkpoint

    return str(build_tiny_checkpoint(tmp_path_factory.mktemp("sam3-tiny")))


def _check_trace(trial: dict, fake, read: Callable[[dict], bytes] | None = None) -> None:
    """What the issue asks the trace to show: the synthesis call, the BT call with the annotated image, every
    prompt candidate with its SAM3 score and the one kept, and the cost of both calls."""
    planning = trial["protocol"]["planning"]
    syn, bt = planning["calls"]
    assert syn["kind"] == "prompt_synthesis" and syn["image_attached"] and syn["variants"]["red block"]
    assert bt["kind"] == "behavior_tree" and bt["image"]["camera"] == "agentview" and len(bt["image"]["sha256"]) == 64
    assert planning["cost_usd"] == pytest.approx(syn["cost_usd"] + bt["cost_usd"]) and syn["cost_usd"] > 0
    assert [r["path"].rsplit(":", 1)[-1] for r in fake.requests] == ["generateContent"] * 2
    candidates = [c for g in trial["groundings"] for cam in g["cameras"].values() for c in cam["candidates"]]
    assert {"red block", *SYNTHESIS[0]["prompts"]} <= {c["prompt"] for c in candidates}
    assert all(isinstance(c["best_score"], float) and c["verdict"] for c in candidates)
    assert all("chosen" in cam for g in trial["groundings"] for cam in g["cameras"].values())
    _check_planner_image(trial, bt, read)


def _check_planner_image(trial: dict, bt: dict, read: Callable[[dict], bytes] | None = None) -> None:
    """The BT call's annotated image is kept with the trial's artifacts, byte for byte as sent. `read`: the
    artifact's bytes (default: its file, as the store records it; the console API serves them by name)."""
    (image,) = [a for a in trial["artifacts"] if a["kind"] == "planner_input"]
    data = read(image) if read else Path(image["path"]).read_bytes()
    assert image["sha256"] == bt["image"]["sha256"] == hashlib.sha256(data).hexdigest()
    assert image["camera"] == bt["image"]["camera"]


def test_spark_run_with_gemini_and_sam3_traces_both_calls(tmp_path, monkeypatch, tiny_sam3, capsys):
    from spark_cli import main
    from spark_core.trace import TraceStore
    from tests.doubles.fake_gemini import FakeGemini

    store = f"sqlite:///{tmp_path / 'run.db'}"
    with FakeGemini() as fake:
        _gemini_endpoint(tmp_path, monkeypatch, fake)
        fake.script = [("ok", json.dumps(SYNTHESIS), (300, 60, 0)), ("ok", json.dumps(PLAN), (2000, 80, 40))]
        main(
            ["run", "lift_block", "--planner", "gemini", "--endpoint", "fake", "--segmenter", "sam3"]
            + ["--sam3-model", tiny_sam3, "--store", store, "--no-plan-library"]
        )
    out = capsys.readouterr().out
    assert "verdict:" in out  # the random tiny model finds nothing it is sure of: the trial ends, it does not crash
    (trial,) = TraceStore(store).list_trials()[1]
    _check_trace(TraceStore(store).get_trial(trial["id"]), fake)


def test_a_console_trial_with_gemini_and_sam3_traces_both_calls(tmp_path, monkeypatch, tiny_sam3):
    import time

    from fastapi.testclient import TestClient

    from server.app import create_app
    from server.settings import Settings
    from tests.doubles.fake_gemini import FakeGemini

    with FakeGemini() as fake:
        _gemini_endpoint(tmp_path, monkeypatch, fake)
        monkeypatch.setenv("SPARK_SAM3_MODEL", tiny_sam3)  # the operator's checkpoint
        fake.script = [("ok", json.dumps(SYNTHESIS)), ("ok", json.dumps(PLAN))]
        app = create_app(Settings(store_url=f"sqlite:///{tmp_path / 'c.db'}", workers=1, viser=False))
        with TestClient(app) as c:
            r = c.post(
                "/api/trials",
                json={"task": "lift_block", "planner": "gemini", "endpoint": "fake", "segmenter": "sam3"},
            )
            assert r.status_code == 202, r.text
            t0 = time.monotonic()
            while (trial := c.get(f"/api/trials/{r.json()['id']}").json())["status"] not in ("done", "interrupted"):
                assert time.monotonic() - t0 < 180, trial["status"]
                time.sleep(0.2)
            assert trial["status"] == "done" and trial["verdict"] != "crashed", trial.get("reason")
            assert all("path" not in a for a in trial["artifacts"])  # the API names files, never where they lie
            _check_trace(trial, fake, lambda a: c.get(f"/api/trials/{trial['id']}/artifacts/{a['name']}").content)


@pytest.mark.slow  # spark bench's path; the s2 smoke test in tests/bench/test_protocols.py runs it by default
def test_a_one_trial_bench_with_gemini_and_sam3_traces_both_calls(tmp_path, monkeypatch, tiny_sam3):
    from spark_cli import main
    from spark_core.trace import TraceStore
    from tests.doubles.fake_gemini import FakeGemini

    store = f"sqlite:///{tmp_path / 'bench.db'}"
    with FakeGemini() as fake:
        _gemini_endpoint(tmp_path, monkeypatch, fake)
        fake.script = [("ok", json.dumps(SYNTHESIS)), ("ok", json.dumps(PLAN))]
        code = main(
            ["bench", "builtin", "--tasks", "lift_block", "--trials", "1", "--planner", "gemini", "--endpoint", "fake"]
            + ["--segmenter", "sam3", "--sam3-model", tiny_sam3, "--store", store]
        )
    assert code == 0
    (trial,) = TraceStore(store).list_trials()[1]
    _check_trace(TraceStore(store).get_trial(trial["id"]), fake)


def test_the_bt_calls_image_has_the_kept_masks_and_labels_drawn_on_it():
    import numpy as np

    from spark_core.perception.annotate import annotate
    from spark_core.perception.factory import make_resolver
    from spark_core.planning.observe import annotated_view, observe
    from spark_core.sim.tasks import TASKS

    world = TASKS["lift_block"].make_world(0)
    try:
        resolver = make_resolver(world, "sim")
        view = annotated_view(observe("pick up the red block", resolver), resolver)
        frame = resolver.frames["agentview"]
        mask = resolver.detections["agentview"]["red block"].mask
        crosses_only = annotate(frame, [], view.keypoints)
    finally:
        world.close()
    assert view.image is not None and view.image.shape == frame.rgb.shape
    tinted = np.any(view.image[mask] != crosses_only[mask], axis=1).mean()
    assert tinted > 0.5  # the kept detection's mask is tinted (and outlined, labelled), not just a cross


def test_an_unknown_primitive_twice_ends_the_trial_as_a_clear_planner_error():
    bad = {"task": "t", "tree": {"type": "sequence", "children": [{"type": "pick_up", "params": {}}]}}
    with FakeOpenAI() as fake:
        fake.script = [("ok", json.dumps(SYNTHESIS)), ("ok", json.dumps(bad)), ("ok", json.dumps(bad))]
        out = run_trial(_config(fake))
    assert len(fake.requests) == 3  # the synthesis call, the BT call and exactly one repair round
    assert out.verdict is Verdict.PLANNER_ERROR
    assert "did not type-check after 1 repair round" in out.reason and "unknown primitive 'pick_up'" in out.reason
