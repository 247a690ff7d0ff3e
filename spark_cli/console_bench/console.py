"""The console as an operator sees it, measured in a real browser (Playwright driving Debian's headless chromium,
SwiftShader WebGL) against a real server (uvicorn, a trial worker process, the viser 3D view):

- Run -> first node shown running: the dashboard's Run button clicked, until the trial page's tree shows a node
  running (the next animation frame after it is in the DOM), at real-time pace;
- event -> screen with the 3D view on: an event's publication in the trial worker (its `wall_s`) until the
  animation frame after its row is in the trial page's event table (same machine clock), at real-time pace;
- 3D frame rate: animation frames the viser client (it renders on every frame) draws per second, while a trial
  runs and while its replay plays at 1x;
- dashboard and history load time with a store of `store_size` trials: navigation until the recent trials / the
  first history page are on screen.
"""

from __future__ import annotations

import os
import shutil
import statistics
import tempfile
import threading
import time
from pathlib import Path
from typing import Any

import numpy as np

from spark_core.bench.report import footer

from .api import free_port, seed_store

ROOT = Path(__file__).resolve().parents[2]
CHROMIUM_ARGS = [
    "--no-sandbox",
    "--use-angle=swiftshader",
    "--enable-unsafe-swiftshader",
    "--disable-background-networking",
]

# In the page: when a node is first shown running, and when each event's table row was first on screen.
WATCH_JS = """() => {
  const w = window; w.__firstRunning = null; w.__screen = {};
  const mark = () => {
    if (w.__firstRunning === null && document.querySelector('#tree .node.running'))
      requestAnimationFrame(() => { if (w.__firstRunning === null) w.__firstRunning = performance.now(); });
    const fresh = [...document.querySelectorAll('#event-table tr[data-seq]')]
      .filter((r) => !(r.dataset.seq in w.__screen));
    if (fresh.length) requestAnimationFrame(() => { const now = Date.now() / 1000;
      for (const r of fresh) if (!(r.dataset.seq in w.__screen)) w.__screen[r.dataset.seq] = now; });
  };
  new MutationObserver(mark).observe(document.body, { subtree: true, childList: true, attributes: true });
}"""
# Before any script of the page: each event's publication time as it arrives on a WebSocket, and the click on Run.
INIT_JS = """(() => { window.__wall = {}; window.__click = null; const W = window.WebSocket;
  window.WebSocket = function (...a) { const s = new W(...a); s.addEventListener('message', (m) => {
    try { const e = JSON.parse(m.data); if (e.seq !== undefined && e.wall_s) window.__wall[e.seq] = e.wall_s; }
    catch {} });
    return s; };
  window.WebSocket.prototype = W.prototype; Object.assign(window.WebSocket, W);
  document.addEventListener('click', (e) => {
    if (e.target.closest && e.target.closest('#new-trial button[type=submit]')) window.__click = performance.now();
  }, true); })();"""
COUNT_FRAMES_JS = """() => { window.__frames = 0; const f = () => { window.__frames++; requestAnimationFrame(f); };
  requestAnimationFrame(f); }"""


def _serve(store_url: str, artifacts: str, viser: bool) -> tuple[str, Any, threading.Thread]:
    import uvicorn

    from server.app import create_app
    from server.settings import Settings

    port = free_port()
    app = create_app(Settings(port=port, store_url=store_url, workers=1, artifacts_dir=artifacts, viser=viser))
    srv = uvicorn.Server(uvicorn.Config(app, host="127.0.0.1", port=port, log_level="warning"))
    thread = threading.Thread(target=srv.run, daemon=True)
    thread.start()
    while not srv.started:
        time.sleep(0.05)
    return f"http://127.0.0.1:{port}", srv, thread


def _post(page, base: str, path: str, body: dict) -> dict:
    r = page.request.post(base + path, data=body)
    if not r.ok:
        raise RuntimeError(f"POST {path}: {r.status} {r.text()}")
    return r.json()


def _viser_frame(page):
    el = page.wait_for_selector("#viser-frame")
    for _ in range(200):
        frame = el.content_frame()
        if frame is not None and frame.url not in ("", "about:blank"):
            frame.wait_for_load_state()
            return frame
        time.sleep(0.05)
    raise RuntimeError("the 3D view's frame did not load")


def _run_to_running(ctx, base: str, task: str) -> float:
    """Seconds from the click on Run to the first node shown running (real-time pace); the trial is then aborted."""
    page = ctx.new_page()
    try:
        page.goto(base + "/#/")
        page.click(f"button[data-task={task}]")
        page.select_option("#new-trial select[name=segmenter]", "privileged-keypoints")
        page.select_option("#new-trial select[name=pacing]", "1")
        page.evaluate(WATCH_JS)
        page.click("#new-trial button[type=submit]")
        page.wait_for_function("() => window.__firstRunning !== null", timeout=180_000)
        dt = page.evaluate("() => (window.__firstRunning - window.__click) / 1000")
        page.click("#abort")
        page.wait_for_selector("#status[data-status=done]", timeout=120_000)
        return float(dt)
    finally:
        page.close()


def _live_and_replay(ctx, base: str, task: str, seed: int) -> tuple[list[float], float, float]:
    """One trial watched live with the 3D view on: (event -> screen latencies s, 3D frames/s live, in replay)."""
    page = ctx.new_page()
    try:
        page.goto(base + "/")
        # real-time pace (as an operator watches): the replay at 1x then lasts as long as the trial's simulated
        # time, not the fraction of a second an unpaced trial takes
        body = {"task": task, "segmenter": "privileged-keypoints", "seed": seed, "start_paused": True, "pacing": 1.0}
        tid = _post(page, base, "/api/trials", body)["id"]
        page.goto(f"{base}/#/trial/{tid}")
        page.wait_for_selector("#tree .node.paused", timeout=180_000)
        frame = _viser_frame(page)
        page.evaluate(WATCH_JS)
        seen_before = set(page.evaluate("() => Object.keys(window.__wall)"))  # replayed at connect: not live
        frame.evaluate(COUNT_FRAMES_JS)
        t0 = time.perf_counter()
        page.click("#resume")
        page.wait_for_selector("#status[data-status=done]", timeout=600_000)
        live_fps = frame.evaluate("() => window.__frames") / (time.perf_counter() - t0)
        page.wait_for_timeout(500)  # the last rows' frames
        wall, screen = page.evaluate("() => [window.__wall, window.__screen]")
        lat = [screen[s] - wall[s] for s in wall if s in screen and s not in seen_before]
        page.select_option("#speed", "1")
        frame.evaluate("() => { window.__frames = 0; }")
        t0 = time.perf_counter()
        page.click("#play")
        page.wait_for_selector("#play:has-text('Pause replay')")
        page.wait_for_selector("#play:has-text('Play replay')", timeout=600_000)
        replay_fps = frame.evaluate("() => window.__frames") / (time.perf_counter() - t0)
        return lat, live_fps, replay_fps
    finally:
        page.close()


def _load_s(ctx, url: str, ready: str) -> float:
    page = ctx.new_page()
    try:
        t0 = time.perf_counter()
        page.goto(url)
        page.wait_for_selector(ready, timeout=120_000)
        return time.perf_counter() - t0
    finally:
        page.close()


def run(runs: int = 3, trials: int = 2, store_size: int = 10_000, task: str = "stack_two") -> dict:
    """`runs` Run clicks, `trials` watched trials (live, then replayed), `runs` loads of each page."""
    from playwright.sync_api import sync_playwright

    chromium = shutil.which("chromium-headless-shell") or shutil.which("chromium")
    if chromium is None:
        raise RuntimeError("Debian's chromium-headless-shell is missing (scripts/apt-deps.sh installs it)")
    if not (ROOT / "web" / "dist" / "index.html").is_file():
        raise RuntimeError("the front end is not built: run `make install` (or `cd web && npm run build`)")
    load_before = os.getloadavg()
    tmp = tempfile.mkdtemp(prefix="spark-console-bench-")
    out: dict[str, Any] = {"task": task, "store_size": store_size}
    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path=chromium, args=CHROMIUM_ARGS)
        ctx = browser.new_context(viewport={"width": 1400, "height": 1000})
        ctx.add_init_script(INIT_JS)
        base, srv, thread = _serve(f"sqlite:///{tmp}/live.db", f"{tmp}/art", viser=True)
        try:
            out["run_to_running_s"] = [_run_to_running(ctx, base, task) for _ in range(runs)]
            lat: list[float] = []
            out["fps_live"], out["fps_replay"] = [], []
            for k in range(trials):
                got, live, replay = _live_and_replay(ctx, base, task, seed=k)
                lat += got
                out["fps_live"].append(live)
                out["fps_replay"].append(replay)
            out["latency_s"] = lat
        finally:
            srv.should_exit = True
            thread.join(10)
        url = f"sqlite:///{tmp}/big.db"
        seed_store(url, store_size, n_events=10, trajectory_rows=100)
        base, srv, thread = _serve(url, f"{tmp}/art2", viser=False)
        try:
            out["dashboard_s"] = [_load_s(ctx, base + "/#/", "#recent tbody tr") for _ in range(runs)]
            out["history_s"] = [_load_s(ctx, base + "/#/history", "#rows tbody tr") for _ in range(runs)]
        finally:
            srv.should_exit = True
            thread.join(10)
        browser.close()
    shutil.rmtree(tmp, ignore_errors=True)
    out["load_before"], out["load_after"] = load_before, os.getloadavg()
    if not out["latency_s"]:
        raise RuntimeError("no live event reached the screen: nothing to report")
    return out


def _row(name: str, xs: list[float], unit: str, worst: str) -> str:
    scale, fmt = (1000.0, "{:.0f} ms") if unit == "ms" else (1.0, "{:.1f} " + unit)
    a = np.array(xs) * scale
    w = {"p99": np.percentile(a, 99), "max": a.max(), "min": a.min()}[worst]
    return f"| {name} | {len(xs)} | {fmt.format(statistics.median(a))} | {worst} {fmt.format(w)} |\n"


def section(r: dict, command: str) -> str:
    n = f"{r['store_size']:,}"
    runs = r["run_to_running_s"]  # the first Run also starts the server's trial worker process
    body = (
        "| measurement | samples | median | worst |\n|---|---|---|---|\n"
        + _row("Run clicked -> first node shown running, first Run after server start", runs[:1], "ms", "max")
        + (_row("Run clicked -> first node shown running, later Runs", runs[1:], "ms", "max") if runs[1:] else "")
        + _row("event -> screen, 3D view on (p50 / p99)", r["latency_s"], "ms", "p99")
        + _row("3D view frame rate during a trial", r["fps_live"], "fps", "min")
        + _row("3D view frame rate during replay (1x)", r["fps_replay"], "fps", "min")
        + _row(f"dashboard load, {n} trials in the store", r["dashboard_s"], "ms", "max")
        + _row(f"history load (first page of 50), {n} trials in the store", r["history_s"], "ms", "max")
    )
    lb, la = r["load_before"], r["load_after"]
    return (
        body
        + "\n"
        + footer(
            command,
            f"Playwright driving Debian's headless chromium (SwiftShader software WebGL, 1400x1000) against a "
            f"real server (uvicorn, one trial worker process, viser 3D view on for the live rows, lit by its "
            f"default lights: environment map off, SPARK_VISER_ENV_MAP unset); task "
            f"{r['task']}, reference plan, segmenter privileged-keypoints (PRIVILEGED). Run -> running: the click "
            f"on the dashboard's Run button (real-time pace) until the animation frame after a tree node shows "
            f"running, page already loaded; the first Run after the server starts also waits for its trial worker "
            f"process to start, later Runs find it idle (each trial is aborted once shown running). "
            f"Event -> screen: each event's publication time in the worker until "
            f"the animation frame after its row is in the event table, trial at real-time pace, events replayed at "
            f"connect excluded. Frame rate: animation frames of the viser client's document (it renders on each) "
            f"per second of wall time while the paced trial runs and while its replay plays at 1x (as long as "
            f"the trial), samples = trials. Loads: navigation in a new tab until the recent trials / "
            f"the first history page (50 rows, newest first) are in the DOM; the store is seeded with {n} "
            f"finished trials (10 events, 100 trajectory rows each). The machine was shared with other work: "
            f"load average {lb[0]:.1f} before and {la[0]:.1f} after the run (1 min), on "
            f"{os.cpu_count()} cores",
        )
    )
