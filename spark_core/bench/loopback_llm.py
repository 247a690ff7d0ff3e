"""A loopback stand-in for the Gemini API, for smoke runs of the paper's protocols on a machine without a key.

It speaks `models/{model}:generateContent` on 127.0.0.1 (the real google-genai client talks to it through a named
endpoint, `loopback`, the way an operator's proxy is configured) and answers with what the offline parts can
give: the prompt-synthesis call with the instruction's own phrases (the rules parser) and the synonym table's
variants; the BT call with the rules planner's plan over the keypoints listed in the prompt. Its figures measure
the pipeline (two calls, perception on every prompt, the annotated image, cost accounting), never Gemini.
"""

from __future__ import annotations

import contextlib
import json
import os
import re
import tempfile
import threading
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from pathlib import Path
from typing import Any

import numpy as np

ENDPOINT = "loopback"
KEY_ENV = "SPARK_LOOPBACK_KEY"
KEYPOINT_LINE = re.compile(
    r"^- (?P<label>.+?): \((?P<x>-?[\d.]+), (?P<y>-?[\d.]+), (?P<z>-?[\d.]+)\), "
    r"size \((?P<sx>[\d.]+), (?P<sy>[\d.]+), (?P<sz>[\d.]+)\)$",
    re.M,
)


def answer(body: dict[str, Any]) -> str:
    """The text the loopback model answers a generateContent request with."""
    config = body.get("generationConfig", {})
    schema = config.get("responseJsonSchema") or {}
    user = body["contents"][0]["parts"][0]["text"]
    task = user.rsplit("Task:", 1)[-1].strip()
    if schema.get("type") == "array":  # the prompt-synthesis call
        from ..perception.variants import prompt_variants
        from ..planning.observe import phrases_for

        with_prompts = "prompts" in schema.get("items", {}).get("properties", {})
        return json.dumps(
            [{"object": p, **({"prompts": prompt_variants(p, 3)} if with_prompts else {})} for p in phrases_for(task)]
        )
    from ..grammar.serialize import plan_to_dict
    from ..perception import Keypoint
    from ..planning import PlanRequest, SceneView
    from ..planning.rules import RulesPlanner

    keypoints = {
        m["label"]: Keypoint(
            m["label"],
            np.array([float(m["x"]), float(m["y"]), float(m["z"])]),
            np.array([float(m["sx"]), float(m["sy"]), float(m["sz"])]),
        )
        for m in KEYPOINT_LINE.finditer(user)
    }
    result = RulesPlanner().plan(PlanRequest(task, SceneView(keypoints, "")))
    if result.plan is None:  # what a model does when it cannot plan: an answer that does not type-check
        return json.dumps({"task": task, "tree": {"type": "sequence", "children": []}})
    return json.dumps(plan_to_dict(result.plan))


class LoopbackGemini:
    """`with LoopbackGemini():` serves on 127.0.0.1 and configures the `loopback` endpoint (a temporary
    spark.yaml named by SPARK_CONFIG, its key in SPARK_LOOPBACK_KEY) for this process and the workers it
    spawns; both are restored on exit."""

    def __init__(self) -> None:
        self.requests = 0
        owner = self

        class Handler(BaseHTTPRequestHandler):
            def log_message(self, *args):  # keep the bench's output clean
                pass

            def do_POST(self):
                body = json.loads(self.rfile.read(int(self.headers.get("Content-Length", 0))) or b"{}")
                owner.requests += 1
                text = answer(body)
                prompt = sum(len(p.get("text", "")) for c in body.get("contents", []) for p in c.get("parts", []))
                payload = {
                    "candidates": [
                        {"content": {"parts": [{"text": text}], "role": "model"}, "finishReason": "STOP", "index": 0}
                    ],
                    "usageMetadata": {  # about 4 characters per token, as the vendors count roughly
                        "promptTokenCount": prompt // 4,
                        "candidatesTokenCount": len(text) // 4,
                        "totalTokenCount": (prompt + len(text)) // 4,
                    },
                    "modelVersion": "loopback",
                }
                data = json.dumps(payload).encode()
                self.send_response(200)
                self.send_header("Content-Type", "application/json")
                self.send_header("Content-Length", str(len(data)))
                self.end_headers()
                with contextlib.suppress(BrokenPipeError):
                    self.wfile.write(data)

        self.server = ThreadingHTTPServer(("127.0.0.1", 0), Handler)
        self.thread = threading.Thread(target=self.server.serve_forever, daemon=True)
        self._saved: dict[str, str | None] = {}
        self._dir: tempfile.TemporaryDirectory[str] | None = None

    @property
    def url(self) -> str:
        return f"http://127.0.0.1:{self.server.server_address[1]}"

    def __enter__(self) -> LoopbackGemini:
        self.thread.start()
        self._dir = tempfile.TemporaryDirectory(prefix="spark-loopback-")
        config = Path(self._dir.name) / "spark.yaml"
        config.write_text(
            f"endpoints:\n  {ENDPOINT}: {{planner: gemini, base_url: '{self.url}', api_key_env: {KEY_ENV}}}\n"
        )
        for name, value in (("SPARK_CONFIG", str(config)), (KEY_ENV, "loopback-key")):
            self._saved[name] = os.environ.get(name)
            os.environ[name] = value
        return self

    def __exit__(self, *exc: object) -> None:
        for name, value in self._saved.items():
            if value is None:
                os.environ.pop(name, None)
            else:
                os.environ[name] = value
        self.server.shutdown()
        self.server.server_close()
        if self._dir is not None:
            self._dir.cleanup()
