"""Exports are listed (id, created, trial count, size on disk, download) and deleted with their files; one being
written is listed as such and refuses delete and download with 409; one a stopped server left half written is
listed `incomplete` and can be deleted (adversarial review L8)."""

from __future__ import annotations

import threading
import time
from pathlib import Path

import pytest
from fastapi.testclient import TestClient

import spark_core
from server.app import create_app

from .isolated_settings import isolated_settings


@pytest.fixture
def console(tmp_path):
    """A console whose store holds one captured, successful lift_block trial `t-cap`."""
    from spark_core.sim.capture import CaptureConfig
    from spark_core.trace import TraceStore
    from spark_core.trace.sink import StoreSink
    from spark_core.trial import TrialConfig, run_trial

    settings = isolated_settings(tmp_path)
    store = TraceStore(settings.store_url)
    config = TrialConfig("lift_block", segmenter="privileged-keypoints", capture=CaptureConfig(5, 64, 64))
    assert run_trial(config, [StoreSink(store, tmp_path / "art")], trial_id="t-cap").success
    with TestClient(create_app(settings)) as c:
        yield c, Path(settings.exports_dir)


def _on_disk(root: Path) -> int:
    return sum(p.stat().st_size for p in root.rglob("*") if p.is_file())


def test_exports_are_listed_and_deleted_with_their_files(console):
    c, exports = console
    assert c.get("/api/exports").json() == {"total": 0, "limit": 100, "offset": 0, "items": []}
    made = c.post("/api/exports", json={"trial_ids": ["t-cap"]}).json()
    (item,) = c.get("/api/exports").json()["items"]
    assert item["id"] == made["id"] and item["status"] == "ready" and item["download"] == made["download"]
    assert item["trials"] == 1 and item["frames"] == made["frames"] > 0 and item["batch"] is None
    assert item["bytes"] == _on_disk(exports / made["id"]) > made["bytes"]  # the dataset and its zip
    assert "T" in item["created_at"] and item["created_at"].endswith("+00:00")
    assert (exports / made["id"] / "export.json").is_file()
    (exports / made["id"] / "export.json").unlink()  # as written before exports kept a record: the dataset tells
    (legacy,) = c.get("/api/exports").json()["items"]
    assert legacy["status"] == "ready" and legacy["trials"] == 1 and legacy["frames"] == made["frames"]

    r = c.delete(f"/api/exports/{made['id']}")
    assert r.status_code == 200 and r.json() == {"id": made["id"], "bytes_freed": legacy["bytes"]}
    assert not (exports / made["id"]).exists() and c.get("/api/exports").json()["total"] == 0
    assert c.get(made["download"]).status_code == 404
    r = c.delete(f"/api/exports/{made['id']}")
    assert r.status_code == 404 and made["id"] in r.json()["detail"]
    for bad in ("export-nope", "export-..", "not-an-export", "export-0123456789"):
        assert c.delete(f"/api/exports/{bad}").status_code == 404
    assert c.delete("/api/exports/export-a%2F..%2F..%2Fs.db").status_code in (404, 405)  # no route takes a "/"
    assert (exports.parent / "s.db").is_file() and exports.is_dir()


def test_an_export_left_half_written_is_incomplete_and_can_be_deleted(console):
    c, exports = console
    (exports / "export-0123456789" / "dataset" / "data").mkdir(parents=True)  # a server stopped mid-write
    (item,) = c.get("/api/exports").json()["items"]
    assert item["status"] == "incomplete" and item["download"] is None and item["trials"] is None
    assert c.delete("/api/exports/export-0123456789").status_code == 200
    assert list(exports.iterdir()) == []


def test_an_export_being_written_cannot_be_deleted_or_downloaded(console, monkeypatch):
    c, exports = console
    go, real = threading.Event(), spark_core.export_lerobot

    def held(*args, **kwargs):  # the real export, once the test has looked at it while it was being written
        assert go.wait(30)
        return real(*args, **kwargs)

    monkeypatch.setattr(spark_core, "export_lerobot", held)
    answer: dict = {}
    writer = threading.Thread(target=lambda: answer.update(r=c.post("/api/exports", json={"trial_ids": ["t-cap"]})))
    writer.start()
    try:
        deadline = time.monotonic() + 30
        while not (items := c.get("/api/exports").json()["items"]):
            assert time.monotonic() < deadline, "the export never showed up as being written"
            time.sleep(0.05)
        (item,) = items
        assert item["status"] == "writing" and item["download"] is None
        r = c.delete(f"/api/exports/{item['id']}")
        assert r.status_code == 409 and "still being written" in r.json()["detail"]
        assert c.get(f"/api/exports/{item['id']}.zip").status_code == 409
    finally:
        go.set()
        writer.join(60)
    assert answer["r"].status_code == 201 and answer["r"].json()["id"] == item["id"]
    assert c.get("/api/exports").json()["items"][0]["status"] == "ready"
    assert c.delete(f"/api/exports/{item['id']}").status_code == 200


def test_two_deletes_of_one_export_at_once_free_it_once_and_answer_404_to_the_other(tmp_path, monkeypatch):
    """Both requests find the export; one removes it and reports every byte, the other answers 404 (they used to
    remove the same files together: 500s, and bytes_freed counted only part of the export)."""
    import server.api.exports as exports_api

    with TestClient(create_app(isolated_settings(tmp_path)), raise_server_exceptions=False) as c:
        root = tmp_path / "exports" / "export-0123456789"
        for i in range(50):
            (root / "dataset" / f"d{i}").mkdir(parents=True)
            (root / "dataset" / f"d{i}" / "f.bin").write_bytes(b"x" * 1000)
        (root / "export-0123456789.zip").write_bytes(b"z" * 500)
        both_found = threading.Barrier(2, timeout=30)
        real = exports_api._directory

        def found_together(request, export_id):
            path = real(request, export_id)
            both_found.wait()  # each request has checked that the export is there before either removes it
            return path

        monkeypatch.setattr(exports_api, "_directory", found_together)
        answers: list = []
        deleters = [
            threading.Thread(target=lambda: answers.append(c.delete("/api/exports/export-0123456789")))
            for _ in range(2)
        ]
        for t in deleters:
            t.start()
        for t in deleters:
            t.join(60)
        assert sorted(r.status_code for r in answers) == [200, 404], [r.text for r in answers]
        ok = next(r for r in answers if r.status_code == 200)
        assert ok.json() == {"id": "export-0123456789", "bytes_freed": 50 * 1000 + 500}
        assert list((tmp_path / "exports").iterdir()) == [] and c.get("/api/exports").json()["total"] == 0
