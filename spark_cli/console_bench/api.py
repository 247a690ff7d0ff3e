"""API latency with a large trace store: p50/p99 of list and get over a real SQLite file."""

from __future__ import annotations

import tempfile
import time
from datetime import UTC, datetime, timedelta

import numpy as np

from spark_core.bench.report import footer


def run(n_trials: int = 10_000, n_requests: int = 200) -> dict:
    from fastapi.testclient import TestClient

    from server.app import create_app
    from server.settings import Settings
    from spark_core.trace.models import EventRow, TrialRow
    from spark_core.trace.store import TraceStore

    tmp = tempfile.mkdtemp(prefix="spark-api-bench-")
    url = f"sqlite:///{tmp}/bench.db"
    store = TraceStore(url)
    t0 = datetime(2026, 1, 1, tzinfo=UTC)
    with store.Session.begin() as s:  # bulk insert: 10 events per trial, like a short plan
        s.add_all(
            TrialRow(
                id=f"t{i:06d}",
                created_at=t0 + timedelta(seconds=i),
                status="done",
                task=f"task{i % 14}",
                instruction=f"instruction {i}",
                success=bool(i % 3),
                outcome="success",
                wall_time_s=float(i % 50),
            )
            for i in range(n_trials)
        )
        s.add_all(
            EventRow(
                trial_id=f"t{i:06d}", seq=k, t=0.1 * k, node_path=f"tree.children[{k}]", kind="succeeded", detail={}
            )
            for i in range(n_trials)
            for k in range(10)
        )
    rng = np.random.default_rng(0)
    with TestClient(create_app(Settings(store_url=url, workers=1))) as c:

        def timed(path):
            t = time.perf_counter()
            assert c.get(path).status_code == 200
            return (time.perf_counter() - t) * 1000

        lists = [timed(f"/api/trials?limit=50&offset={int(rng.integers(0, n_trials - 50))}") for _ in range(n_requests)]
        filtered = [timed("/api/trials?limit=50&task=task3&success=true") for _ in range(n_requests)]
        gets = [timed(f"/api/trials/t{int(rng.integers(0, n_trials)):06d}") for _ in range(n_requests)]
    pct = lambda xs, q: float(np.percentile(xs, q))
    return {
        "trials": n_trials,
        "requests": n_requests,
        "list": (pct(lists, 50), pct(lists, 99)),
        "list_filtered": (pct(filtered, 50), pct(filtered, 99)),
        "get": (pct(gets, 50), pct(gets, 99)),
    }


def section(r: dict, command: str) -> str:
    rows = [
        ("list, 50 per page at a random offset", r["list"]),
        ("list filtered by task and success", r["list_filtered"]),
        ("get one trial with its events", r["get"]),
    ]
    table = "| request | p50 | p99 |\n|---|---|---|\n" + "\n".join(
        f"| {name} | {a:.1f} ms | {b:.1f} ms |" for name, (a, b) in rows
    )
    return (
        table
        + "\n\n"
        + footer(
            command,
            f"{r['trials']} trials with 10 events each in a SQLite (WAL) trace store; "
            f"{r['requests']} sequential requests each through FastAPI's TestClient (in-process HTTP)",
        )
    )
