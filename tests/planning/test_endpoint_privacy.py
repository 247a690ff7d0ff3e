"""A named endpoint's URL is the operator's: planner errors name the endpoint, never its URL, and a gemini
endpoint that cannot work (no key) says so by name (adversarial review L2)."""

from __future__ import annotations

import pytest

from spark_core.planning.backends import make_planner
from spark_core.planning.llm import PlannerUnavailable
from spark_core.planning.protocol import PlanRequest
from tests.doubles.fake_openai import FakeOpenAI


def test_an_endpoint_error_names_the_endpoint_not_its_url(tmp_path, monkeypatch):
    with FakeOpenAI() as fake:
        config = tmp_path / "spark.yaml"
        config.write_text(f"endpoints:\n  lab: {{planner: openai, base_url: '{fake.url}/v1', models: [qwen]}}\n")
        monkeypatch.setenv("SPARK_CONFIG", str(config))
        fake.script = [("status", 400)]
        result = make_planner("openai", "qwen", endpoint="lab").plan(PlanRequest("pick up the red block"))
        assert result.plan is None and "from endpoint 'lab'" in result.error, result.error
        assert fake.url not in result.error and "127.0.0.1" not in result.error


def test_a_gemini_endpoint_without_a_key_says_so_by_name(tmp_path, monkeypatch):
    config = tmp_path / "spark.yaml"
    config.write_text("endpoints:\n  gem: {planner: gemini, base_url: 'http://127.0.0.1:9/gem'}\n")
    monkeypatch.setenv("SPARK_CONFIG", str(config))
    with pytest.raises(PlannerUnavailable, match="endpoint 'gem' has no key: a gemini endpoint needs api_key_env") as e:
        make_planner("gemini", "m", endpoint="gem")
    assert "127.0.0.1" not in str(e.value)
