"""HEAD wherever GET works, over the wire (API pass: HEAD /api/health, HEAD /api/trials and HEAD /docs answered
405 or 404), and 405s that name every method of their path (PUT /api/trials said `allow: POST` only)."""

from __future__ import annotations

import http.client
import socket
import threading
import time
from dataclasses import replace
from pathlib import Path

import pytest
from fastapi.testclient import TestClient

from server.app import create_app

from .isolated_settings import isolated_settings

ROOT = Path(__file__).resolve().parents[2]
GETS = ["/api/health", "/api/trials?limit=5", "/api/catalog", "/api/batches", "/api/exports", "/openapi.json"]


@pytest.fixture()
def app(tmp_path):
    return create_app(replace(isolated_settings(tmp_path), workers=0))


def test_head_answers_as_get_does_without_a_body(app):
    with TestClient(app) as c:
        store = c.app.state.store  # type: ignore[attr-defined]
        store.create_trial("t1", task="lift_block", status="done")
        pages = ["/", "/docs", "/favicon.svg"] if (ROOT / "web" / "dist" / "index.html").is_file() else []
        for path in [*GETS, "/api/trials/t1", *pages]:
            get, head = c.get(path), c.head(path)
            assert (head.status_code, get.status_code) == (200, 200), (path, head.status_code)
            assert head.content == b"", path
            for name in ("content-type", "content-length"):
                assert head.headers.get(name) == get.headers.get(name), (path, name)
        # what GET answers with an error, HEAD answers with the same status (and no body)
        for path, status in (("/api/trials/nope", 404), ("/api/nope", 404), ("/api/trials?limit=0", 422)):
            head = c.head(path)
            assert (head.status_code, head.content) == (status, b""), path
        # a path that takes no GET: HEAD is not allowed either, and the 405 names what is
        r = c.head("/api/trials/t1/control")
        assert r.status_code == 405 and r.headers["allow"] == "POST"


def test_a_405_names_every_method_of_its_path(app):
    with TestClient(app) as c:
        assert c.put("/api/trials", json={}).headers["allow"] == "GET, HEAD, POST"
        assert c.put("/api/health").headers["allow"] == "GET, HEAD"
        assert c.patch("/api/trials/t1").headers["allow"] == "GET, HEAD, DELETE"
        assert c.post("/api/trial", json={}).status_code == 404  # no such endpoint stays 404


def test_head_over_a_real_connection_gets_headers_only(app):
    import uvicorn

    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    server = uvicorn.Server(uvicorn.Config(app, host="127.0.0.1", port=port, log_level="warning"))
    thread = threading.Thread(target=server.run, daemon=True)
    thread.start()
    try:
        for _ in range(200):
            if server.started:
                break
            time.sleep(0.05)
        conn = http.client.HTTPConnection("127.0.0.1", port, timeout=10)
        for path in ("/api/health", "/api/catalog", "/api/health"):  # one connection: no stray body between them
            conn.request("HEAD", path)
            r = conn.getresponse()
            assert r.status == 200 and r.read() == b"" and int(r.getheader("content-length")) > 0, path
        conn.request("GET", "/api/health")
        r = conn.getresponse()
        assert r.status == 200 and r.read() == b'{"status":"ok"}'
        conn.close()
    finally:
        server.should_exit = True
        thread.join(10)
