"""Finding 1 of the security issue: the server's LLM keys go only to endpoints the operator configured. A caller
can name an endpoint, never a URL; an ad-hoc URL gets no key from the environment."""

from __future__ import annotations

import time

import pytest
from fastapi.testclient import TestClient

from server.app import create_app
from server.settings import Settings
from tests.doubles.fake_openai import FakeOpenAI
from tests.doubles.fake_vendor import FakeVendor

PLAN = (
    '{"task": "lift", "tree": {"type": "sequence", "children": '
    '[{"primitive": "pick", "params": {"keypoint_label": "red block"}}]}}'
)


@pytest.fixture()
def keys(monkeypatch):
    monkeypatch.setenv("OPENAI_API_KEY", "sk-server-secret")
    monkeypatch.setenv("GEMINI_API_KEY", "g-server-secret")


def _authorization(fake: FakeVendor) -> list[str]:
    out = []
    for r in fake.requests:
        headers = {k.lower(): v for k, v in r["headers"].items()}
        out.append(headers.get("authorization") or headers.get("x-goog-api-key") or "")
    return out


def test_a_caller_supplied_url_is_refused_and_never_contacted(keys, tmp_path):
    with FakeOpenAI() as fake:
        app = create_app(Settings(store_url=f"sqlite:///{tmp_path / 'k.db'}", workers=1, viser=False))
        with TestClient(app) as c:
            for planner in ("openai", "gemini"):
                r = c.post(
                    "/api/trials",
                    json={"task": "lift_block", "planner": planner, "model": "m", "base_url": fake.url + "/v1"},
                )
                assert r.status_code == 422 and "base_url" in r.text
            time.sleep(0.5)
        assert fake.requests == []


def test_only_a_configured_endpoint_gets_its_key(keys, tmp_path, monkeypatch):
    from spark_core.planning.backends import make_planner
    from spark_core.planning.protocol import PlanRequest

    with FakeOpenAI() as fake:
        config = tmp_path / "spark.yaml"
        config.write_text(
            f"endpoints:\n  lab: {{planner: openai, base_url: '{fake.url}/v1', api_key_env: LAB_KEY, models: [qwen]}}\n"
        )
        monkeypatch.setenv("SPARK_CONFIG", str(config))
        monkeypatch.setenv("LAB_KEY", "lab-key")
        fake.script = [("ok", PLAN), ("ok", PLAN)]
        make_planner("openai", "qwen", endpoint="lab").plan(PlanRequest("pick up the red block"))
        make_planner("openai", "qwen", base_url=fake.url + "/v1").plan(PlanRequest("pick up the red block"))
        sent = _authorization(fake)
        assert sent[0] == "Bearer lab-key"  # the configured endpoint: its own key
        assert "sk-server-secret" not in sent[1] and sent[1] == "Bearer not-needed"  # an ad-hoc URL: no key
        with pytest.raises(ValueError, match="model: endpoint 'lab' serves qwen, not 'gpt'"):
            make_planner("openai", "gpt", endpoint="lab")
        with pytest.raises(ValueError, match="unknown endpoint 'elsewhere'; configured: lab"):
            make_planner("openai", "qwen", endpoint="elsewhere")


def test_gemini_at_an_ad_hoc_url_gets_no_key(keys):
    from spark_core.planning.backends import make_planner
    from spark_core.planning.llm import PlannerUnavailable

    with pytest.raises(PlannerUnavailable, match="no key for http://127.0.0.1:9"):
        make_planner("gemini", "m", base_url="http://127.0.0.1:9")


def test_the_api_names_endpoints_without_their_keys_or_urls(keys, tmp_path, monkeypatch):
    config = tmp_path / "spark.yaml"
    config.write_text(
        "endpoints:\n  lab: {planner: openai, base_url: 'http://10.0.0.5:8000/v1', api_key_env: LAB_KEY}\n"
    )
    monkeypatch.setenv("SPARK_CONFIG", str(config))
    monkeypatch.setenv("LAB_KEY", "lab-key")
    app = create_app(Settings(store_url=f"sqlite:///{tmp_path / 'k.db'}", workers=1, viser=False))
    with TestClient(app) as c:
        cat = c.get("/api/catalog")
        assert cat.json()["endpoints"] == [{"name": "lab", "planner": "openai", "models": []}]
        assert "lab-key" not in cat.text and "10.0.0.5" not in cat.text
        bad = c.post("/api/trials", json={"task": "lift_block", "planner": "gemini", "endpoint": "lab"})
        assert bad.status_code == 422 and "'lab' serves the openai planner" in bad.text
