"""The loopback HTTP server under the fake vendors (`fake_gemini`, `fake_openai`): a script consumed one entry
per request, every request recorded. Test-only.

Script entries:
- ("ok", text[, (prompt, output, thoughts) tokens]): a success in the vendor's JSON shape
- ("status", code[, retry_after_s]): the vendor's error body for that HTTP status (429 with its retry hint,
  1 s unless given; 5xx; 4xx)
- ("sleep", seconds, text): answer `text` after a delay (timeouts)
- ("raw", code, body bytes): exactly these bytes (a proxy's HTML page, a cut-off body)
A request the vendor would refuse (missing key, bad payload) is answered with the vendor's 4xx and does not
consume the script; an empty script answers 500.
"""

from __future__ import annotations

import contextlib
import json
import threading
import time
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from typing import Any


class FakeVendor:
    def __init__(self) -> None:
        self.script: list[tuple] = []
        self.requests: list[dict[str, Any]] = []
        fake = self

        class Handler(BaseHTTPRequestHandler):
            def log_message(self, *args):  # keep test output clean
                pass

            def do_POST(self):
                raw = self.rfile.read(int(self.headers.get("Content-Length", 0)))
                try:
                    body = json.loads(raw or b"{}")
                except json.JSONDecodeError:
                    body = None
                headers = {k.lower(): v for k, v in self.headers.items()}
                fake.requests.append({"path": self.path, "headers": headers, "body": body})
                refused = fake.refuse(self.path, headers, body)
                if refused is not None:
                    return self._send(refused[0], json.dumps(refused[1]).encode())
                entry = fake.script.pop(0) if fake.script else ("status", 500)
                if entry[0] == "sleep":
                    time.sleep(entry[1])
                    entry = ("ok", entry[2])
                if entry[0] == "raw":
                    return self._send(entry[1], entry[2], "text/html")
                if entry[0] == "status":
                    return self._send(
                        entry[1],
                        json.dumps(fake.error(entry[1], *entry[2:])).encode(),
                        extra=fake.error_headers(entry[1], *entry[2:]),
                    )
                usage = entry[2] if len(entry) > 2 else (120, 40, 8)
                return self._send(200, json.dumps(fake.success(entry[1], usage, body)).encode())

            def _send(self, code, data: bytes, content_type="application/json", extra=None):
                self.send_response(code)
                self.send_header("Content-Type", content_type)
                self.send_header("Content-Length", str(len(data)))
                for k, v in (extra or {}).items():
                    self.send_header(k, v)
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

    # -- what each vendor defines ----------------------------------------------------------------------------
    def refuse(self, path: str, headers: dict[str, str], body: Any) -> tuple[int, dict] | None:
        raise NotImplementedError

    def success(self, text: str, usage: tuple[int, int, int], body: dict) -> dict:
        raise NotImplementedError

    def error(self, code: int, retry_after_s: float = 1.0) -> dict:
        raise NotImplementedError

    def error_headers(self, code: int, retry_after_s: float = 1.0) -> dict[str, str]:
        return {}


def approx_tokens(text: str) -> int:
    """The vendors' rule of thumb: about 4 characters per token."""
    return max(1, len(text) // 4)
