"""Every time the API serves carries its UTC offset (API pass: a trial's `created_at` came as
`2026-11-28T11:40:57.327413`, no zone, on the default SQLite store), in JSON and in the CSV export."""

from __future__ import annotations

import csv
import io
from dataclasses import replace
from datetime import UTC, datetime, timedelta, timezone

import pytest
from fastapi.testclient import TestClient

from server.app import create_app

from .isolated_settings import isolated_settings


@pytest.fixture()
def client(tmp_path):
    with TestClient(create_app(replace(isolated_settings(tmp_path), workers=0))) as c:
        yield c


def _utc(stamp: str) -> datetime:
    assert stamp.endswith("+00:00"), stamp
    return datetime.fromisoformat(stamp)


def test_created_at_is_utc_with_its_offset_in_every_endpoint_and_the_csv(client):
    store = client.app.state.store  # type: ignore[attr-defined]
    store.create_batch("batch-t", {"suite": "builtin", "trial_count": 2})
    early = datetime(2026, 1, 2, 8, 34, 5, tzinfo=timezone(timedelta(hours=5)))  # 03:34:05 UTC
    store.create_trial("t-early", task="lift_block", batch_id="batch-t", status="done", created_at=early)
    store.create_trial("t-now", task="lift_block", batch_id="batch-t", status="done", seed=1)
    now = datetime.now(UTC)
    items = client.get("/api/trials", params={"sort": "created_at"}).json()["items"]
    assert [i["id"] for i in items] == ["t-early", "t-now"]  # sorted as instants
    assert _utc(items[0]["created_at"]) == early and abs(_utc(items[1]["created_at"]) - now) < timedelta(minutes=1)
    assert [i["id"] for i in client.get("/api/trials").json()["items"]] == ["t-now", "t-early"]  # newest first
    assert _utc(client.get("/api/trials/t-early").json()["created_at"]) == early
    batch = client.get("/api/batches/batch-t").json()
    _utc(batch["created_at"])
    assert [_utc(t["created_at"]) for t in batch["trials"]][0] == early
    _utc(client.get("/api/batches").json()["items"][0]["created_at"])
    rows = list(csv.DictReader(io.StringIO(client.get("/api/batches/batch-t/trials.csv").text)))
    assert _utc(rows[0]["created_at"]) == early and rows[0]["created_at"] == "2026-01-02T03:34:05+00:00"
    deleted = client.delete("/api/trials/t-now").json()
    assert _utc(deleted["restore_until"]) > now
