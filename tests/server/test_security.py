"""Issue 20's attacks, each against the console: token in URLs and logs, guessing, cross-origin pages, streamed
bodies, unknown websockets, exports of unknown trials, the slow list. Real uvicorn where the server matters."""

import contextlib
import logging
import socket
import threading
import time

import httpx
import pytest
from fastapi.testclient import TestClient
from starlette.testclient import WebSocketDenialResponse

from server.app import create_app
from server.settings import Settings
from tests.server.isolated_settings import isolated_settings

TOKEN = "s3cret-token-4711"


@contextlib.contextmanager
def _serve(settings: Settings, log_level: str = "warning"):
    """The app under a real uvicorn on a free loopback port, with uvicorn's defaults (proxy headers on)."""
    import uvicorn

    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    srv = uvicorn.Server(uvicorn.Config(create_app(settings), host="127.0.0.1", port=port, log_level=log_level))
    thread = threading.Thread(target=srv.run, daemon=True)
    thread.start()
    for _ in range(400):
        if srv.started:
            break
        time.sleep(0.05)
    try:
        yield f"http://127.0.0.1:{port}"
    finally:
        srv.should_exit = True
        thread.join(10)


def test_url_token_is_swapped_for_an_httponly_samesite_cookie_and_a_clean_url(tmp_path):
    with TestClient(create_app(isolated_settings(tmp_path, host="0.0.0.0", api_token=TOKEN))) as c:
        r = c.get(f"/?token={TOKEN}&view=history", follow_redirects=False)
        assert r.status_code == 303 and r.headers["location"] == "/?view=history"
        cookie = r.headers["set-cookie"]
        assert "HttpOnly" in cookie and "SameSite=Strict" in cookie and "Path=/" in cookie and TOKEN not in cookie
        ok = c.post("/api/plans/validate", json={"text": "task: t\ntree: {primitive: wait}"})  # the cookie suffices
        assert ok.status_code == 200 and ok.json()["ok"]
        with c.websocket_connect("/api/events"):  # so does it for websockets
            pass
        c.cookies.clear()
        assert c.post("/api/plans/validate", json={"text": "x"}).status_code == 401
        # the token in a websocket URL is no credential
        with pytest.raises(WebSocketDenialResponse) as refused, c.websocket_connect(f"/api/events?token={TOKEN}"):
            pass
        assert refused.value.status_code == 401
        with c.websocket_connect("/api/events", headers={"Authorization": f"Bearer {TOKEN}"}):
            pass
        wrong = c.get("/?token=guess", follow_redirects=False)
        assert wrong.status_code == 401 and "set-cookie" not in wrong.headers
        assert c.get("//evil.example/?token=x", follow_redirects=False).headers.get("location") != "//evil.example/"


def test_no_credential_reaches_a_log_line(tmp_path):
    lines: list[str] = []

    class Keep(logging.Handler):
        def emit(self, record):
            lines.append(self.format(record))

    keep = Keep()
    try:
        with _serve(isolated_settings(tmp_path, api_token=TOKEN), log_level="info") as base:
            for name in ("uvicorn.access", "uvicorn.error"):  # after uvicorn's logging set-up, which drops handlers
                logging.getLogger(name).addHandler(keep)
            assert httpx.get(f"{base}/?token={TOKEN}", follow_redirects=True).status_code == 200  # to / via a cookie
            httpx.get(f"{base}/api/health?token={TOKEN}&access_token={TOKEN}")
            httpx.post(f"{base}/api/plans/validate", json={"text": "x"}, headers={"Authorization": f"Bearer {TOKEN}"})
            time.sleep(0.2)
    finally:
        for name in ("uvicorn.access", "uvicorn.error"):
            logging.getLogger(name).removeHandler(keep)
    access = [line for line in lines if "/?token=" in line or "/api/health?" in line]
    assert len(access) >= 2, lines  # the lines were written, with the parameter's name
    assert not any(TOKEN in line for line in lines), [line for line in lines if TOKEN in line]
    from server.security.redact import redact

    assert TOKEN not in redact(f"headers: {{'authorization': 'Bearer {TOKEN}', 'cookie': 'spark_session={TOKEN}'}}")


def test_guessing_the_token_is_rate_limited_and_forwarded_for_from_loopback_does_not_reset_it(tmp_path):
    with _serve(isolated_settings(tmp_path, api_token=TOKEN, auth_failures_max=10)) as base:
        guesses = [{"Authorization": f"Bearer guess{k}", "X-Forwarded-For": f"203.0.113.{k}"} for k in range(20)]
        codes = [httpx.post(f"{base}/api/plans/validate", json={"text": "x"}, headers=h).status_code for h in guesses]
        assert codes[:10] == [401] * 10 and codes[10:] == [429] * 10, codes
        right = httpx.post(
            f"{base}/api/plans/validate",
            json={"text": "x"},
            headers={"Authorization": f"Bearer {TOKEN}", "X-Forwarded-For": "198.51.100.7"},
        )
        assert right.status_code == 429 and int(right.headers["retry-after"]) > 0  # blocked, however it is dressed
        login = httpx.get(f"{base}/?token=guess", headers={"X-Forwarded-For": "198.51.100.8"})
        assert login.status_code == 429
    from server.security.clients import client_address, parse_networks

    scope = {"client": ("10.0.0.2", 5000), "headers": [(b"x-forwarded-for", b"198.51.100.9, 10.0.0.3")]}
    assert client_address(scope, ()) == "10.0.0.2"  # no trusted proxy configured: the header is ignored
    assert client_address(scope, parse_networks(["10.0.0.0/8"])) == "198.51.100.9"  # SPARK_TRUSTED_PROXIES


def test_cross_origin_pages_cannot_drive_a_loopback_console(tmp_path):
    with TestClient(create_app(isolated_settings(tmp_path))) as c:  # loopback, no token: the default console
        with (
            pytest.raises(WebSocketDenialResponse) as refused,
            c.websocket_connect("/api/events", headers={"Origin": "http://evil.example"}),
        ):
            pass
        assert refused.value.status_code == 403
        r = c.post("/api/trials", json={"task": "lift_block"}, headers={"Origin": "http://evil.example"})
        assert r.status_code == 403 and "evil.example" in r.json()["detail"]
        assert c.get("/api/trials").json()["total"] == 0  # nothing was queued
        form = c.post("/api/plans/validate", content=b'{"text": "x"}', headers={"Content-Type": "text/plain"})
        assert form.status_code == 415  # what a cross-site <form> could send without a preflight
        same = c.post("/api/plans/validate", json={"text": "x"}, headers={"Origin": "http://testserver"})
        assert same.status_code == 200
        assert c.post("/api/plans/validate", json={"text": "x"}).status_code == 200  # curl / SDKs send no Origin
        with c.websocket_connect("/api/events", headers={"Origin": "http://testserver"}):
            pass
    with TestClient(create_app(isolated_settings(tmp_path, cors_origins=("http://ui.example",)))) as c:
        listed = c.post("/api/plans/validate", json={"text": "x"}, headers={"Origin": "http://ui.example"})
        assert listed.status_code == 200


def test_a_dns_rebinding_page_cannot_read_or_drive_a_console_without_a_token(tmp_path):
    """A page at http://rebind.attacker.example:8000 whose name then resolves to 127.0.0.1 is "same origin" with the
    console (its Origin and the Host it sends are both its own name): on a console that asks no credentials it
    could queue, read and purge trials. Such a console answers only to loopback names and IP addresses."""
    rebound = {"Host": "rebind.attacker.example:8000", "Origin": "http://rebind.attacker.example:8000"}
    with TestClient(create_app(isolated_settings(tmp_path))) as c:  # loopback, no token: the default console
        r = c.post("/api/trials", json={"task": "lift_block"}, headers=rebound)
        assert r.status_code == 403 and "DNS rebinding" in r.json()["detail"]
        assert c.get("/api/trials", headers={"Host": "rebind.attacker.example:8000"}).status_code == 403
        assert c.get("/", headers={"Host": "rebind.attacker.example."}).status_code == 403
        with (
            pytest.raises(WebSocketDenialResponse) as refused,
            c.websocket_connect("/api/events", headers=rebound),
        ):
            pass
        assert refused.value.status_code == 403
        assert c.get("/api/trials").json()["total"] == 0  # nothing was queued
        for host in ("localhost:8000", "127.0.0.1:8000", "[::1]:8000", "127.0.0.2", "spark.localhost:8000", "box"):
            assert c.get("/api/trials", headers={"Host": host}).status_code == 200, host
    allowed = isolated_settings(tmp_path, allowed_hosts=("spark.lab.example",))
    with TestClient(create_app(allowed)) as c:  # SPARK_ALLOWED_HOSTS: the operator's own name for this machine
        assert c.get("/api/trials", headers={"Host": "spark.lab.example:8000"}).status_code == 200
        assert c.get("/api/trials", headers={"Host": "rebind.attacker.example"}).status_code == 403
    with TestClient(create_app(isolated_settings(tmp_path, api_token=TOKEN))) as c:  # a token guards every name
        auth = {"Authorization": f"Bearer {TOKEN}", "Host": "spark.lab.example"}
        assert c.get("/api/trials", headers=auth).status_code == 200
        assert c.get("/api/trials", headers={"Host": "spark.lab.example"}).status_code == 401


def test_a_chunked_body_over_the_limit_is_refused(tmp_path):
    def body():
        for _ in range(32):  # 2 MiB in 64 KiB chunks: no Content-Length to check up front
            yield b" " * 65536

    with _serve(isolated_settings(tmp_path)) as base:
        r = httpx.post(f"{base}/api/plans/validate", content=body(), headers={"Content-Type": "application/json"})
        assert r.status_code == 413 and "larger than 1024 KiB" in r.json()["detail"]
        declared = httpx.post(
            f"{base}/api/plans/validate", content=b" " * (2 * 1024 * 1024), headers={"Content-Type": "application/json"}
        )
        assert declared.status_code == 413
        small = httpx.post(
            f"{base}/api/plans/validate",
            content=(c for c in [b'{"text": ', b'"x"}']),
            headers={"Content-Type": "application/json"},
        )
        assert small.status_code == 200  # a small chunked body still reaches the route whole


def test_a_websocket_about_an_unknown_trial_is_answered_404_before_the_upgrade(tmp_path):
    """The helper the trial stream calls (`websocket_allowed(ws, trial_id=...)`), on the real store."""
    from fastapi import FastAPI, WebSocket

    from server.api.auth import websocket_allowed
    from spark_core.trace.store import TraceStore

    app = FastAPI()
    app.state.store = TraceStore(f"sqlite:///{tmp_path / 'w.db'}")
    app.state.runner = type("Runner", (), {"live": {"live-1": object()}})()
    app.state.store.create_trial("stored-1", status="done", task="lift_block")

    @app.websocket("/api/trials/{trial_id}/events")
    async def events(websocket: WebSocket, trial_id: str) -> None:
        if not await websocket_allowed(websocket, trial_id=trial_id):
            return
        await websocket.accept()
        await websocket.send_json({"kind": "closed"})
        await websocket.close()

    with TestClient(app) as c:
        with pytest.raises(WebSocketDenialResponse) as refused, c.websocket_connect("/api/trials/ghost-1/events"):
            pass
        assert refused.value.status_code == 404 and "ghost-1" in refused.value.text
        for known in ("stored-1", "live-1"):
            with c.websocket_connect(f"/api/trials/{known}/events") as ws:
                assert ws.receive_json() == {"kind": "closed"}


def test_an_export_of_unknown_trials_is_refused_and_reveals_no_server_path(tmp_path):
    with TestClient(create_app(isolated_settings(tmp_path))) as c:
        c.app.state.store.create_trial("known-1", status="done", task="lift_block", success=True)
        r = c.post("/api/exports", json={"trial_ids": ["known-1", "ghost-1", "ghost-2"]})
        assert r.status_code == 404 and "'ghost-1'" in r.json()["detail"] and "'ghost-2'" in r.json()["detail"]
        assert "known-1" not in r.json()["detail"]
        assert c.post("/api/exports", json={"batch": "no-such-batch"}).status_code == 404
        nothing = c.post("/api/exports", json={"trial_ids": ["known-1"]})  # exists, but has nothing to export
        assert nothing.status_code == 422
        for text in (r.text, nothing.text):
            assert str(tmp_path) not in text and "/exports/" not in text


def test_the_trial_list_reads_no_heavy_column_and_pages_from_an_index(tmp_path):
    from sqlalchemy import event, text

    from spark_core.trace.store import TraceStore

    store = TraceStore(f"sqlite:///{tmp_path / 'l.db'}")
    trajectory = [[0.01 * k, "right", [0.0] * 7, 0.04] for k in range(2000)]
    for i in range(60):
        store.create_trial(f"t{i:03d}", status="done", task=f"task{i % 3}", success=bool(i % 2), trajectory=trajectory)
    statements: list[str] = []
    event.listen(store.engine, "before_cursor_execute", lambda *a: statements.append(a[2]))
    total, items = store.list_trials(limit=50, offset=5)
    assert total == 60 and len(items) == 50 and items[0]["id"] == "t054"  # newest first, id breaking no ties here
    assert "trajectory" not in items[0] and "plan_text" not in items[0] and items[0]["task"] == "task0"
    assert statements and not any("trajectory" in s for s in statements), statements  # never read, never decoded
    filtered_total, filtered = store.list_trials(task="task1", success=True, limit=5)
    assert filtered_total == 10 and all(t["task"] == "task1" and t["success"] for t in filtered)
    with store.engine.connect() as conn:
        plan = conn.execute(
            text(
                "EXPLAIN QUERY PLAN SELECT id FROM trials WHERE deleted_at IS NULL "
                "ORDER BY created_at DESC, id DESC LIMIT 50 OFFSET 5000"
            )
        ).fetchall()
    assert any("COVERING INDEX ix_trials_created_at_id" in str(row) for row in plan), plan  # migrations 0006, 0007
