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

MAX_RETRY_AFTER_S = 60.0  # a vendor's retry hint is honoured up to this; longer waits are reported, not slept


class TransientError(Exception):
    """Rate limit (429), server error (5xx) or timeout: worth retrying. `retry_after_s`: how long the vendor
    asked us to wait (OpenAI's retry-after header, Gemini's RetryInfo), when it said."""

    def __init__(self, message: str, retry_after_s: float | None = None):
        super().__init__(message)
        self.retry_after_s = retry_after_s


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
                detail={"model": settings.model, "rounds": round_, "prompt": turns[0].text},
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
                detail={"model": settings.model, "rounds": round_ + 1, "attempts": texts, "prompt": turns[0].text},
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
        detail={"model": settings.model, "attempts": texts, "prompt": turns[0].text},
    )


def _with_retries(settings: LLMSettings, fn: Callable[[], CallOutcome]) -> CallOutcome:
    delay = settings.backoff_s
    for attempt in range(settings.max_retries + 1):
        try:
            return fn()
        except TransientError as e:
            hint = e.retry_after_s or 0.0
            if attempt == settings.max_retries or hint > MAX_RETRY_AFTER_S:
                why = f"gave up after {attempt + 1} attempts" + (
                    f"; the vendor asked to wait {hint:g} s" if hint > MAX_RETRY_AFTER_S else ""
                )
                raise TransientError(f"{e} ({why})") from None
            time.sleep(max(delay, hint))  # never sooner than the vendor asked
            delay *= 2
    raise AssertionError("unreachable")


# The paper's prompt-synthesis call: image + task language -> the objects to detect and, in the adaptive
# configuration, three alternative colour-and-shape prompts per object; a JSON list, at most 512 output tokens.
SYNTHESIS_MAX_OUTPUT_TOKENS = 512
MAX_PHRASE_WORDS = 6  # SAM3 reads short noun phrases (its CLIP text encoder takes 32 tokens)
MAX_PHRASE_CHARS = 48

SYNTHESIS_SYSTEM = (
    "You prepare the prompts of an open-vocabulary object detector (SAM3) for a robot. From the task and the "
    "camera image, list every object the robot must find to do the task, each as a short noun phrase (at most "
    f"{MAX_PHRASE_WORDS} words) the way the task names it."
)
SYNTHESIS_VARIANTS = (
    " For each object also give {k} alternative short prompts that describe the same object by its colour and "
    "shape as seen in the image (never the object's own phrase again)."
)
SYNTHESIS_ANSWER = ' Answer with a JSON list of {{"object": <phrase>{prompts}}} entries, and nothing else.'


@dataclass(frozen=True)
class Synthesis:
    """What the prompt-synthesis call gave, after filtering: objects to detect, alternative prompts per object,
    and every phrase refused with the reason (empty, too long, not a string, duplicate)."""

    objects: tuple[str, ...] = ()
    variants: dict[str, list[str]] = field(default_factory=dict)
    dropped: tuple[str, ...] = ()


def synthesis_schema(k: int) -> dict:
    """The JSON list the synthesis call must answer with (`prompts` only when k > 0)."""
    item: dict = {"type": "object", "properties": {"object": {"type": "string"}}, "required": ["object"]}
    if k:
        item["properties"]["prompts"] = {"type": "array", "items": {"type": "string"}}
        item["required"].append("prompts")
    return {"type": "array", "items": item}


def synthesise_with_llm(
    settings: LLMSettings,
    instruction: str,
    image_png: bytes | None,
    k: int,
    call: Callable[..., CallOutcome],
    record: Callable[[dict], None] | None = None,
) -> Synthesis:
    """One call (retried on 429/5xx/timeouts like every call; raises TransientError or PlannerUnavailable when
    it fails). `k` = 0: objects only (the fair and bddl configurations). `record` receives the call as the trace
    keeps it: prompt, whether the image went with it, response, usage, cost, latency, what was dropped."""
    system = SYNTHESIS_SYSTEM + (SYNTHESIS_VARIANTS.format(k=k) if k else "")
    system += SYNTHESIS_ANSWER.format(prompts=f', "prompts": [{k} strings]' if k else "")
    user = f"Task: {instruction.strip()}"
    t0 = time.perf_counter()
    turns = [Turn("user", user)]
    out = _with_retries(
        settings, functools.partial(call, system, turns, image_png, synthesis_schema(k), SYNTHESIS_MAX_OUTPUT_TOKENS)
    )
    result = parse_synthesis(out.text, k)
    if record is not None:
        record(
            _synthesis_record(settings, system, user, out, result, t0)
            | {
                "image_attached": image_png is not None,
                "max_output_tokens": SYNTHESIS_MAX_OUTPUT_TOKENS,
                "objects": list(result.objects),
                "variants": result.variants,
            }
        )
    return result


def _synthesis_record(
    settings: LLMSettings, system: str, user: str, out: CallOutcome, result: Synthesis, t0: float
) -> dict:
    """A prompt-synthesis or variant call as the trace keeps it (`t0`: perf_counter at the call's start)."""
    return {
        "kind": "prompt_synthesis",
        "model": settings.model,
        "prompt": f"{system}\n\n{user}",
        "response": out.text,
        "dropped": list(result.dropped),
        "usage": asdict(out.usage),
        "cost_usd": cost_usd(settings.model, out.usage, settings.prices),
        "latency_s": round(time.perf_counter() - t0, 3),
    }


def parse_synthesis(text: str, k: int) -> Synthesis:
    """The model's answer as a Synthesis. Accepts the JSON list asked for, or an object mapping each object to
    its prompts; anything else gives no objects (perception then looks for the instruction's own phrases)."""
    try:
        data = json.loads(unfence(text))
    except (json.JSONDecodeError, TypeError):
        return Synthesis(dropped=(f"response: not JSON ({text[:60]!r})",))
    if isinstance(data, dict):
        data = [{"object": name, "prompts": prompts} for name, prompts in data.items()]
    if not isinstance(data, list):
        return Synthesis(dropped=(f"response: expected a JSON list, got {type(data).__name__}",))
    dropped: list[str] = []
    objects: dict[str, list[str]] = {}
    for i, entry in enumerate(data):
        name = entry.get("object") if isinstance(entry, dict) else entry
        phrase, why = _phrase(name)
        if phrase is None or phrase.lower() in (o.lower() for o in objects):
            dropped.append(f"[{i}].object: {why or 'duplicate'}")
            continue
        prompts: list[str] = []
        raw = entry.get("prompts", []) if isinstance(entry, dict) else []
        if not isinstance(raw, list):
            dropped.append(f"[{i}].prompts: expected a list, got {type(raw).__name__}")
            raw = []
        for j, value in enumerate(raw):
            p, why = _phrase(value)
            seen = {phrase.lower(), *(q.lower() for q in prompts)}
            if p is None or p.lower() in seen:
                dropped.append(f"[{i}].prompts[{j}]: {why or 'duplicate'}")
            elif len(prompts) < k:
                prompts.append(p)
        objects[phrase] = prompts
    return Synthesis(tuple(objects), {o: v for o, v in objects.items() if v}, tuple(dropped))


def _phrase(value: object) -> tuple[str | None, str]:
    """A usable detector prompt, or None and why not."""
    if not isinstance(value, str):
        return None, f"not a string ({type(value).__name__})"
    phrase = " ".join(value.split())
    if not phrase:
        return None, "empty"
    if len(phrase) > MAX_PHRASE_CHARS or len(phrase.split()) > MAX_PHRASE_WORDS:
        return None, f"too long for the detector ({len(phrase.split())} words, {len(phrase)} characters)"
    return phrase, ""


def variants_with_llm(
    settings: LLMSettings,
    labels: list[str],
    k: int,
    call: Callable[..., CallOutcome],
    record: Callable[[dict], None] | None = None,
) -> dict[str, list[str]]:
    """Alternative prompts for labels already known (no image, no object discovery): the synthesis call's
    filtering applied to labels the model skipped or mangled, which get no variants."""
    schema = {
        "type": "object",
        "properties": {label: {"type": "array", "items": {"type": "string"}} for label in labels},
        "required": list(labels),
    }
    system = SYNTHESIS_VARIANTS.format(k=k).strip() + " Answer with a JSON object mapping each object to its list."
    user = json.dumps(labels)
    t0 = time.perf_counter()
    out = _with_retries(
        settings, functools.partial(call, system, [Turn("user", user)], None, schema, SYNTHESIS_MAX_OUTPUT_TOKENS)
    )
    result = parse_synthesis(out.text, k)
    if record is not None:
        record(_synthesis_record(settings, system, user, out, result, t0))
    return {label: result.variants.get(label, []) for label in labels}
