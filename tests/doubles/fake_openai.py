"""A loopback server that answers like OpenAI's chat completions (`/v1/chat/completions`): its JSON shapes and
usage (reasoning tokens inside completion_tokens), its error bodies and headers (429 with retry-after and
x-request-id), its refusal of a request without a bearer key or with a malformed payload, and finish_reason
"length" when the answer exceeds max_tokens. Test-only."""

from __future__ import annotations

from typing import Any

from tests.doubles.fake_vendor import FakeVendor, approx_tokens

ERRORS = {
    400: ("invalid_request_error", None, "Invalid request."),
    401: ("invalid_request_error", "invalid_api_key", "Incorrect API key provided."),
    429: ("requests", "rate_limit_exceeded", "Rate limit reached for requests. Please try again in 1s."),
    500: ("server_error", None, "The server had an error while processing your request. Sorry about that!"),
    503: ("server_error", None, "The engine is currently overloaded, please try again later."),
}


class FakeOpenAI(FakeVendor):
    def refuse(self, path: str, headers: dict[str, str], body: Any) -> tuple[int, dict] | None:
        if path.split("?")[0] != "/v1/chat/completions":
            return 404, self._error("invalid_request_error", "unknown_url", f"Unknown request URL: POST {path}.")
        if not headers.get("authorization", "").startswith("Bearer "):
            return 401, self._error("invalid_request_error", None, "You didn't provide an API key.")
        if not isinstance(body, dict) or not body.get("model") or not body.get("messages"):
            return 400, self._error("invalid_request_error", None, "'messages' and 'model' are required.")
        fmt = body.get("response_format")
        if fmt is not None and fmt.get("type") == "json_schema":
            spec = fmt.get("json_schema") or {}
            if not spec.get("name") or "schema" not in spec:
                return 400, self._error(
                    "invalid_request_error", None, "Missing required parameter: 'response_format.json_schema.name'."
                )
        return None

    def success(self, text: str, usage: tuple[int, int, int], body: dict) -> dict:
        prompt, out, thoughts = usage
        limit = body.get("max_tokens") or body.get("max_completion_tokens")
        finish = "stop"
        if limit is not None and approx_tokens(text) > limit:  # the vendor cuts the answer at the limit
            text, out, finish = text[: limit * 4], limit, "length"
        return {
            "id": f"chatcmpl-fake{len(self.requests)}",
            "object": "chat.completion",
            "created": 1764000000,
            "model": body["model"],
            "choices": [
                {
                    "index": 0,
                    "message": {"role": "assistant", "content": text, "refusal": None, "annotations": []},
                    "logprobs": None,
                    "finish_reason": finish,
                }
            ],
            "usage": {
                "prompt_tokens": prompt,
                "completion_tokens": out + thoughts,
                "total_tokens": prompt + out + thoughts,
                "prompt_tokens_details": {"cached_tokens": 0, "audio_tokens": 0},
                "completion_tokens_details": {
                    "reasoning_tokens": thoughts,
                    "audio_tokens": 0,
                    "accepted_prediction_tokens": 0,
                    "rejected_prediction_tokens": 0,
                },
            },
            "service_tier": "default",
            "system_fingerprint": "fp_fake",
        }

    def error(self, code: int, retry_after_s: float = 1.0) -> dict:
        kind, err_code, message = ERRORS.get(code, ("server_error", None, f"fake error {code}"))
        return self._error(kind, err_code, message)

    def error_headers(self, code: int, retry_after_s: float = 1.0) -> dict[str, str]:
        headers = {"x-request-id": f"req_fake{len(self.requests)}"}
        if code == 429:
            headers |= {"retry-after": f"{retry_after_s:g}", "x-ratelimit-remaining-requests": "0"}
        return headers

    @staticmethod
    def _error(kind: str, code: str | None, message: str) -> dict:
        return {"error": {"message": message, "type": kind, "param": None, "code": code}}
