"""The paper's evaluation configurations as named protocols: what each sets, that a privileged segmenter can
never be reported under them, that every report names its protocol, and a smoke run of each through `spark bench`
with the gemini client against the loopback stand-in and the tiny random SAM3 checkpoint."""

from __future__ import annotations

import pytest

from spark_core.bench.protocols import LIBERO_CAMERAS, PROTOCOLS, ProtocolError, apply, bddl_object_names
from spark_core.catalog import SEGMENTERS, catalog_json
from spark_core.trial import TrialConfig, TrialConfigError

LIBERO_TASK = "libero_spatial_swap:pick_up_the_black_bowl_between_the_plate_and_the_ramekin_and_place_it_on_the_plate"


@pytest.fixture(scope="module")
def tiny_sam3(tmp_path_factory):
    from spark_core.perception.sam3_segmenter import build_tiny_checkpoint

    return str(build_tiny_checkpoint(tmp_path_factory.mktemp("sam3-tiny")))


@pytest.mark.parametrize("name", list(PROTOCOLS))
@pytest.mark.parametrize("segmenter", [s for s, e in SEGMENTERS.items() if e.privileged])
def test_a_privileged_segmenter_is_never_reported_under_a_protocol(name, segmenter):
    task = LIBERO_TASK if "liberopro" in PROTOCOLS[name].suites else "Lift"
    with pytest.raises(ProtocolError, match=f"segmenter: '{segmenter}' is privileged"):
        apply(name, TrialConfig(task, planner="gemini", segmenter=segmenter))
    config = TrialConfig(
        task, planner="gemini", segmenter=segmenter, eval_protocol=name, adaptive=PROTOCOLS[name].adaptive
    )
    with pytest.raises(TrialConfigError, match="protocol: segmenter: .* is privileged"):
        config.check()  # also when a config names the protocol itself (a batch, the API)


def test_what_each_protocol_sets(tmp_path, monkeypatch):
    monkeypatch.setenv("SPARK_SAM3_MODEL", str(tmp_path))  # check() only needs a config.json there
    (tmp_path / "config.json").write_text("{}")
    base = TrialConfig(LIBERO_TASK, planner="gemini", segmenter="sam3")
    fair, bddl, adaptive = (apply(n, base) for n in ("fair", "bddl", "adaptive"))
    assert (fair.adaptive, bddl.adaptive, adaptive.adaptive) == (False, False, True)
    assert fair.cameras == bddl.cameras == adaptive.cameras == LIBERO_CAMERAS == ("agentview", "robot0_eye_in_hand")
    assert fair.eval_protocol == "fair" and fair.protocol(60.0)["eval_protocol"] == "fair"
    assert "canonical object names" in bddl.protocol(60.0)["wording"]
    assert "canonical object names" not in fair.protocol(60.0)["wording"]
    with pytest.raises(ProtocolError, match="planner: under protocol 'fair' a planner writes the plan"):
        apply("fair", TrialConfig(LIBERO_TASK, planner="reference", segmenter="sam3"))
    with pytest.raises(ProtocolError, match="task: protocol 's2' is defined on capbench, not liberopro"):
        apply("s2", base)
    s2 = apply("s2", TrialConfig("Lift", planner="rules", segmenter="sam3"))
    assert s2.adaptive and s2.cameras is None  # CaP-Bench's own cameras
    with pytest.raises(ProtocolError, match="unknown protocol 'paper'; available: fair, bddl, adaptive, s2"):
        apply("paper", base)


def test_bddl_names_are_the_tasks_object_categories():
    assert bddl_object_names(LIBERO_TASK) == ["akita black bowl", "cookies", "glazed rim porcelain ramekin", "plate"]
    assert bddl_object_names("lift_block") == []


def test_the_catalog_lists_the_protocols():
    served = {p["name"]: p for p in catalog_json(with_tasks=False)["protocols"]}
    assert list(served) == ["fair", "bddl", "adaptive", "s2"]
    assert served["s2"]["suites"] == ["capbench"] and served["adaptive"]["adaptive"] is True


def test_spark_bench_refuses_a_privileged_segmenter_under_a_protocol(capsys):
    from spark_cli import main

    code = main(["bench", "capbench", "--protocol", "s2", "--planner", "rules", "--segmenter", "sim", "--trials", "1"])
    err = capsys.readouterr().err
    assert code == 2 and "--protocol s2: segmenter: 'sim' is privileged" in err
    code = main(["bench", "capbench", "--protocol", "fair", "--planner", "rules", "--segmenter", "sam3"])
    assert code == 2 and "--protocol fair is defined on liberopro, not capbench" in capsys.readouterr().err


def test_s2_smoke_run_through_the_loopback_gemini_names_its_protocol(tiny_sam3, tmp_path, capsys):
    """One CaP-Bench trial under S2: the real google-genai client against the loopback stand-in (both calls),
    SAM3's tiny random checkpoint through the cameras; the written section names the protocol and says why the
    figure is a smoke figure."""
    from spark_cli import main

    out = tmp_path / "BENCHMARKS.md"
    code = main(
        ["bench", "capbench", "--protocol", "s2", "--planner", "gemini", "--llm-loopback", "--segmenter", "sam3"]
        + ["--sam3-model", tiny_sam3, "--tasks", "Lift", "--trials", "1", "--write", str(out)]
    )
    assert code == 0
    text = out.read_text()
    assert "## capbench, protocol s2 (gemini planner, sam3 segmenter)" in text
    assert "Protocol: protocol `s2`: CaP-Bench under CaP-X's S2 rules" in text and "SMOKE FIGURE" in text
    assert "non-privileged" in text and "loopback stand-in" in text
    assert "| Lift |" in text


@pytest.mark.slow  # a LIBERO env and SAM3 on two 640x480 cameras: ~40 s on 2 cores
def test_bddl_names_reach_perception_through_the_papers_libero_cameras(tiny_sam3, tmp_path, monkeypatch):
    """A LIBERO-PRO trial under `bddl`: perception also looks for the BDDL object categories, on agentview and
    the wrist camera at 640x480 (the synthesis call names only the instruction's objects)."""
    import json

    from spark_core.trace import TraceStore
    from spark_core.trace.sink import StoreSink
    from spark_core.trial import run_trial
    from tests.doubles.fake_gemini import FakeGemini

    store = TraceStore(f"sqlite:///{tmp_path / 'b.db'}")
    with FakeGemini() as fake:
        config = tmp_path / "spark.yaml"
        config.write_text(f"endpoints:\n  fake: {{planner: gemini, base_url: '{fake.url}', api_key_env: FAKE_KEY}}\n")
        monkeypatch.setenv("SPARK_CONFIG", str(config))
        monkeypatch.setenv("FAKE_KEY", "k")
        fake.script = [("ok", json.dumps([{"object": "black bowl"}])), ("ok", "not a plan"), ("ok", "not a plan")]
        base = TrialConfig(LIBERO_TASK, planner="gemini", endpoint="fake", segmenter="sam3", sam3_model=tiny_sam3)
        out = run_trial(apply("bddl", base), [StoreSink(store, tmp_path / "art")])
    trial = store.get_trial(out.trial_id)
    labels = [g["label"] for g in trial["groundings"]]
    assert {"black bowl", "akita black bowl", "glazed rim porcelain ramekin", "plate", "cookies"} <= set(labels)
    assert all(set(g["cameras"]) == {"agentview", "robot0_eye_in_hand"} for g in trial["groundings"])
    assert out.protocol["eval_protocol"] == "bddl" and not out.protocol["privileged"]
    image = fake.requests[0]["body"]["contents"][0]["parts"][1]["inlineData"]["data"]
    import base64

    import cv2
    import numpy as np

    data = base64.urlsafe_b64decode(image.replace("+", "-").replace("/", "_"))  # the SDK sends URL-safe base64
    png = cv2.imdecode(np.frombuffer(data, np.uint8), cv2.IMREAD_COLOR)
    assert png.shape[:2] == (480, 640)  # the synthesis call's agentview image, 640x480


def test_the_loopback_stand_in_answers_from_the_offline_parts():
    import json

    from spark_core.bench.loopback_llm import answer
    from spark_core.grammar import validate
    from spark_core.planning.llm import synthesis_schema

    def request(text: str, schema: dict | None = None) -> dict:
        config = {"responseJsonSchema": schema} if schema else {}
        return {"contents": [{"role": "user", "parts": [{"text": text}]}], "generationConfig": config}

    syn = json.loads(answer(request("Task: put the red block on the plate", synthesis_schema(3))))
    assert [e["object"] for e in syn] == ["red block", "plate"]
    assert syn[0]["prompts"] == ["red cube", "red wooden block"]  # never the bare "the block"
    assert "prompts" not in json.loads(answer(request("Task: pick up the red block", synthesis_schema(0))))[0]
    seen = (
        "What perception sees now:\nobjects (label: centre xyz m, size xyz m):\n"
        "- red block: (0.500, 0.000, 0.020), size (0.040, 0.040, 0.040)\n"
        "- plate: (0.500, 0.200, 0.008), size (0.180, 0.180, 0.016)\n\nTask: put the red block on the plate"
    )
    plan, issues = validate(answer(request(seen)))
    assert plan is not None, issues
    assert [n.primitive for _, n, _ in plan.primitives()][-1] in ("place", "release")
    nothing = answer(request("What perception sees now:\n(nothing reported)\n\nTask: put the red block on the plate"))
    assert validate(nothing)[0] is None  # no keypoints: an answer that does not type-check, as a model's would
