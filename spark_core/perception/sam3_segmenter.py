"""`sam3` segmenter: SAM3 (transformers `Sam3Model`) with our own pre/post-processing (no torchvision).

Weights come from a local directory or a model id already in the local Hugging Face cache; nothing is ever
downloaded at run time. One image encoding is reused for every prompt of a call.
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from pathlib import Path

import cv2
import numpy as np

from .detection import Detection
from .frame import CameraFrame

DEFAULT_MODEL = "facebook/sam3"
TEXT_TOKENS = 32  # SAM3's CLIP text encoder takes 32 tokens
# The paper's detection threshold rule: SAM3 reports instances at the model's own default threshold (the one of
# transformers' Sam3Processor.post_process_instance_segmentation: score 0.3, masks binarised at 0.5); which of
# them a label keeps is then decided by the selection rule in adaptive.py, which supersedes the threshold when
# there are alternative prompts (the adaptive configuration).
MODEL_SCORE_THRESHOLD = 0.3
MODEL_MASK_THRESHOLD = 0.5


class Sam3WeightsMissing(FileNotFoundError):
    """The SAM3 checkpoint is not on this machine; the message says what is missing and how to provide it."""


def locate_checkpoint(model: str | os.PathLike) -> Path:
    """A directory holding config.json + weights: `model` itself if it is one, else its local HF-cache snapshot."""
    path = Path(model).expanduser()
    if path.is_dir():
        if not (path / "config.json").exists():
            raise Sam3WeightsMissing(
                f"{path} exists but has no config.json: it is not a SAM3 checkpoint directory "
                "(expected config.json, model.safetensors and the tokenizer files)"
            )
        return path
    try:
        from huggingface_hub import snapshot_download

        return Path(snapshot_download(str(model), local_files_only=True))
    except Exception:
        raise Sam3WeightsMissing(
            f"SAM3 weights not found: {str(model)!r} is neither a local directory nor in the Hugging Face cache "
            f"({os.environ.get('HF_HOME', '~/.cache/huggingface')}). This machine cannot download them. On a machine "
            f"with network access, accept the licence of {DEFAULT_MODEL} on Hugging Face, run "
            f"`huggingface-cli download {DEFAULT_MODEL} --local-dir sam3`, copy the `sam3` directory here and pass it "
            "as the model path (or set SPARK_SAM3_MODEL=/path/to/sam3). A GPU is strongly advised: one image and "
            "prompt takes ~75 s on 2 CPU cores."
        ) from None


class Sam3Segmenter:
    name = "sam3"
    privileged = False

    def __init__(
        self,
        model: str | os.PathLike | None = None,
        device: str | None = None,
        score_threshold: float = MODEL_SCORE_THRESHOLD,
        mask_threshold: float = MODEL_MASK_THRESHOLD,
        max_detections: int = 10,
    ):
        import torch
        from transformers import AutoTokenizer, Sam3Model

        self.path = locate_checkpoint(model or os.environ.get("SPARK_SAM3_MODEL", DEFAULT_MODEL))
        self.device = device or ("cuda" if torch.cuda.is_available() else "cpu")
        # transformers' stubs type .to() of a from_pretrained() result wrongly (as taking a model)
        self.model = Sam3Model.from_pretrained(str(self.path)).to(self.device).eval()  # type: ignore[arg-type]
        self.tokenizer = AutoTokenizer.from_pretrained(str(self.path))
        self.image_size = int(self.model.config.vision_config.image_size)
        self.score_threshold = score_threshold
        self.mask_threshold = mask_threshold
        self.max_detections = max_detections

    def preprocess(self, rgb: np.ndarray):
        """uint8 HxWx3 -> (1, 3, S, S) float tensor: bilinear resize to the model's square input, mean = std = 0.5."""
        import torch

        img = (
            cv2.resize(rgb, (self.image_size, self.image_size), interpolation=cv2.INTER_LINEAR).astype(np.float32)
            / 255.0
        )
        img = (img - 0.5) / 0.5
        return torch.from_numpy(img.transpose(2, 0, 1)[None].copy()).to(self.device)

    def segment(self, frame: CameraFrame, prompts: Sequence[str]) -> list[Detection]:
        import torch

        if not prompts:
            return []
        h, w = frame.shape
        tokens = self.tokenizer(
            list(prompts), padding="max_length", max_length=TEXT_TOKENS, truncation=True, return_tensors="pt"
        )
        out: list[Detection] = []
        with torch.no_grad():
            vision = self.model.get_vision_features(pixel_values=self.preprocess(frame.rgb))  # once per image
            for i, prompt in enumerate(prompts):
                res = self.model(
                    vision_embeds=vision,
                    input_ids=tokens["input_ids"][i : i + 1].to(self.device),
                    attention_mask=tokens["attention_mask"][i : i + 1].to(self.device),
                )
                scores = (torch.sigmoid(res.pred_logits[0]) * torch.sigmoid(res.presence_logits[0])).cpu().numpy()
                masks = torch.sigmoid(res.pred_masks[0]).cpu().numpy()
                boxes = res.pred_boxes[0].cpu().numpy()
                for q in np.argsort(-scores)[: self.max_detections]:
                    if scores[q] < self.score_threshold:
                        break
                    mask = cv2.resize(masks[q], (w, h), interpolation=cv2.INTER_LINEAR) > self.mask_threshold
                    if not mask.any():
                        continue
                    x0, y0, x1, y1 = (boxes[q] * [w, h, w, h]).tolist()
                    out.append(
                        Detection(
                            prompt,
                            prompt,
                            mask,
                            float(scores[q]),
                            frame.camera,
                            False,
                            {"box_xyxy_px": [round(x0, 1), round(y0, 1), round(x1, 1), round(y1, 1)], "query": int(q)},
                        )
                    )
        return out


TINY_VOCAB = ["<pad>", "<s>", "</s>", "<unk>", "red", "block", "blue", "plate", "the", "bowl", "white", "cube"]


def build_tiny_checkpoint(path: str | os.PathLike, seed: int = 0) -> Path:
    """A tiny randomly initialised SAM3 (hidden 32, 2 layers, 224 px) with a word-level tokenizer, saved with
    `save_pretrained` so `Sam3Segmenter(path)` loads it on the real checkpoint's path. It detects nothing
    meaningful: for tests and smoke runs of the pipeline on a machine without the real weights (~1 MB)."""
    import torch
    from tokenizers import Tokenizer, models, pre_tokenizers
    from transformers import PreTrainedTokenizerFast, Sam3Config, Sam3Model

    torch.manual_seed(seed)
    small = dict(hidden_size=32, num_attention_heads=2, intermediate_size=64)
    cfg = Sam3Config(
        vision_config=dict(
            backbone_config=dict(
                model_type="sam3_vit_model",
                num_hidden_layers=2,
                image_size=224,
                patch_size=14,
                window_size=8,
                global_attn_indexes=[1],
                pretrain_image_size=224,
                **small,
            ),
            fpn_hidden_size=32,
            backbone_feature_sizes=[[64, 64], [32, 32], [16, 16]],
        ),
        text_config=dict(
            vocab_size=len(TINY_VOCAB),
            projection_dim=32,
            num_hidden_layers=2,
            max_position_embeddings=32,
            bos_token_id=1,
            eos_token_id=2,
            pad_token_id=0,
            **small,
        ),
        geometry_encoder_config=dict(num_layers=1, **small),
        detr_encoder_config=dict(num_layers=1, **small),
        detr_decoder_config=dict(num_layers=1, num_queries=20, **small),
        mask_decoder_config=dict(hidden_size=32, num_attention_heads=2),
    )
    out = Path(path)
    Sam3Model(cfg).save_pretrained(out)
    tok = Tokenizer(models.WordLevel({w: i for i, w in enumerate(TINY_VOCAB)}, unk_token="<unk>"))
    tok.pre_tokenizer = pre_tokenizers.Whitespace()
    PreTrainedTokenizerFast(
        tokenizer_object=tok, pad_token="<pad>", unk_token="<unk>", bos_token="<s>", eos_token="</s>"
    ).save_pretrained(out)
    return out


def describe_checkpoint(model: str | os.PathLike | None) -> str:
    """The checkpoint in words, for protocol lines: whether it is the tiny random one (no real weights)."""
    import json

    model = model or os.environ.get("SPARK_SAM3_MODEL", DEFAULT_MODEL)
    try:
        cfg = json.loads((locate_checkpoint(model) / "config.json").read_text())
        hidden = cfg["vision_config"]["backbone_config"]["hidden_size"]
    except (Sam3WeightsMissing, KeyError, ValueError):
        return f"the checkpoint {model}"
    if hidden <= 64:
        return (
            f"a tiny randomly initialised checkpoint at {model} (hidden size {hidden}; built by "
            f"`python -m spark_core.perception.sam3_segmenter --tiny {model}`), not SAM3's weights"
        )
    return f"the checkpoint at {model} (hidden size {hidden})"


if __name__ == "__main__":  # python -m spark_core.perception.sam3_segmenter --tiny DIR
    import argparse

    parser = argparse.ArgumentParser(description="build the tiny random SAM3 checkpoint for smoke runs")
    parser.add_argument("--tiny", required=True, metavar="DIR", help="where to save it")
    print(build_tiny_checkpoint(parser.parse_args().tiny))
