"""A scripted fake LLM server on 127.0.0.1 that speaks the Gemini (generateContent) and OpenAI (chat
completions) wire formats, recording every request. Test-only."""

from __future__ import annotations

import contextlib
import json
import threading
import time
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer


class FakeLLM:
    """`script` is consumed one entry per request: ("ok", text[, usage]) | ("status", code) | ("sleep", s, text)."""

    def __init__(self, flavour: str):
        assert flavour in ("gemini", "openai")
        self.flavour = flavour
        self.script: list[tuple] = []
        self.requests: list[dict] = []
        fake = self

        class Handler(BaseHTTPRequestHandler):
            def log_message(self, *args):  # keep test output clean
                pass

            def do_POST(self):
                body = json.loads(self.rfile.read(int(self.headers.get("Content-Length", 0))) or b"{}")
                fake.requests.append({"path": self.path, "headers": dict(self.headers), "body": body})
                entry = fake.script.pop(0) if fake.script else ("status", 500)
                if entry[0] == "sleep":
                    time.sleep(entry[1])
                    entry = ("ok", entry[2])
                if entry[0] == "status":
                    payload = fake.error(entry[1])
                    self._send(entry[1], payload)
                else:
                    usage = entry[2] if len(entry) > 2 else (120, 40, 8)
                    self._send(200, fake.success(entry[1], usage))

            def _send(self, code, payload):
                data = json.dumps(payload).encode()
                self.send_response(code)
                self.send_header("Content-Type", "application/json")
                self.send_header("Content-Length", str(len(data)))
                self.end_headers()
                with contextlib.suppress(BrokenPipeError):
                    self.wfile.write(data)

        self.server = ThreadingHTTPServer(("127.0.0.1", 0), Handler)
        self.thread = threading.Thread(target=self.server.serve_forever, daemon=True)

    @property
    def url(self) -> str:
        return f"http://127.0.0.1:{self.server.server_address[1]}"

    def __enter__(self):
        self.thread.start()
        return self

    def __exit__(self, *exc):
        self.server.shutdown()
        self.server.server_close()

    def success(self, text: str, usage: tuple[int, int, int]) -> dict:
        prompt, out, thoughts = usage
        if self.flavour == "gemini":
            return {
                "candidates": [{"content": {"role": "model", "parts": [{"text": text}]}, "finishReason": "STOP"}],
                "usageMetadata": {
                    "promptTokenCount": prompt,
                    "candidatesTokenCount": out,
                    "thoughtsTokenCount": thoughts,
                    "totalTokenCount": prompt + out + thoughts,
                },
                "modelVersion": "fake",
            }
        return {
            "id": "chatcmpl-fake",
            "object": "chat.completion",
            "created": 0,
            "model": "fake",
            "choices": [{"index": 0, "message": {"role": "assistant", "content": text}, "finish_reason": "stop"}],
            "usage": {
                "prompt_tokens": prompt,
                "completion_tokens": out + thoughts,
                "total_tokens": prompt + out + thoughts,
                "completion_tokens_details": {"reasoning_tokens": thoughts},
            },
        }

    def error(self, code: int) -> dict:
        if self.flavour == "gemini":
            status = {429: "RESOURCE_EXHAUSTED", 500: "INTERNAL", 403: "PERMISSION_DENIED"}.get(code, "UNKNOWN")
            return {"error": {"code": code, "message": f"fake error {code}", "status": status}}
        return {"error": {"message": f"fake error {code}", "type": "fake", "code": None}}
