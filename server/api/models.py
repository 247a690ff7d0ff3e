"""Request and response models of the REST API (pydantic; documented in OpenAPI at /docs)."""

from __future__ import annotations

from typing import Any, Literal

from pydantic import BaseModel, Field


class TrialCreate(BaseModel):
    task: str = Field(description="builtin task whose scene to run in")
    instruction: str | None = Field(None, max_length=2000, description="default: the task's own instruction")
    planner: Literal["reference", "rules", "gemini", "openai"] = "reference"
    resolver: Literal["privileged", "sim", "sim-noisy"] = "sim"
    seed: int = Field(0, ge=0, le=1_000_000)
    breakpoints: list[str] = Field(default_factory=list, max_length=200, description="node paths to pause before")
    model: str | None = None
    base_url: str | None = None
    start_paused: bool = Field(False, description="pause before the first primitive")
    capture: bool = Field(False, description="record training-data frames (agentview + wrist video at 10 fps)")
    embodiment: Literal["panda", "ur10", "bimanual"] | None = Field(None, description="robot set-up (default: the task's own)")


class TrialCreated(BaseModel):
    id: str
    status: str


class TrialPage(BaseModel):
    total: int
    limit: int
    offset: int
    items: list[dict[str, Any]]


class Control(BaseModel):
    action: Literal["pause", "resume", "step", "abort", "breakpoints"]
    breakpoints: list[str] | None = Field(None, max_length=200)


class PlanText(BaseModel):
    text: str = Field(max_length=256 * 1024)


class PlanValidation(BaseModel):
    ok: bool
    plan: dict | None = None
    canonical_yaml: str | None = None
    errors: list[dict[str, str]] = Field(default_factory=list)
