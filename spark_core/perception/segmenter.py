"""The Segmenter protocol: text prompts in, masks with scores out."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Protocol, runtime_checkable

from .detection import Detection
from .frame import CameraFrame


@runtime_checkable
class Segmenter(Protocol):
    name: str
    privileged: bool  # True when masks come from simulator ground truth

    def segment(self, frame: CameraFrame, prompts: Sequence[str]) -> list[Detection]:
        """Every detection for every prompt (zero, one or several per prompt), label = prompt."""
        ...
