"""Plan library: successful plans kept with their instruction and scene summary, retrieved by text similarity
as few-shot examples. Built passively from execution; never used to fine-tune anything; can be turned off."""

from __future__ import annotations

import json
import threading
import time
from pathlib import Path

import numpy as np

from ..perception.text_encoder import SHARED_ENCODER, TextEncoder


class PlanLibrary:
    """JSON-lines file of {instruction, plan, scene_summary, t}; `enabled=False` stores and returns nothing;
    `read_only=True` gives examples but never grows (a benchmark run's fixed memory regime)."""

    def __init__(
        self, path: str | Path, enabled: bool = True, encoder: TextEncoder | None = None, read_only: bool = False
    ):
        self.path = Path(path)
        self.enabled = enabled
        self.read_only = read_only
        self.encoder = encoder or SHARED_ENCODER
        self._lock = threading.Lock()

    def entries(self) -> list[dict]:
        if not self.path.exists():
            return []
        return [json.loads(line) for line in self.path.read_text().splitlines() if line.strip()]

    def add(self, instruction: str, plan_yaml: str, scene_summary: str = "", trial_id: str | None = None) -> None:
        """Call only for plans whose trial succeeded."""
        if not self.enabled or self.read_only:
            return
        with self._lock:
            self.path.parent.mkdir(parents=True, exist_ok=True)
            with self.path.open("a") as f:
                f.write(
                    json.dumps(
                        {
                            "instruction": instruction,
                            "plan": plan_yaml,
                            "scene_summary": scene_summary,
                            "t": time.time(),
                        }
                    )
                    + "\n"
                )

    def examples(self, instruction: str, k: int = 2) -> tuple[tuple[str, str], ...]:
        """The k stored (instruction, plan) pairs whose instructions are most similar to `instruction`."""
        return most_similar(self.entries() if self.enabled else [], instruction, self.encoder, k)


def most_similar(entries: list[dict], instruction: str, encoder: TextEncoder, k: int) -> tuple[tuple[str, str], ...]:
    if not entries:
        return ()
    uniq = {e["instruction"]: e for e in entries}  # newest plan per instruction
    texts = list(uniq)
    sims = encoder.encode(texts) @ encoder.encode([instruction])[0]
    order = np.argsort(-sims)[:k]
    return tuple((texts[i], uniq[texts[i]]["plan"]) for i in order)
