"""The `sam3` backend on its real loading path: a tiny randomly initialised SAM3 is built, saved with
`save_pretrained` (model + tokenizer), reloaded with `from_pretrained`, and run on a rendered scene image."""

import numpy as np
import pytest

from spark_core.perception.sam3_segmenter import (
    Sam3Segmenter,
    Sam3WeightsMissing,
    build_tiny_checkpoint,
    locate_checkpoint,
)


@pytest.fixture(scope="module")
def tiny_checkpoint(tmp_path_factory):
    return build_tiny_checkpoint(tmp_path_factory.mktemp("sam3-tiny"))


@pytest.fixture(scope="module")
def frame():
    from spark_core.sim.tasks import BUILTIN

    w = BUILTIN["block_on_plate"].make_world(0)
    f = w.render("agentview")
    w.close()
    return f


def test_tiny_model_runs_on_a_rendered_scene(tiny_checkpoint, frame):
    seg = Sam3Segmenter(tiny_checkpoint, device="cpu", score_threshold=0.0, max_detections=3)
    assert seg.image_size == 224 and not seg.privileged
    dets = seg.segment(frame, ["red block", "the plate"])
    assert {d.prompt for d in dets} == {"red block", "the plate"}
    for d in dets:
        assert d.mask.shape == frame.shape and d.mask.dtype == bool  # masks at image resolution
        assert 0.0 <= d.score <= 1.0 and not d.privileged
        assert len(d.detail["box_xyxy_px"]) == 4
    # per prompt, detections come best-first and at most max_detections
    reds = [d.score for d in dets if d.prompt == "red block"]
    assert reds == sorted(reds, reverse=True) and len(reds) <= 3


def test_image_is_encoded_once_per_call(tiny_checkpoint, frame, monkeypatch):
    seg = Sam3Segmenter(tiny_checkpoint, device="cpu", score_threshold=0.0, max_detections=1)
    calls = []
    original = seg.model.get_vision_features
    monkeypatch.setattr(seg.model, "get_vision_features", lambda **kw: calls.append(1) or original(**kw))
    seg.segment(frame, ["red block", "blue block", "the plate"])
    assert len(calls) == 1


def test_preprocessing_matches_sam3_normalisation(tiny_checkpoint):
    seg = Sam3Segmenter(tiny_checkpoint, device="cpu")
    px = seg.preprocess(np.full((480, 640, 3), 255, np.uint8))
    assert tuple(px.shape) == (1, 3, 224, 224) and float(px.min()) == pytest.approx(1.0)
    px = seg.preprocess(np.zeros((480, 640, 3), np.uint8))
    assert float(px.max()) == pytest.approx(-1.0)


def test_high_threshold_gives_no_detections(tiny_checkpoint, frame):
    assert Sam3Segmenter(tiny_checkpoint, device="cpu", score_threshold=1.01).segment(frame, ["red block"]) == []


def test_missing_weights_say_what_and_how(tmp_path, monkeypatch):
    monkeypatch.setenv("HF_HUB_OFFLINE", "1")
    monkeypatch.setenv("HF_HOME", str(tmp_path / "hf"))
    with pytest.raises(Sam3WeightsMissing) as info:
        locate_checkpoint("facebook/sam3")
    msg = str(info.value)
    assert "not found" in msg and "huggingface-cli download facebook/sam3" in msg and "SPARK_SAM3_MODEL" in msg
    (tmp_path / "empty").mkdir()
    with pytest.raises(Sam3WeightsMissing, match="has no config.json"):
        locate_checkpoint(tmp_path / "empty")


def test_sam3_is_a_segmenter_of_spark_run_and_of_the_trial_pipeline(tiny_checkpoint, capsys):
    """The real loading path behind `--segmenter sam3`: a random tiny model sees nothing it is sure of, so the
    trial ends on a perception failure; the record says the segmenter was not privileged."""
    from spark_cli import main

    code = main(
        [
            "run",
            "lift_block",
            "--segmenter",
            "sam3",
            "--sam3-model",
            str(tiny_checkpoint),
            "--no-store",
            "--no-adaptive",
        ]
    )
    out = capsys.readouterr().out
    assert "segmenter sam3" in out and "PRIVILEGED" not in out
    assert code == 1 and "verdict: tree_failed" in out and "failure=perception" in out


def test_a_missing_sam3_checkpoint_is_refused_before_anything_runs(tmp_path, monkeypatch):
    from spark_core.trial import TrialConfig, TrialConfigError

    monkeypatch.setenv("HF_HOME", str(tmp_path / "empty-cache"))
    with pytest.raises(TrialConfigError, match="segmenter: SAM3 weights not found: '/nowhere/sam3'"):
        TrialConfig("lift_block", segmenter="sam3", sam3_model="/nowhere/sam3").check()


class _Scored:
    """The tiny model's real forward pass with its scores and masks set per prompt (in call order): the
    detection rule is then tested on SAM3's own output path (sigmoid(logit) x sigmoid(presence), mask > 0.5)."""

    def __init__(self, model, scores_per_call: list[list[float]]):
        self.model, self.scores = model, list(scores_per_call)

    def get_vision_features(self, **kw):
        return self.model.get_vision_features(**kw)

    def __call__(self, **kw):
        import torch

        res = self.model(**kw)
        scores = self.scores.pop(0)
        n = res.pred_logits.shape[1]
        logits = torch.full((1, n), -20.0)
        masks = torch.full(res.pred_masks.shape, -20.0)
        side = masks.shape[-1]
        for q, s in enumerate(scores):  # instance q: its own patch of the image, well apart from the others
            logits[0, q] = float(np.log(s / (1 - s)))
            masks[0, q, side // 2 - 4 : side // 2 + 4, q * side // 5 : q * side // 5 + 8] = 20.0
        res.pred_logits, res.presence_logits, res.pred_masks = logits, torch.full((1, 1), 20.0), masks
        return res


def test_the_paper_threshold_rule_is_the_models_default(tiny_checkpoint, frame):
    import inspect

    from transformers.models.sam3.processing_sam3 import Sam3Processor

    from spark_core.perception.sam3_segmenter import MODEL_MASK_THRESHOLD, MODEL_SCORE_THRESHOLD

    defaults = inspect.signature(Sam3Processor.post_process_instance_segmentation).parameters
    assert MODEL_SCORE_THRESHOLD == defaults["threshold"].default == 0.3
    assert MODEL_MASK_THRESHOLD == defaults["mask_threshold"].default == 0.5
    seg = Sam3Segmenter(tiny_checkpoint, device="cpu")
    assert seg.score_threshold == MODEL_SCORE_THRESHOLD
    seg.model = _Scored(seg.model, [[0.9, 0.4, 0.2]])
    dets = seg.segment(frame, ["red block"])
    assert [round(d.score, 3) for d in dets] == [0.9, 0.4]  # reported down to 0.3, no lower


def test_the_adaptive_rule_supersedes_the_threshold(tiny_checkpoint, frame):
    from spark_core.perception.adaptive import CONFIDENT, detection_threshold, select_prompt

    seg = Sam3Segmenter(tiny_checkpoint, device="cpu")
    assert detection_threshold(seg, adaptive=True) == CONFIDENT == 0.5 and detection_threshold(seg, False) == 0.3
    # label: two instances (ambiguous); variant 1: one weak (0.45 < 0.5); variant 2: one confident; variant 3: none
    seg.model = _Scored(seg.model, [[0.9, 0.4], [0.45], [0.7], []])
    sel = select_prompt(seg, frame, "red block", ["crimson cube", "red cube", "the block"])
    verdicts = {c.prompt: c.verdict for c in sel.candidates}
    assert verdicts == {"red block": "ambiguous", "crimson cube": "weak", "red cube": "chosen", "the block": "none"}
    assert sel.chosen_prompt == "red cube" and sel.detection.label == "red block"
    # the label alone (fair, bddl): its single detection is kept at the model's threshold, though not confident
    seg.model = _Scored(seg.model.model, [[0.45]])
    sel = select_prompt(seg, frame, "red block", [])
    assert sel.chosen_prompt == "red block" and sel.candidates[0].best_score == 0.45
    seg.model = _Scored(seg.model.model, [[0.25]])
    assert select_prompt(seg, frame, "red block", []).detection is None  # under 0.3: never reported
