"""The Planner protocol and what goes in and out of one planner call."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Protocol, runtime_checkable

import numpy as np

from ..grammar import Plan, PlanIssue
from ..perception import Keypoint


@dataclass(frozen=True)
class SceneView:
    """What perception saw, as the planner receives it: labels with keypoints, a text summary, an image.
    Never a ground-truth object dictionary."""

    keypoints: dict[str, Keypoint] = field(default_factory=dict)
    summary: str = ""
    image: np.ndarray | None = None  # annotated RGB, for multimodal planners
    # phrases perception could not single out, and why ("several match: 2", "none found"): what a planner needs
    # to ask which one rather than say it is absent
    unresolved: dict[str, str] = field(default_factory=dict)
    # the names of everything perception can list in the scene (segmenters that can list it: the sim oracle), so
    # a refusal can say what is there to name instead
    inventory: tuple[str, ...] = ()


@dataclass(frozen=True)
class PlanRequest:
    instruction: str
    scene: SceneView = SceneView()
    examples: tuple[tuple[str, str], ...] = ()  # (instruction, plan YAML) few-shot pairs from the plan library
    arms: dict[str, tuple[float, float]] = field(default_factory=dict)  # arm -> base (x, y) in the world, m;
    # with two arms a planner may write arm-tagged parallel branches
    tools: dict[str, str] = field(
        default_factory=dict
    )  # arm -> the tool fixed to it in place of fingers (a wiping pad)


@dataclass(frozen=True)
class Usage:
    input_tokens: int = 0
    output_tokens: int = 0
    reasoning_tokens: int = 0


@dataclass
class PlanResult:
    """One planner call: the raw text, the typed plan or the structured error, usage, cost and latency."""

    backend: str
    text: str
    plan: Plan | None
    issues: list[PlanIssue] = field(default_factory=list)
    error: str = ""  # what went wrong in words (the planner's own explanation, or the type-checker's summary)
    usage: Usage = Usage()
    cost_usd: float = 0.0
    latency_s: float = 0.0
    detail: dict[str, Any] = field(default_factory=dict)

    @property
    def ok(self) -> bool:
        return self.plan is not None


@runtime_checkable
class Planner(Protocol):
    name: str

    def plan(self, request: PlanRequest) -> PlanResult: ...
