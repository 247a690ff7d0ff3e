"""The store's times are UTC instants with their offset on every backend (API pass): on SQLite a `created_at` came
back naive (the API served it without an offset), a filter bound given with another offset was compared as its
own wall time, and the plan library's `t` read a naive UTC time as local time."""

from __future__ import annotations

import time
from datetime import UTC, datetime, timedelta, timezone

import pytest

from spark_core.trace import TraceStore

PLUS_5 = timezone(timedelta(hours=5))


def test_every_time_read_back_is_iso_8601_utc_with_its_offset(store_url):
    store = TraceStore(store_url)
    store.create_batch("b1", {"suite": "builtin"})
    store.create_trial("t1", task="lift_block", batch_id="b1")
    before = datetime.now(UTC)
    stamps = [
        store.get_trial("t1")["created_at"],
        store.list_trials()[1][0]["created_at"],
        store.get_batch("b1")["created_at"],
        store.get_batch("b1")["trials"][0]["created_at"],
        store.list_batches()[1][0]["created_at"],
    ]
    for stamp in stamps:
        assert stamp.endswith("+00:00"), stamp
        assert abs(datetime.fromisoformat(stamp) - before) < timedelta(minutes=1), stamp


def test_a_written_time_with_another_offset_is_the_same_instant(store_url):
    store = TraceStore(store_url)
    at = datetime(2026, 1, 2, 8, 34, 5, tzinfo=PLUS_5)  # 03:34:05 UTC
    store.create_trial("t1", task="lift_block", created_at=at)
    assert store.get_trial("t1")["created_at"] == "2026-01-02T03:34:05+00:00"
    store.create_trial("naive", task="lift_block", created_at=datetime(2026, 1, 2, 3, 34, 6))  # read as UTC
    assert store.get_trial("naive")["created_at"] == "2026-01-02T03:34:06+00:00"
    assert store.list_trials(sort="created_at")[1][0]["id"] == "t1"  # the order is the instants' order


def test_since_and_until_compare_instants_whatever_their_offset(store_url):
    store = TraceStore(store_url)
    store.create_trial("t1", task="lift_block")
    now = datetime.now(UTC)
    a_minute_ago, in_a_minute = now - timedelta(minutes=1), now + timedelta(minutes=1)
    # the same instants written at +05:00: SQLite compared their wall times (5 h ahead) with the stored UTC text
    assert store.trial_ids(since=a_minute_ago.astimezone(PLUS_5)) == ["t1"]
    assert store.trial_ids(until=a_minute_ago.astimezone(PLUS_5)) == []
    assert store.trial_ids(until=in_a_minute.astimezone(PLUS_5)) == ["t1"]
    # a naive bound is UTC, as is a date (its midnight)
    assert store.trial_ids(since=a_minute_ago.replace(tzinfo=None)) == ["t1"]
    assert store.trial_ids(since=in_a_minute.replace(tzinfo=None)) == []
    assert store.trial_ids(since=now.date(), until=now.date() + timedelta(days=1)) == ["t1"]


@pytest.fixture
def eastern_time(monkeypatch):
    """The process's local time zone set to UTC-05:00 (America/New_York in winter) for the test."""
    monkeypatch.setenv("TZ", "America/New_York")
    time.tzset()
    yield
    monkeypatch.undo()
    time.tzset()


def test_the_plan_librarys_times_are_unix_times_whatever_the_local_zone(tmp_path, eastern_time):
    store = TraceStore(f"sqlite:///{tmp_path / 'lib.db'}")
    store.add_library_plan("lift it", "task: t\ntree: {type: sequence, children: []}")
    t = store.library_plans()[0]["t"]
    assert abs(t - time.time()) < 60, t - time.time()  # a naive UTC time read as local was 5 h off
