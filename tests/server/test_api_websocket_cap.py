"""Open websockets are capped per server (SPARK_MAX_WEBSOCKETS): one more is closed at once with code 1013 and a
reason that says why and which setting; a socket that closes frees its place (adversarial review L8)."""

from __future__ import annotations

import time

import pytest
from fastapi.testclient import TestClient
from starlette.websockets import WebSocketDisconnect

from server.app import create_app
from server.settings import Settings

from .isolated_settings import isolated_settings


def _refused(c: TestClient, url: str) -> WebSocketDisconnect:
    with pytest.raises(WebSocketDisconnect) as refused, c.websocket_connect(url) as ws:
        ws.receive_json()
    return refused.value


def test_websockets_beyond_the_cap_are_closed_with_a_reason(tmp_path):
    with TestClient(create_app(isolated_settings(tmp_path, max_websockets=2))) as c:
        c.app.state.store.create_trial("t-done", status="done", task="lift_block", seed=0)
        with c.websocket_connect("/api/events"), c.websocket_connect("/api/events"):
            for url in ("/api/events", "/api/trials/t-done/events"):  # every stream counts
                gone = _refused(c, url)
                assert gone.code == 1013 and "too many websockets" in gone.reason
                assert "2 at once" in gone.reason and "SPARK_MAX_WEBSOCKETS" in gone.reason
            assert c.get("/api/health").status_code == 200  # plain requests are not affected
        deadline = time.monotonic() + 10  # both handlers return once their clients have gone
        while True:
            try:
                with c.websocket_connect("/api/trials/t-done/events") as ws:
                    assert ws.receive_json()["kind"] == "closed"  # a finished trial without events: closed
                break
            except WebSocketDisconnect as e:
                assert e.code == 1013 and time.monotonic() < deadline, "a closed socket never freed its place"
                time.sleep(0.05)


def test_the_cap_is_a_setting_with_a_default():
    assert Settings().max_websockets == 64
    import os
    from unittest import mock

    with mock.patch.dict(os.environ, {"SPARK_MAX_WEBSOCKETS": "5"}):
        assert Settings.from_env().max_websockets == 5
