"""Event latency from the executor to a browser: a real server, headless chromium holding the trial's
WebSocket, latency = browser receive time - event publish time (same machine clock)."""

from __future__ import annotations

import json
import shutil
import socket
import tempfile
import threading
import time
import urllib.request

import numpy as np

from spark_core.bench.report import footer


def run(trials: int = 3) -> dict:
    import uvicorn
    from playwright.sync_api import sync_playwright

    from server.app import create_app
    from server.settings import Settings

    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    app = create_app(Settings(port=port, store_url=f"sqlite:///{tempfile.mkdtemp()}/lat.db", workers=1))
    server = uvicorn.Server(uvicorn.Config(app, host="127.0.0.1", port=port, log_level="warning"))
    threading.Thread(target=server.run, daemon=True).start()
    while not server.started:
        time.sleep(0.05)
    base = f"http://127.0.0.1:{port}"
    chromium = shutil.which("chromium-headless-shell") or shutil.which("chromium")
    latencies: list[float] = []
    try:
        with sync_playwright() as p:
            browser = p.chromium.launch(
                executable_path=chromium, args=["--no-sandbox", "--disable-background-networking"]
            )
            page = browser.new_page()
            page.goto(base + "/api/health")
            for k in range(trials):
                req = urllib.request.Request(
                    base + "/api/trials",
                    method="POST",
                    headers={"content-type": "application/json"},
                    data=json.dumps(
                        {"task": "stack_two", "segmenter": "privileged-keypoints", "seed": k, "start_paused": True}
                    ).encode(),
                )
                trial_id = json.loads(urllib.request.urlopen(req).read())["id"]
                got = page.evaluate(
                    """async ([id, base]) => {
                    const lat = [];
                    await new Promise((done) => {
                      const ws = new WebSocket(base.replace('http', 'ws') + `/api/trials/${id}/events`);
                      ws.onopen = () => setTimeout(() => fetch(`/api/trials/${id}/control`, {method: 'POST',
                          headers: {'content-type': 'application/json'},
                          body: JSON.stringify({action: 'resume'})}), 300);
                      ws.onmessage = (m) => { const ev = JSON.parse(m.data);
                        if (ev.kind === 'closed') { done(); return; }
                        if (ev.kind !== 'paused' && ev.wall_s) lat.push(Date.now() / 1000 - ev.wall_s); };
                    });
                    return lat; }""",
                    [trial_id, base],
                )
                latencies += got[2:]  # the first events (tree start, the pause) predate the socket
            browser.close()
    finally:
        server.should_exit = True
    ms = np.array(latencies) * 1000
    return {
        "events": int(len(ms)),
        "p50_ms": float(np.median(ms)),
        "p99_ms": float(np.percentile(ms, 99)),
        "trials": trials,
    }


def section(r: dict, command: str) -> str:
    return (
        f"| events | p50 | p99 |\n|---|---|---|\n| {r['events']} | {r['p50_ms']:.1f} ms | {r['p99_ms']:.1f} ms |\n\n"
        + footer(
            command,
            f"executor event published in the trial worker process -> pipe -> console -> WebSocket -> "
            f"headless chromium "
            f"(Debian chromium-headless-shell, same machine clock); stack_two reference plan, segmenter "
            f"privileged-keypoints (PRIVILEGED), {r['trials']} trials; "
            "events replayed from history at connect are excluded",
        )
    )
