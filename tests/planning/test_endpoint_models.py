"""An endpoint's model allowlist holds when the caller names no model (adversarial review L1): the planner's
default model is not one the operator allowed, so the request is refused naming the models that are."""

from __future__ import annotations

import pytest

from spark_core.planning.endpoints import resolve_endpoint
from spark_core.trial import TrialConfig, TrialConfigError


@pytest.fixture()
def endpoint(tmp_path, monkeypatch):
    config = tmp_path / "spark.yaml"
    config.write_text(
        "endpoints:\n  only-one: {planner: gemini, base_url: 'http://127.0.0.1:9/gm', models: [only-this-model]}\n"
    )
    monkeypatch.setenv("SPARK_CONFIG", str(config))


def test_an_omitted_model_is_refused_where_the_endpoint_lists_its_models(endpoint):
    with pytest.raises(ValueError, match="model: endpoint 'only-one' serves only only-this-model: name one"):
        resolve_endpoint("only-one", "gemini", None)
    with pytest.raises(TrialConfigError, match="serves only only-this-model"):
        TrialConfig("lift_block", planner="gemini", endpoint="only-one").check()
    assert resolve_endpoint("only-one", "gemini", "only-this-model").name == "only-one"
