"""The cross-encoder that scores how well a plainly said goal matches an instruction.

all-MiniLM-L6-v2 (the sentence encoder the grounding already ships, `perception/text_encoder.py`) reads the pair
"instruction [SEP] goal"; its last transformer layer and a linear head on the [CLS] state were trained here on the
dev wording corpus (`train.py`); the other five layers are the shipped model's, frozen. Only the trained layer and
head are stored (`weights/reader.pt`, float16, ~3.5 MB)."""

from __future__ import annotations

import threading
from pathlib import Path

import torch
from torch import nn

WEIGHTS = Path(__file__).with_name("weights") / "reader.pt"
TRAINED_LAYERS = 2  # the last N transformer layers are trained; the rest stay as shipped
MAX_TOKENS = 96
# "None of these": the score of the answer that no goal offered is the one, in training and in use.
NONE_SCORE = 0.0
_LOCK = threading.Lock()
_LOADED: dict[str, CrossEncoder] = {}


class CrossEncoder(nn.Module):
    """MiniLM over the pair, a linear score from its [CLS] state."""

    def __init__(self):
        super().__init__()
        from ...perception.text_encoder import TextEncoder

        shipped = TextEncoder._model()[0]
        self.tokenizer = shipped.tokenizer
        # a copy: the grounding's encoder stays as shipped
        self.bert = type(shipped.auto_model)(shipped.auto_model.config)
        self.bert.load_state_dict(shipped.auto_model.state_dict())
        self.head = nn.Linear(self.bert.config.hidden_size, 1)
        for p in self.bert.parameters():
            p.requires_grad = False
        for p in self.trained_parameters():
            p.requires_grad = True

    def trained_parameters(self) -> list[nn.Parameter]:
        layers = self.bert.encoder.layer[-TRAINED_LAYERS:]
        return [p for layer in layers for p in layer.parameters()] + list(self.head.parameters())

    def trained_state(self) -> dict[str, torch.Tensor]:
        keep = {id(p) for p in self.trained_parameters()}
        return {k: v.detach().half() for k, v in self.named_parameters() if id(v) in keep}

    def encode_pairs(self, instructions: list[str], goals: list[str]) -> dict[str, torch.Tensor]:
        return self.tokenizer(
            instructions, goals, padding=True, truncation=True, max_length=MAX_TOKENS, return_tensors="pt"
        )

    def frozen_states(self, batch: dict[str, torch.Tensor]) -> tuple[torch.Tensor, torch.Tensor]:
        """The hidden states entering the first trained layer, and the attention mask (computed once in
        training: those layers never change)."""
        emb = self.bert.embeddings(input_ids=batch["input_ids"], token_type_ids=batch["token_type_ids"])
        mask = self._mask(batch["attention_mask"])
        h = emb
        for layer in self.bert.encoder.layer[:-TRAINED_LAYERS]:
            h = _layer_out(layer(h, attention_mask=mask))
        return h, batch["attention_mask"]

    def score_states(self, h: torch.Tensor, attention_mask: torch.Tensor) -> torch.Tensor:
        mask = self._mask(attention_mask)
        for layer in self.bert.encoder.layer[-TRAINED_LAYERS:]:
            h = _layer_out(layer(h, attention_mask=mask))
        return self.head(h[:, 0]).squeeze(-1)

    def _mask(self, attention_mask: torch.Tensor) -> torch.Tensor:
        return (1.0 - attention_mask[:, None, None, :].float()) * torch.finfo(torch.float32).min

    @torch.no_grad()
    def scores(self, instruction: str, goals: list[str], batch: int = 64) -> list[float]:
        """A score per goal (higher: more likely the goal the instruction states)."""
        out: list[float] = []
        for i in range(0, len(goals), batch):
            enc = self.encode_pairs([instruction] * len(goals[i : i + batch]), goals[i : i + batch])
            out += self.score_states(*self.frozen_states(enc)).tolist()
        return out


def _layer_out(out) -> torch.Tensor:
    return out[0] if isinstance(out, tuple) else out


def load(path: Path = WEIGHTS) -> CrossEncoder | None:
    """The trained scorer, loaded once per process; None when no weights are shipped at `path`."""
    with _LOCK:
        key = str(path)
        if key not in _LOADED:
            if not path.exists():
                return None
            model = CrossEncoder()
            state = {k: v.float() for k, v in torch.load(path, map_location="cpu", weights_only=True).items()}
            missing = model.load_state_dict(state, strict=False)
            if missing.unexpected_keys:
                raise RuntimeError(f"{path}: keys the reader has not: {missing.unexpected_keys[:3]}")
            model.eval()
            _LOADED[key] = model
        return _LOADED[key]
