"""List filters and exports refuse what they do not know instead of answering with nothing, and search text is
literal (adversarial review L4)."""

from __future__ import annotations

import pytest
from fastapi.testclient import TestClient

from server.app import create_app
from server.settings import Settings
from spark_core import enums


@pytest.fixture()
def client(tmp_path):
    settings = Settings(store_url=f"sqlite:///{tmp_path / 'f.db'}", workers=1, viser=False)
    with TestClient(create_app(settings)) as c:
        store = c.app.state.store  # type: ignore[attr-defined]
        store.create_trial("t-pct", status="done", task="lift_block", instruction="raise it 100% of the way")
        store.create_trial("t-plain", status="done", task="lift_block", instruction="lift the red block")
        yield c


def test_an_unknown_verdict_or_status_is_422_listing_the_known_ones(client):
    r = client.get("/api/trials?verdict=nonsense")
    assert r.status_code == 422 and all(v in r.json()["detail"] for v in enums()["verdict"])
    r = client.get("/api/trials?status=bogus")
    assert r.status_code == 422 and "queued, running, done, interrupted" in r.json()["detail"]
    assert client.get("/api/trials?verdict=success&status=done").status_code == 200
    r = client.get("/api/trials?sort=--created_at")  # was taken as -created_at
    assert r.status_code == 422 and "one '-' before it for descending" in r.json()["detail"]
    assert client.get("/api/trials?sort=-created_at").status_code == 200


@pytest.mark.parametrize("q,ids", [("%", ["t-pct"]), ("lift_the", []), ("100%", ["t-pct"]), ("red", ["t-plain"])])
def test_search_text_is_literal(client, q, ids):
    assert [t["id"] for t in client.get("/api/trials", params={"q": q}).json()["items"]] == ids


def test_an_export_with_an_unknown_field_is_refused(client):
    r = client.post("/api/exports", json={"batch": "x", "evil": 1})
    assert r.status_code == 422 and "evil" in str(r.json()["detail"])


def test_a_plan_error_names_the_request_field(client):
    r = client.post(
        "/api/trials", json={"task": "lift_block", "plan": "task: t\ntree: {primitive: grasp, params: {force: high}}"}
    )
    assert r.status_code == 422 and r.json()["detail"].startswith("plan: tree.params.force")


def test_a_trial_record_names_its_files_without_server_paths(client, tmp_path):
    art = tmp_path / "art" / "t-art"
    art.mkdir(parents=True)
    (art / "detection.png").write_bytes(b"png")
    store = client.app.state.store  # type: ignore[attr-defined]
    entry = {"name": "detection.png", "path": str(art / "detection.png"), "sha256": "x"}
    store.create_trial("t-art", status="done", task="lift_block", artifacts=[entry])
    r = client.get("/api/trials/t-art")
    assert r.json()["artifacts"] == [{"name": "detection.png", "sha256": "x"}] and str(tmp_path) not in r.text
    assert client.get("/api/trials/t-art/artifacts/detection.png").content == b"png"  # still served by name


def test_an_artifact_whose_file_is_gone_is_a_404_naming_it(client, tmp_path):
    """The record names a file that is no longer on disk (removed by hand, or the console started elsewhere):
    a 404 that names the artifact and not where it was, never a 500."""
    gone = tmp_path / "art" / "t-gone" / "detection.png"
    store = client.app.state.store  # type: ignore[attr-defined]
    entry = {"name": "detection.png", "path": str(gone), "sha256": "x"}
    store.create_trial("t-gone", status="done", task="lift_block", artifacts=[entry])
    r = client.get("/api/trials/t-gone/artifacts/detection.png")
    assert r.status_code == 404 and "'detection.png' is no longer on" in r.json()["detail"], r.text
    assert str(tmp_path) not in r.text


@pytest.mark.parametrize(
    "url,body,field",
    [
        ("/api/trials", {"task": "lift_block", "capture": "yes"}, "capture"),
        ("/api/trials", {"task": "lift_block", "start_paused": 1}, "start_paused"),
        ("/api/batches", {"tasks": ["lift_block"], "capture": "true"}, "capture"),
        ("/api/exports", {"batch": "x", "success_only": "no"}, "success_only"),
    ],
)
def test_a_switch_is_a_json_boolean(client, url, body, field):
    r = client.post(url, json=body)
    assert r.status_code == 422 and [d["field"] for d in r.json()["detail"]] == [field]


def test_a_model_for_a_planner_that_takes_none_is_refused(client):
    r = client.post("/api/trials", json={"task": "lift_block", "planner": "reference", "model": "gpt-4.1"})
    assert (
        r.status_code == 422
        and r.json()["detail"] == "model: the reference planner takes no model (only the LLM planners do)"
    )


@pytest.mark.parametrize("planner", ["openai", "gemini"])
@pytest.mark.parametrize("model", ["", "   ", "\t"])
def test_a_blank_model_name_is_refused(client, planner, model):
    """A blank model is no model: openai's "needs a model name" let "   " through to the LLM server, and gemini
    sent it instead of its default."""
    r = client.post("/api/trials", json={"task": "lift_block", "planner": planner, "model": model})
    assert r.status_code == 422 and r.json()["detail"].startswith("model: the model name is blank"), r.text
    assert sorted(client.app.state.store.trial_ids()) == ["t-pct", "t-plain"]  # type: ignore[attr-defined]


def test_a_validator_s_message_reads_without_pydantic_s_prefix(client):
    r = client.post("/api/trials", json={"task": "lift_block", "planner": "oracle"})
    assert r.status_code == 422 and r.json()["detail"][0]["msg"].startswith("unknown planner 'oracle'; available:")
