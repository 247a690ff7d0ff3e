"""Batches are checked whole before anything is recorded or expanded (security issue, findings 4 and 5)."""

from __future__ import annotations

import time

import pytest
from fastapi.testclient import TestClient

from server.app import create_app
from server.settings import Settings


@pytest.fixture()
def client(tmp_path):
    app = create_app(Settings(store_url=f"sqlite:///{tmp_path / 'b.db'}", workers=1, viser=False))
    with TestClient(app) as c:
        yield c


def _nothing_recorded(client) -> bool:
    store = client.app.state.store
    return store.list_trials()[0] == 0 and not store.trial_ids()


@pytest.mark.parametrize(
    "body,message",
    [
        (
            {"specs": [{"task": "lift_block", "seed": 1}, {"task": "lift_block", "seed": 2, "segmenter": "oracle"}]},
            "unknown segmenter 'oracle'",
        ),
        ({"specs": [{"task": "lift_block"}, {"task": "unicorn_dance"}]}, "specs[1]: unknown task 'unicorn_dance'"),
        ({"tasks": ["lift_block"], "seed": 2**31 - 1, "trials": 2}, "seed: seeds 2147483647..2147483648 go past"),
        ({"tasks": ["lift_block"], "seed": True}, "seed"),
        ({"tasks": ["lift_block"], "planner": "openai"}, "model: the openai planner needs a model name"),
        # an empty name in a spec is not "unset": it was run with the batch's planner / segmenter instead
        ({"specs": [{"task": "lift_block", "planner": ""}]}, "specs[0]: unknown planner ''"),
        ({"specs": [{"task": "lift_block", "segmenter": ""}]}, "specs[0]: unknown segmenter ''"),
        # specs name their own tasks and seeds: the suite's fields beside them were ignored, not run
        ({"specs": [{"task": "lift_block"}], "tasks": ["stack_two"]}, "tasks (['stack_two']): not with specs"),
        ({"specs": [{"task": "lift_block"}], "trials": 100}, "trials (100): not with specs"),
        ({"specs": [{"task": "lift_block"}], "seed": 5}, "seed (5): not with specs"),
    ],
)
def test_a_bad_batch_records_nothing_and_names_what_was_wrong(client, body, message):
    r = client.post("/api/batches", json=body)
    assert r.status_code == 422 and message in r.text, r.text
    assert _nothing_recorded(client)


def test_a_huge_batch_is_refused_before_it_is_expanded(client):
    t0 = time.perf_counter()
    r = client.post("/api/batches", json={"tasks": ["lift_block"] * 20_000, "trials": 100})
    assert r.status_code == 422 and "tasks" in r.text
    r = client.post("/api/batches", json={"tasks": ["lift_block", "push_to_zone"] * 600, "trials": 100})
    assert r.status_code == 422 and "120000 trials is more than one batch may hold (2000)" in r.text
    assert time.perf_counter() - t0 < 5.0 and _nothing_recorded(client)
