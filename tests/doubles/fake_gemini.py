"""A loopback server that answers like the Gemini API (`models/{model}:generateContent`, v1 or v1beta): its
JSON shapes, usageMetadata, error bodies (google.rpc.Status with RetryInfo on 429), its refusal of a request
without a key or with a malformed payload, and finishReason MAX_TOKENS when the answer exceeds maxOutputTokens.
Test-only."""

from __future__ import annotations

import re
from typing import Any

from tests.doubles.fake_vendor import FakeVendor, approx_tokens

PATH = re.compile(r"^/v1(beta)?/models/(?P<model>[^/:]+):generateContent$")
TOP_LEVEL = {"contents", "systemInstruction", "generationConfig", "safetySettings", "tools", "toolConfig"}
STATUS = {
    400: "INVALID_ARGUMENT",
    403: "PERMISSION_DENIED",
    404: "NOT_FOUND",
    429: "RESOURCE_EXHAUSTED",
    500: "INTERNAL",
    503: "UNAVAILABLE",
    504: "DEADLINE_EXCEEDED",
}
MESSAGES = {
    429: "You exceeded your current quota, please check your plan and billing details.",
    500: "An internal error has occurred. Please retry or report in https://developers.generativeai.google/guide/troubleshooting",
    503: "The model is overloaded. Please try again later.",
}


class FakeGemini(FakeVendor):
    def refuse(self, path: str, headers: dict[str, str], body: Any) -> tuple[int, dict] | None:
        if not PATH.match(path.split("?")[0]):
            return 404, self._status(404, f"Requested entity was not found: {path}")
        if not headers.get("x-goog-api-key"):
            return 403, self._status(
                403,
                "Method doesn't allow unregistered callers (callers without established identity). "
                "Please use API Key or other form of API consumer identity to call this API.",
            )
        if not isinstance(body, dict):
            return 400, self._status(400, "Invalid JSON payload received.")
        unknown = sorted(set(body) - TOP_LEVEL)
        if unknown:
            return 400, self._status(
                400, f'Invalid JSON payload received. Unknown name "{unknown[0]}": Cannot find field.'
            )
        contents = body.get("contents")
        if not contents or any(c.get("role") not in ("user", "model") or not c.get("parts") for c in contents):
            return 400, self._status(400, "* GenerateContentRequest.contents: contents is not specified")
        config = body.get("generationConfig", {})
        if "responseJsonSchema" in config and config.get("responseMimeType") != "application/json":
            return 400, self._status(400, "responseJsonSchema requires responseMimeType application/json")
        if not 1 <= config.get("maxOutputTokens", 8192) <= 65536:
            return 400, self._status(400, "max_output_tokens must be in [1, 65536]")
        return None

    def success(self, text: str, usage: tuple[int, int, int], body: dict) -> dict:
        prompt, out, thoughts = usage
        limit = body.get("generationConfig", {}).get("maxOutputTokens")
        finish = "STOP"
        if limit is not None and approx_tokens(text) > limit:  # the vendor cuts the answer at the limit
            text, out, finish = text[: limit * 4], limit, "MAX_TOKENS"
        images = sum(1 for c in body["contents"] for p in c["parts"] if "inlineData" in p)
        return {
            "candidates": [
                {"content": {"parts": [{"text": text}], "role": "model"}, "finishReason": finish, "index": 0}
            ],
            "usageMetadata": {
                "promptTokenCount": prompt,
                "candidatesTokenCount": out,
                "totalTokenCount": prompt + out + thoughts,
                "promptTokensDetails": [{"modality": "TEXT", "tokenCount": prompt - 258 * images}]
                + ([{"modality": "IMAGE", "tokenCount": 258 * images}] if images else []),
                "thoughtsTokenCount": thoughts,
            },
            "modelVersion": PATH.match(self.requests[-1]["path"].split("?")[0])["model"],
            "responseId": f"fake-{len(self.requests)}",
        }

    def error(self, code: int, retry_after_s: float = 1.0) -> dict:
        status = self._status(code, MESSAGES.get(code, f"fake error {code}"))
        if code == 429:
            status["error"]["details"] = [
                {"@type": "type.googleapis.com/google.rpc.RetryInfo", "retryDelay": f"{retry_after_s:g}s"},
            ]
        return status

    @staticmethod
    def _status(code: int, message: str) -> dict:
        return {"error": {"code": code, "message": message, "status": STATUS.get(code, "UNKNOWN")}}
