"""What every LLM backend shares: one call, a bounded retry on transient errors, one repair round trip for
plans that do not type-check, usage and cost, and a clean failure that keeps the raw text."""

from __future__ import annotations

import functools
import json
import time
from collections.abc import Callable
from dataclasses import asdict, dataclass, field

import cv2
import numpy as np

from ..grammar import validate
from ..grammar.loading import unfence
from .pricing import cost_usd
from .prompt import repair_prompt, system_prompt, user_prompt
from .protocol import PlanRequest, PlanResult, Usage


class TransientError(Exception):
    """Rate limit (429), server error (5xx) or timeout: worth retrying."""


class PlannerUnavailable(Exception):
    """A permanent error (auth, bad request, unknown model): reported, not retried."""


@dataclass(frozen=True)
class LLMSettings:
    model: str
    temperature: float = 0.3
    max_output_tokens: int = 2048
    timeout_s: float = 60.0
    max_retries: int = 2  # per call, for 429 / 5xx / timeouts
    backoff_s: float = 1.0  # doubled each retry
    repair_rounds: int = 1  # type-checker errors sent back to the model, then fail cleanly
    prices: dict[str, tuple[float, float]] | None = None


@dataclass
class Turn:
    """One exchange in the conversation: ('user', text) or ('model', text)."""

    role: str
    text: str


@dataclass
class CallOutcome:
    text: str
    usage: Usage
    raw: dict = field(default_factory=dict)


def png_bytes(image: np.ndarray) -> bytes:
    ok, buf = cv2.imencode(".png", cv2.cvtColor(image, cv2.COLOR_RGB2BGR))
    if not ok:
        raise ValueError("could not encode the annotated image as PNG")
    return buf.tobytes()


def plan_with_llm(
    backend: str,
    settings: LLMSettings,
    request: PlanRequest,
    call: Callable[[str, list[Turn], bytes | None], CallOutcome],
) -> PlanResult:
    """Drive `call(system, turns, image_png)` through retries and repair; `call` raises TransientError or
    PlannerUnavailable for failures."""
    t0 = time.perf_counter()
    system = system_prompt()
    turns = [Turn("user", user_prompt(request))]
    image = png_bytes(request.scene.image) if request.scene.image is not None else None
    total = Usage()
    texts: list[str] = []
    for round_ in range(settings.repair_rounds + 1):
        try:
            out = _with_retries(settings, functools.partial(call, system, list(turns), image))
        except (TransientError, PlannerUnavailable) as e:
            return PlanResult(
                backend,
                texts[-1] if texts else "",
                None,
                error=f"{backend} planner failed: {e}",
                usage=total,
                cost_usd=cost_usd(settings.model, total, settings.prices),
                latency_s=time.perf_counter() - t0,
                detail={"model": settings.model, "rounds": round_},
            )
        total = Usage(
            total.input_tokens + out.usage.input_tokens,
            total.output_tokens + out.usage.output_tokens,
            total.reasoning_tokens + out.usage.reasoning_tokens,
        )
        texts.append(out.text)
        plan, issues = validate(out.text)
        if plan is not None:
            return PlanResult(
                backend,
                out.text,
                plan,
                usage=total,
                cost_usd=cost_usd(settings.model, total, settings.prices),
                latency_s=time.perf_counter() - t0,
                detail={"model": settings.model, "rounds": round_ + 1, "attempts": texts},
            )
        turns += [Turn("model", out.text), Turn("user", repair_prompt([str(i) for i in issues]))]
    return PlanResult(
        backend,
        texts[-1],
        None,
        issues=issues,
        error=f"the {backend} plan did not type-check after {settings.repair_rounds} repair round(s)",
        usage=total,
        cost_usd=cost_usd(settings.model, total, settings.prices),
        latency_s=time.perf_counter() - t0,
        detail={"model": settings.model, "attempts": texts},
    )


def _with_retries(settings: LLMSettings, fn: Callable[[], CallOutcome]) -> CallOutcome:
    delay = settings.backoff_s
    for attempt in range(settings.max_retries + 1):
        try:
            return fn()
        except TransientError as e:
            if attempt == settings.max_retries:
                raise TransientError(f"{e} (gave up after {settings.max_retries + 1} attempts)") from None
            time.sleep(delay)
            delay *= 2
    raise AssertionError("unreachable")


VARIANTS_SYSTEM = (
    "You help an open-vocabulary object detector. For each object label, give {k} alternative short "
    "text prompts that describe the same object by colour, shape or material. Answer with a JSON object "
    "mapping each label to a list of {k} strings, and nothing else."
)


def variants_with_llm(
    settings: LLMSettings,
    labels: list[str],
    k: int,
    call: Callable[..., CallOutcome],
    record: Callable[[dict], None] | None = None,
) -> dict[str, list[str]]:
    """One call; labels the model skipped or mangled get no variants (perception then uses the label alone).
    `record` receives the call as the trace keeps it: prompt, response, usage, cost, latency."""
    schema = {
        "type": "object",
        "properties": {label: {"type": "array", "items": {"type": "string"}} for label in labels},
        "required": list(labels),
    }
    system, user = VARIANTS_SYSTEM.format(k=k), json.dumps(labels)
    t0 = time.perf_counter()
    out = _with_retries(settings, functools.partial(call, system, [Turn("user", user)], None, schema))
    if record is not None:
        record(
            {
                "kind": "prompt_synthesis",
                "model": settings.model,
                "prompt": f"{system}\n\n{user}",
                "response": out.text,
                "usage": asdict(out.usage),
                "cost_usd": cost_usd(settings.model, out.usage, settings.prices),
                "latency_s": round(time.perf_counter() - t0, 3),
            }
        )
    try:
        data = json.loads(unfence(out.text))
    except json.JSONDecodeError:
        return {label: [] for label in labels}
    result = {}
    for label in labels:
        raw = data.get(label, []) if isinstance(data, dict) else []
        result[label] = [v.strip() for v in raw if isinstance(v, str) and v.strip() and v.strip() != label][:k]
    return result
