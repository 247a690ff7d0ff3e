"""`gemini` planner: the google-genai SDK, JSON output constrained by the plan schema, image attached."""

from __future__ import annotations

import os

from .llm import CallOutcome, LLMSettings, PlannerUnavailable, TransientError, Turn
from .llm_planner import LLMPlanner
from .prompt import response_schema
from .protocol import Usage

DEFAULT_MODEL = "gemini-3.1-pro-preview"


class GeminiPlanner(LLMPlanner):
    name = "gemini"

    def __init__(
        self,
        model: str = DEFAULT_MODEL,
        api_key: str | None = None,
        base_url: str | None = None,
        settings: LLMSettings | None = None,
    ):
        from google import genai
        from google.genai import types

        # The environment's key goes to Google's own endpoint only: any other URL needs its key given explicitly
        # (a named endpoint in spark.yaml), so a caller-chosen URL never receives it.
        key = api_key or (None if base_url else os.environ.get("GEMINI_API_KEY") or os.environ.get("GOOGLE_API_KEY"))
        if not key:
            raise PlannerUnavailable(
                "the gemini planner needs an API key: set GEMINI_API_KEY (or GOOGLE_API_KEY)"
                if not base_url
                else f"no key for {base_url}: configure it as a named endpoint (spark.yaml endpoints:) with api_key_env"
            )
        self.calls: list[dict] = []  # the prompt-synthesis calls made, as the trace keeps them
        self.settings = settings or LLMSettings(model)
        self.types = types
        self.errors = genai.errors
        http = types.HttpOptions(
            base_url=base_url,
            timeout=int(self.settings.timeout_s * 1000),
            retry_options=types.HttpRetryOptions(attempts=1),
        )  # retries are ours: bounded, reported
        self.client = genai.Client(api_key=key, http_options=http)

    def _call(
        self,
        system: str,
        turns: list[Turn],
        image: bytes | None,
        schema: dict | None = None,
        max_output_tokens: int | None = None,
    ) -> CallOutcome:
        t = self.types
        contents = []
        for i, turn in enumerate(turns):
            parts = [t.Part.from_text(text=turn.text)]
            if i == 0 and image is not None:
                parts.append(t.Part.from_bytes(data=image, mime_type="image/png"))
            contents.append(t.Content(role="user" if turn.role == "user" else "model", parts=parts))
        config = t.GenerateContentConfig(
            system_instruction=system,
            temperature=self.settings.temperature,
            max_output_tokens=max_output_tokens or self.settings.max_output_tokens,
            response_mime_type="application/json",
            response_json_schema=schema or response_schema(),
        )
        try:
            resp = self.client.models.generate_content(model=self.settings.model, contents=contents, config=config)
        except self.errors.APIError as e:
            if e.code == 429 or (e.code or 0) >= 500:
                raise TransientError(
                    f"HTTP {e.code} from Gemini: {e.message or e.status}", _retry_delay_s(e.details)
                ) from None
            raise PlannerUnavailable(f"HTTP {e.code} from Gemini: {e.message or e.status}") from None
        except ValueError as e:  # a 200 whose body is not JSON (a proxy's error page): report, do not crash
            raise PlannerUnavailable(f"Gemini answered with a body that is not JSON ({e})") from None
        except Exception as e:
            if "timeout" in type(e).__name__.lower() or "timed out" in str(e).lower():
                raise TransientError(f"Gemini did not answer within {self.settings.timeout_s:g} s") from None
            if "connect" in type(e).__name__.lower():
                raise TransientError(f"cannot reach Gemini: {e}") from None
            raise
        meta = resp.usage_metadata
        usage = Usage(
            getattr(meta, "prompt_token_count", 0) or 0,
            getattr(meta, "candidates_token_count", 0) or 0,
            getattr(meta, "thoughts_token_count", 0) or 0,
        )
        text = resp.text or ""
        if not text:  # a blocked prompt or an answer stopped for safety: say why instead of "repairing" nothing
            feedback = getattr(resp, "prompt_feedback", None)
            blocked = getattr(feedback, "block_reason", None)
            finish = getattr(resp.candidates[0], "finish_reason", None) if resp.candidates else None
            raise PlannerUnavailable(
                "Gemini gave no answer: "
                + (f"the prompt was blocked ({_name(blocked)})" if blocked else f"finish reason {_name(finish)}")
            )
        return CallOutcome(text, usage)


def _name(value: object) -> str:
    return str(getattr(value, "value", value))


def _retry_delay_s(body: object) -> float | None:
    """Gemini's google.rpc.RetryInfo hint ("retryDelay": "30s") in an error body, in seconds."""
    error = body.get("error", {}) if isinstance(body, dict) else {}
    for detail in error.get("details") or [] if isinstance(error, dict) else []:
        if isinstance(detail, dict) and str(detail.get("@type", "")).endswith("google.rpc.RetryInfo"):
            try:
                return float(str(detail.get("retryDelay", "")).rstrip("s"))
            except ValueError:
                return None
    return None
