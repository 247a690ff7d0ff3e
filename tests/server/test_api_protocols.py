"""The paper's named protocols through the console API: a trial or a batch may ask for one; it sets the
protocol's settings, a privileged segmenter or a given plan is refused under it (422 naming why), and a batch's
manifest names it."""

from __future__ import annotations

import pytest
from fastapi.testclient import TestClient

from server.app import create_app
from server.settings import Settings
from spark_core import PROTOCOLS


@pytest.fixture()
def client(tmp_path):
    app = create_app(
        Settings(store_url=f"sqlite:///{tmp_path / 'api.db'}", workers=1, artifacts_dir=str(tmp_path / "art"))
    )
    with TestClient(app) as c:
        yield c


def test_trial_config_takes_the_protocols_settings():
    from server.api.models import TrialCreate
    from server.api.trials import trial_config

    body = TrialCreate(task="Lift", planner="gemini", segmenter="learned", protocol="s2")
    config = trial_config(body)
    assert config.eval_protocol == "s2" and config.adaptive == PROTOCOLS["s2"].adaptive


def test_a_privileged_segmenter_under_a_protocol_is_refused_by_name(client):
    r = client.post("/api/trials", json={"task": "Lift", "planner": "gemini", "segmenter": "sim", "protocol": "s2"})
    assert r.status_code == 422, r.text
    assert "privileged" in r.json()["detail"]


def test_an_unknown_protocol_is_refused_naming_the_available_ones(client):
    r = client.post("/api/trials", json={"task": "lift_block", "protocol": "unfair"})
    assert r.status_code == 422, r.text
    assert "unknown protocol 'unfair'" in r.text and "fair" in r.text


def test_a_batch_under_a_protocol_is_refused_whole_for_a_privileged_segmenter(client):
    r = client.post(
        "/api/batches",
        json={"suite": "capbench", "tasks": ["Lift"], "planner": "gemini", "segmenter": "sim", "protocol": "s2"},
    )
    assert r.status_code == 422, r.text
    assert "Lift seed 0" in r.json()["detail"] and "privileged" in r.json()["detail"]
    assert client.get("/api/batches").json()["total"] == 0


def test_the_openapi_document_lists_the_protocols(client):
    schema = client.get("/openapi.json").json()["components"]["schemas"]
    assert schema["TrialCreate"]["properties"]["protocol"]["enum"] == list(PROTOCOLS)
    assert schema["BatchCreate"]["properties"]["protocol"]["enum"] == list(PROTOCOLS)
