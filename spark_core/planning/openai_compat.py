"""`openai` planner: OpenAI-compatible chat completions (OpenAI, Ollama, vLLM, llama.cpp server) with a JSON
schema response format and the annotated image as a data URL."""

from __future__ import annotations

import base64
import os

from .llm import CallOutcome, LLMSettings, PlannerUnavailable, TransientError, Turn
from .llm_planner import LLMPlanner
from .prompt import response_schema
from .protocol import Usage


class OpenAIPlanner(LLMPlanner):
    name = "openai"

    def __init__(
        self,
        model: str,
        base_url: str | None = None,
        api_key: str | None = None,
        settings: LLMSettings | None = None,
        shown_as: str | None = None,
    ):
        """`shown_as`: how error messages name the server (a named endpoint's URL is the operator's, not the
        caller's to see); default: its URL."""
        import openai

        # The environment's key goes to OpenAI's own endpoint only; any other URL (a local server) gets none
        # unless its key is given explicitly (a named endpoint in spark.yaml).
        key = api_key or ("not-needed" if base_url else os.environ.get("OPENAI_API_KEY"))
        if key is None:
            raise PlannerUnavailable(
                "the openai planner needs OPENAI_API_KEY, or --base-url of a local "
                "OpenAI-compatible server (Ollama, vLLM, llama.cpp)"
            )
        self.calls: list[dict] = []  # the prompt-synthesis calls made, as the trace keeps them
        self.settings = settings or LLMSettings(model)
        self.openai = openai
        self.client = openai.OpenAI(api_key=key, base_url=base_url, timeout=self.settings.timeout_s, max_retries=0)
        self.where = shown_as or str(self.client.base_url)

    def _call(
        self,
        system: str,
        turns: list[Turn],
        image: bytes | None,
        schema: dict | None = None,
        max_output_tokens: int | None = None,
    ) -> CallOutcome:
        messages: list[dict] = [{"role": "system", "content": system}]
        for i, turn in enumerate(turns):
            content: object = turn.text
            if i == 0 and image is not None:
                url = "data:image/png;base64," + base64.b64encode(image).decode()
                content = [{"type": "text", "text": turn.text}, {"type": "image_url", "image_url": {"url": url}}]
            messages.append({"role": "user" if turn.role == "user" else "assistant", "content": content})
        o = self.openai
        try:
            resp = self.client.chat.completions.create(  # type: ignore[call-overload]  # plain dicts, typed by the SDK as TypedDicts
                model=self.settings.model,
                messages=messages,
                temperature=self.settings.temperature,
                max_tokens=max_output_tokens or self.settings.max_output_tokens,
                response_format={
                    "type": "json_schema",
                    "json_schema": {"name": "spark_output", "schema": schema or response_schema()},
                },
            )
        except (o.RateLimitError, o.InternalServerError) as e:
            raise TransientError(f"HTTP {e.status_code} from {self.where}: {_message(e)}", _retry_after_s(e)) from None
        except o.APITimeoutError:
            raise TransientError(f"{self.where} did not answer within {self.settings.timeout_s:g} s") from None
        except o.APIConnectionError as e:
            raise TransientError(f"cannot reach {self.where}: {e}") from None
        except o.APIStatusError as e:
            raise PlannerUnavailable(f"HTTP {e.status_code} from {self.where}: {_message(e)}") from None
        if isinstance(resp, str) or not getattr(resp, "choices", None):  # a body that is not a completion
            raise PlannerUnavailable(f"{self.where} answered with a body that is not JSON: {str(resp)[:80]!r}")
        u = resp.usage
        reasoning = getattr(getattr(u, "completion_tokens_details", None), "reasoning_tokens", 0) or 0 if u else 0
        usage = Usage(u.prompt_tokens if u else 0, (u.completion_tokens - reasoning) if u else 0, reasoning)
        message = resp.choices[0].message
        refusal = getattr(message, "refusal", None)
        if refusal and not message.content:  # the model declined: say so instead of "repairing" nothing
            raise PlannerUnavailable(f"the model refused: {refusal}")
        return CallOutcome(message.content or "", usage)


def _message(e) -> str:
    body = getattr(e, "body", None)
    if isinstance(body, dict):
        err = body.get("error", body)
        return str(err.get("message", err)) if isinstance(err, dict) else str(err)
    return str(e)


def _retry_after_s(e) -> float | None:
    """The retry-after header of a 429/5xx (seconds), when the server sent one."""
    try:
        return float(e.response.headers.get("retry-after"))
    except (AttributeError, TypeError, ValueError):
        return None
