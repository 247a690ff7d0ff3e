"""Reads are guarded like writes once a token is set or the bind is beyond loopback (adversarial review H2, M6,
L7): every /api/* read but /api/health and the /viser/ page need the bearer or the session cookie; scene renders
have a rate limit of their own; the login redirect stays on this server."""

from __future__ import annotations

import pytest
from fastapi.testclient import TestClient

from server.app import create_app
from tests.server.isolated_settings import isolated_settings

TOKEN = "s3cret-token-4711"
READS = [
    "/api/trials?limit=500",
    "/api/trials/some-trial",
    "/api/trials/some-trial/artifacts/detections-agentview",
    "/api/trials/some-trial/camera.png?t_sim_s=1",
    "/api/tasks/lift_block/preview.png",
    "/api/exports/export-0772368c9d.zip",
    "/api/batches",
    "/api/batches/b/timing",
    "/api/catalog",
    "/api/viser",
    "/viser/",
]


@pytest.fixture()
def guarded(tmp_path):
    with TestClient(create_app(isolated_settings(tmp_path, api_token=TOKEN))) as c:
        yield c


@pytest.mark.parametrize("url", READS)
def test_a_read_without_credentials_is_refused_when_a_token_is_set(guarded, url):
    r = guarded.get(url)
    assert r.status_code == 401 and "SPARK_API_TOKEN" in r.json()["detail"]


def test_the_bearer_any_case_and_the_session_cookie_open_the_reads(guarded):
    assert guarded.get("/api/health").status_code == 200  # liveness probes need nothing
    for scheme in ("Bearer", "bearer", "BEARER"):
        assert guarded.get("/api/trials", headers={"Authorization": f"{scheme} {TOKEN}"}).status_code == 200
    assert guarded.get("/api/trials", headers={"Authorization": "Bearer wrong"}).status_code == 401
    login = guarded.get(f"/?token={TOKEN}", follow_redirects=False)
    assert login.status_code == 303 and "spark_session" in login.headers["set-cookie"]
    assert guarded.get("/api/trials").status_code == 200  # the browser's cookie, as the web client sends it
    assert guarded.get("/api/catalog").status_code == 200


def test_reads_are_guarded_beyond_loopback_too(tmp_path):
    with TestClient(create_app(isolated_settings(tmp_path, host="0.0.0.0", api_token=TOKEN))) as c:
        assert c.get("/api/trials").status_code == 401
        assert c.get("/api/trials", headers={"Authorization": f"Bearer {TOKEN}"}).status_code == 200


def test_a_loopback_console_without_a_token_stays_open_for_reads(tmp_path):
    with TestClient(create_app(isolated_settings(tmp_path))) as c:
        assert c.get("/api/trials").status_code == 200


def test_missing_credentials_do_not_lock_the_operator_out(guarded):
    for _ in range(30):  # a page opened before its login, or a websocket reconnecting, presents nothing
        assert guarded.get("/api/trials").status_code == 401
    assert guarded.get("/api/trials", headers={"Authorization": f"Bearer {TOKEN}"}).status_code == 200


def test_scene_renders_have_a_rate_limit_of_their_own(tmp_path):
    settings = isolated_settings(tmp_path, expensive_rate_per_s=0.01, expensive_burst=3)
    with TestClient(create_app(settings)) as c:
        codes = [c.get("/api/trials/nope/camera.png?t_sim_s=1").status_code for _ in range(5)]
        assert codes[:3] == [404, 404, 404] and codes[3:] == [429, 429]
        assert c.get("/api/trials").status_code == 200  # cheap reads are not counted against it


@pytest.mark.parametrize("path", ["/%5Cevil.example", "//evil.example/", "/%5C/evil.example", "/\\\\evil.example"])
def test_the_login_redirect_never_leaves_this_server(guarded, path):
    r = guarded.get(f"{path}?token={TOKEN}&view=history", follow_redirects=False)
    location = r.headers["location"]
    assert r.status_code == 303 and location.startswith("/") and location[1:2] not in ("/", "\\"), location
    assert location.endswith("?view=history")


def test_without_a_token_a_token_in_the_url_is_no_login(tmp_path):
    with TestClient(create_app(isolated_settings(tmp_path))) as c:
        r = c.get("/%5Cevil.example?token=anything", follow_redirects=False)
        assert r.status_code != 303 and "location" not in r.headers
