"""Console API latency over real HTTP: a uvicorn server (its own process) on a SQLite store of 10,000 trials.

Measures sequential `GET /api/trials` (list) and `GET /api/trials/{id}` (get) p50/p99, then 200 list requests
sent at once (target: every one answered within 1 s): `spark bench api [--store-size 10000]`.
"""

from __future__ import annotations

import asyncio
import os
import socket
import subprocess
import sys
import tempfile
import time
from datetime import UTC, datetime, timedelta
from pathlib import Path

import httpx
import numpy as np

from spark_core.bench.report import footer

ROOT = Path(__file__).resolve().parents[2]


def seed_store(url: str, n_trials: int, n_events: int, trajectory_rows: int) -> None:
    """Trials shaped like real ones: a joint trajectory at the control rate, a plan, usage, events."""
    from sqlalchemy import insert

    from spark_core.trace.models import EventRow, TrialRow
    from spark_core.trace.store import TraceStore

    store = TraceStore(url)
    t0 = datetime(2026, 1, 1, tzinfo=UTC)
    trajectory = [[0.01 * k, "right", [0.1 * j + 0.001 * k for j in range(7)], 0.04] for k in range(trajectory_rows)]
    plan_tree = {"type": "sequence", "children": [{"type": "grasp", "params": {"object": "red_block"}}] * 6}
    known = {c.name for c in TrialRow.__table__.columns}  # the schema evolves: seed only the columns it has
    with store.engine.begin() as conn:
        for start in range(0, n_trials, 1000):
            ids = range(start, min(start + 1000, n_trials))
            conn.execute(
                insert(TrialRow),
                [
                    {k: v for k, v in row.items() if k in known}
                    for row in [
                        {
                            "id": f"t{i:06d}",
                            "created_at": t0 + timedelta(seconds=i),
                            "status": "done",
                            "task": f"task{i % 14}",
                            "instruction": f"put the red block on the blue block ({i})",
                            "seed": i,
                            "planner": "reference",
                            "resolver": "sim",
                            "protocol": {"planner": "reference", "segmenter": "sim", "privileged": True},
                            "plan_text": "task: t\ntree: {primitive: wait}\n" * 20,
                            "plan_tree": plan_tree,
                            "outcome": "success" if i % 3 else "task_unmet",
                            "success": bool(i % 3),
                            "reason": "",
                            "wall_time_s": float(i % 50),
                            "sim_time_s": 5.0,
                            "cost_usd": 0.0,
                            "usage": {"calls": 0},
                            "nodes": {"tree": {"duration_s": 5.0, "retries": 0}},
                            "trajectory": trajectory,
                            "artifacts": [],
                            "segmenter": "sim",
                            "verdict": "success" if i % 3 else "task_unmet",
                        }
                        for i in ids
                    ]
                ],
            )
            conn.execute(
                insert(EventRow),
                [
                    {
                        "trial_id": f"t{i:06d}",
                        "seq": k,
                        "t": 0.1 * k,
                        "node_path": f"tree.children[{k}]",
                        "kind": "succeeded",
                        "detail": {},
                    }
                    for i in ids
                    for k in range(n_events)
                ],
            )
    store.engine.dispose()


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def start_server(url: str, port: int) -> subprocess.Popen:
    env = {**os.environ, "SPARK_STORE_URL": url, "SPARK_VISER": "0", "SPARK_WORKERS": "1", "PYTHONPATH": str(ROOT)}
    cmd = [
        sys.executable,
        "-m",
        "uvicorn",
        "--factory",
        "server.app:create_app",
        "--host",
        "127.0.0.1",
        "--port",
        str(port),
        "--log-level",
        "warning",
        "--no-access-log",
        "--no-proxy-headers",
    ]
    proc = subprocess.Popen(cmd, env=env, cwd=ROOT)
    for _ in range(600):
        try:
            if httpx.get(f"http://127.0.0.1:{port}/api/health", timeout=1).status_code == 200:
                return proc
        except httpx.TransportError:
            time.sleep(0.1)
    proc.kill()
    raise RuntimeError("the server did not come up within 60 s")


def sequential(base: str, paths: list[str]) -> list[float]:
    """Latency (ms) of each request in turn over one keep-alive connection."""
    out = []
    with httpx.Client(base_url=base, timeout=30) as c:
        c.get(paths[0])  # warm-up: connection and first query
        for p in paths:
            t = time.perf_counter()
            r = c.get(p)
            out.append((time.perf_counter() - t) * 1000)
            assert r.status_code == 200, (p, r.status_code, r.text[:200])
    return out


async def concurrent(port: int, path: str, n: int) -> list[float]:
    """n requests sent at once on n open HTTP/1.1 connections; latency (ms) of each from the common start.
    A minimal asyncio client: httpx's AsyncClient itself needs ~4 s for 200 simultaneous requests here."""
    conns = [await asyncio.open_connection("127.0.0.1", port) for _ in range(n)]

    async def one(reader: asyncio.StreamReader, writer: asyncio.StreamWriter, t0: float) -> float:
        writer.write(f"GET {path} HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\n\r\n".encode())
        head = await reader.readuntil(b"\r\n\r\n")
        status = int(head.split(b" ", 2)[1])
        length = next(int(h.split(b":", 1)[1]) for h in head.split(b"\r\n") if h.lower().startswith(b"content-length:"))
        await reader.readexactly(length)
        assert status == 200, status
        return (time.perf_counter() - t0) * 1000

    t0 = time.perf_counter()
    try:
        return list(await asyncio.gather(*(one(r, w, t0) for r, w in conns)))
    finally:
        for _, w in conns:
            w.close()


def run(
    n_trials: int = 10_000,
    n_requests: int = 200,
    n_concurrent: int = 200,
    n_events: int = 10,
    trajectory_rows: int = 500,
) -> dict:
    """Latencies in ms: sequential list / page / filtered list / get, and `n_concurrent` lists at once."""
    tmp = tempfile.mkdtemp(prefix="spark-api-latency-")
    url = f"sqlite:///{tmp}/bench.db"
    t = time.perf_counter()
    seed_store(url, n_trials, n_events, trajectory_rows)
    seed_s = time.perf_counter() - t
    port = free_port()
    proc = start_server(url, port)
    base = f"http://127.0.0.1:{port}"
    rng = np.random.default_rng(0)
    try:
        rows = {
            "list, newest 50": sequential(base, ["/api/trials?limit=50"] * n_requests),
            "list, 50 at a random offset": sequential(
                base, [f"/api/trials?limit=50&offset={int(rng.integers(0, n_trials - 50))}" for _ in range(n_requests)]
            ),
            "list filtered by task and success": sequential(
                base, ["/api/trials?limit=50&task=task3&success=true"] * n_requests
            ),
            "get one trial with its events": sequential(
                base, [f"/api/trials/t{int(rng.integers(0, n_trials)):06d}" for _ in range(n_requests)]
            ),
        }
        burst = asyncio.run(concurrent(port, "/api/trials?limit=50", n_concurrent))
    finally:
        proc.terminate()
        proc.wait(10)
    rows[f"{n_concurrent} concurrent lists (from the common start)"] = burst
    pcts = {k: [float(np.percentile(v, 50)), float(np.percentile(v, 99)), float(max(v))] for k, v in rows.items()}
    return {
        "trials": n_trials,
        "requests": n_requests,
        "concurrent": n_concurrent,
        "events": n_events,
        "trajectory_rows": trajectory_rows,
        "seed_s": seed_s,
        "ms": pcts,
        "within_1s": sum(x <= 1000 for x in burst),
    }


def section(r: dict, command: str) -> str:
    lines = ["| request | p50 | p99 | max |", "|---|---|---|---|"]
    lines += [f"| {k} | {p50:.1f} ms | {p99:.1f} ms | {mx:.1f} ms |" for k, (p50, p99, mx) in r["ms"].items()]
    return (
        "\n".join(lines)
        + "\n\n"
        + footer(
            command,
            f"{r['within_1s']}/{r['concurrent']} concurrent list requests answered within 1 s (target: all; "
            f"list p50 target <= 15 ms). Store: {r['trials']} trials ({r['trajectory_rows']} trajectory rows, "
            f"{r['events']} events each), SQLite WAL; server: uvicorn in its own process on 127.0.0.1 (the defaults "
            f"of `spark serve`: one process, sync routes in its thread pool); sequential rows: {r['requests']} "
            f"requests each over one keep-alive connection (httpx); concurrent row: {r['concurrent']} connections "
            "opened first, then one request on each at once (asyncio streams)",
        )
    )
