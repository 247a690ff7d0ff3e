"""Request and response models of the REST API (pydantic; documented in OpenAPI at /docs)."""

from __future__ import annotations

from typing import Annotated, Any, Literal

from pydantic import BaseModel, ConfigDict, Field, field_validator

from spark_core import (
    ALL_EMBODIMENTS,
    DEFAULT_SEGMENTER,
    PLANNERS,
    PROTOCOLS,
    SEGMENTERS,
    CatalogError,
    check_embodiment,
    check_planner,
    check_segmenter,
)

from .text import VISIBLE, VISIBLE_PLAN, Visible

MAX_SEED = 2**31 - 1  # a seed the simulators' RNGs take (np.random, robosuite, LIBERO init-state index)
MAX_OFFSET = 10**9  # list paging: far past any store, well inside SQLite's 64-bit integers
MAX_ID = 256  # trial ids: "{batch}-{n}-{task}-{seed}" at most ~170 characters
MAX_NAME = 128  # task, suite and backend names


MODEL_NAME = (
    "an LLM planner's model (default: the planner's own); letters, digits, '.', '-' and '_', plus a 'models/' or "
    "'tunedModels/' prefix for gemini, '/' between parts and ':' before a tag for openai (Qwen/Qwen2.5-VL-7B, "
    "qwen3:8b); any other character is a 422 naming it"
)
NodePath = Annotated[str, Field(max_length=256), VISIBLE]  # e.g. tree.children[2].children[0]


def _enum(names: Any) -> dict[str, Any]:
    return {"enum": list(names)}


class TrialCreate(BaseModel):
    model_config = ConfigDict(extra="forbid")  # a misspelt or retired field (base_url) is an error, not ignored
    # booleans are strict like the seed: "yes" or 1 is not a switch someone meant to flip

    task: Visible = Field(max_length=MAX_NAME, description="task whose scene to run in (GET /api/catalog lists them)")
    instruction: Annotated[str, Field(max_length=2000), VISIBLE] | None = Field(
        None,
        description="default: the task's own instruction; the reference planner runs the task's own plan and "
        "refuses any other (choose rules or an LLM planner)",
    )
    planner: str = Field("reference", json_schema_extra=_enum(PLANNERS))
    segmenter: str = Field(
        DEFAULT_SEGMENTER,
        json_schema_extra=_enum(SEGMENTERS),
        description="perception backend (default: the camera-only `learned`; `sim` is the oracle); GET /api/catalog "
        "says which are privileged",
    )
    seed: int = Field(0, ge=0, le=MAX_SEED, strict=True)
    breakpoints: list[NodePath] = Field(default_factory=list, max_length=200, description="node paths to pause before")
    model: Annotated[str, Field(max_length=200), VISIBLE] | None = Field(None, description=MODEL_NAME)
    endpoint: Annotated[str, Field(max_length=100), VISIBLE] | None = Field(
        None, description="an LLM endpoint the operator configured (GET /api/catalog lists them)"
    )
    plan: Annotated[str, Field(max_length=256 * 1024), VISIBLE_PLAN] | None = Field(
        None, description="a plan to run as given (the planner is not called)"
    )
    start_paused: bool = Field(False, strict=True, description="pause before the first primitive")
    capture: bool = Field(
        False, strict=True, description="record training-data frames (agentview + wrist video at 10 fps)"
    )
    embodiment: str | None = Field(
        None, json_schema_extra=_enum(ALL_EMBODIMENTS), description="robot set-up (default: the task's own)"
    )
    time_limit_s: float | None = Field(None, gt=0, le=3600, description="simulated seconds (default: the task's own)")
    pacing: float | None = Field(None, ge=0.01, le=100, description="x real time (default: as fast as possible)")
    recovery: bool = Field(True, strict=True, description="recovery tiers 1-2 (2 retries per node)")
    adaptive: bool = Field(True, strict=True, description="adaptive prompts (label + 3 variants)")
    protocol: str | None = Field(
        None,
        json_schema_extra=_enum(PROTOCOLS),
        description="a named evaluation configuration of the paper (sets adaptive prompts and cameras; refused "
        "with a privileged segmenter or a given plan; GET /api/catalog lists them)",
    )

    @field_validator("planner")
    @classmethod
    def _planner(cls, v: str) -> str:
        return _catalog(check_planner, v)

    @field_validator("segmenter")
    @classmethod
    def _segmenter(cls, v: str) -> str:
        return _catalog(check_segmenter, v)

    @field_validator("embodiment")
    @classmethod
    def _embodiment(cls, v: str | None) -> str | None:
        return None if v is None else _catalog(check_embodiment, v)


def _catalog(check: Any, value: str) -> str:
    try:
        return check(value)
    except CatalogError as e:
        raise ValueError(str(e)) from None


class TrialCreated(BaseModel):
    id: str
    status: str


class TrialPage(BaseModel):
    total: int
    limit: int
    offset: int
    items: list[dict[str, Any]]


class TrialDeleted(BaseModel):
    id: str
    purged: bool  # True: gone for good, files included
    restore_until: str | None  # ISO time until which POST /api/trials/{id}/restore undoes the delete


class TrialRestored(BaseModel):
    id: str
    restored: bool


class Control(BaseModel):
    action: Literal["pause", "resume", "step", "abort", "breakpoints"]
    breakpoints: list[NodePath] | None = Field(None, max_length=200)


class PlanText(BaseModel):
    text: Annotated[str, Field(max_length=256 * 1024), VISIBLE_PLAN]
    embodiment: str | None = Field(
        None,
        json_schema_extra=_enum(ALL_EMBODIMENTS),
        description="also check the plan's arm tags against this robot set-up's arms (GET /api/catalog lists them)",
    )

    @field_validator("embodiment")
    @classmethod
    def _embodiment(cls, v: str | None) -> str | None:
        return None if v is None else _catalog(check_embodiment, v)


class PlanValidation(BaseModel):
    ok: bool
    plan: dict | None = None
    canonical_yaml: str | None = None
    errors: list[dict[str, str]] = Field(default_factory=list)
