"""The console in a real browser: Playwright driving Debian's headless chromium against a real server (uvicorn,
trial workers, the 3D view), through the built front end (web/dist, from `make install`)."""

import contextlib
import io
import json
import shutil
import socket
import threading
import time
import urllib.error
import urllib.request
import zipfile
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[2]
ARTIFACTS = ROOT / "test-artifacts"
APPS = []  # the app behind the `server` fixture, to look at its 3D view
CHROMIUM = shutil.which("chromium-headless-shell") or shutil.which("chromium")
NUDGE = """task: nudge the hand up
tree:
  type: sequence
  children:
    - type: move_relative
      params: {dz: 0.05}
"""


@pytest.fixture(scope="module")
def server(tmp_path_factory):
    import uvicorn

    from server.app import create_app
    from server.settings import Settings

    assert (ROOT / "web" / "dist" / "index.html").is_file(), "the front end is not built: run `make install`"
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    tmp = tmp_path_factory.mktemp("web")
    app = create_app(
        Settings(
            port=port,
            store_url=f"sqlite:///{tmp / 'ui.db'}",
            workers=2,
            artifacts_dir=str(tmp / "art"),
            exports_dir=str(tmp / "exports"),
        )
    )
    APPS.append(app)
    srv = uvicorn.Server(uvicorn.Config(app, host="127.0.0.1", port=port, log_level="warning"))
    thread = threading.Thread(target=srv.run, daemon=True)
    thread.start()
    for _ in range(200):
        if srv.started:
            break
        time.sleep(0.05)
    yield f"http://127.0.0.1:{port}"
    srv.should_exit = True
    thread.join(10)


@pytest.fixture(scope="module")
def browser():
    from playwright.sync_api import sync_playwright

    assert CHROMIUM, "Debian's chromium-headless-shell is missing: make test installs it (scripts/apt-deps.sh)"
    with sync_playwright() as p:
        b = p.chromium.launch(
            executable_path=CHROMIUM,
            args=[
                "--no-sandbox",
                "--use-angle=swiftshader",
                "--enable-unsafe-swiftshader",
                "--disable-background-networking",
            ],
        )
        yield b
        b.close()


@pytest.fixture
def page(browser, server):
    ctx = browser.new_context(viewport={"width": 1400, "height": 1000})
    # every WebSocket the page opens, to check that leaving a trial closes its stream
    ctx.add_init_script("""(() => { const W = window.WebSocket; window.sparkSockets = [];
        window.WebSocket = function (...a) { const s = new W(...a); window.sparkSockets.push(s); return s; };
        window.WebSocket.prototype = W.prototype; Object.assign(window.WebSocket, W); })();""")
    pg = ctx.new_page()
    yield pg
    ctx.close()


def shot(page, name):
    ARTIFACTS.mkdir(exist_ok=True)
    page.screenshot(path=str(ARTIFACTS / f"{name}.png"))


def _post(server, path, body):
    req = urllib.request.Request(
        server + path, method="POST", headers={"content-type": "application/json"}, data=json.dumps(body).encode()
    )
    return json.loads(urllib.request.urlopen(req).read())


def _wait_done(server, tid, timeout_s=180):
    for _ in range(int(timeout_s * 10)):
        t = json.loads(urllib.request.urlopen(f"{server}/api/trials/{tid}").read())
        if t["status"] == "done":
            return t
        time.sleep(0.1)
    raise AssertionError(f"{tid} did not finish")


def _grounding_images(page) -> list[str]:
    """The artifact names of the detection images shown for the grounding(s) in effect at the cursor, once loaded."""
    page.wait_for_function(
        "() => { const is = [...document.querySelectorAll('#grounding-now img.detection-image')];"
        " return is.length > 0 && is.every(i => i.complete && i.naturalWidth > 0); }"
    )
    srcs = page.eval_on_selector_all("#grounding-now img.detection-image", "is => is.map(i => i.src)")
    return [s.rsplit("/", 1)[1] for s in srcs]


def test_workspace_steps_breakpoints_then_scrubs_tree_camera_and_3d_together(server, page):
    page.goto(server + "/")
    page.click("button[data-task=stack_two]")
    page.select_option("#new-trial select[name=segmenter]", "sim")  # cameras + masks: the trial has detection images
    page.check("#new-trial input[name=start_paused]")
    page.click("#new-trial button[type=submit]")
    page.wait_for_url("**/#/trial/stack_two-*")
    page.wait_for_selector(".node.paused[data-path='tree.children[0]']", timeout=120_000)
    assert page.locator("#status").inner_text() == "paused"
    assert page.is_enabled("#step") and page.is_enabled("#resume") and not page.is_enabled("#pause")
    page.click(".node[data-path='tree.children[3]']")  # a breakpoint
    page.wait_for_selector(".node.breakpoint[data-path='tree.children[3]']")
    shot(page, "1-paused-with-breakpoint")
    page.click("#step")  # exactly one primitive runs, then it pauses again
    page.wait_for_selector(".node.paused[data-path='tree.children[1]']", timeout=120_000)
    assert page.locator("#tree .node.succeeded").count() == 1
    page.reload()  # a reopened page shows the state and the breakpoints already set
    page.wait_for_selector(".node.breakpoint[data-path='tree.children[3]']")
    page.wait_for_selector("#status[data-status=paused]")
    # The answer to this resume is held back until the trial has already paused at the breakpoint (as a loaded
    # server can deliver it): its stale "running" must not hide the newer pause and leave Resume disabled.
    held: list = []

    def hold(route):
        held.append((route, route.fetch()))

    page.route("**/control", hold)
    page.click("#resume")  # runs until the breakpoint
    page.wait_for_selector(".node.paused[data-path='tree.children[3]']", timeout=120_000)
    assert len(held) == 1 and held[0][1].json()["state"] == "running"
    held[0][0].fulfill(response=held[0][1])
    page.unroute("**/control", hold)
    page.wait_for_function("() => document.querySelector('#resume').disabled === false", timeout=10_000)
    page.wait_for_timeout(300)  # the late answer has been handled by now: it must not have switched to running
    assert page.locator("#status").inner_text() == "paused" and page.is_enabled("#resume")
    page.click("#resume")
    page.wait_for_selector("#verdict[data-verdict=success]", timeout=120_000)
    # finished: every control that can no longer act is disabled
    for b in ("#pause", "#step", "#resume", "#abort"):
        assert not page.is_enabled(b)
    trial_id = page.url.split("/trial/")[1]
    assert "width_m=" in page.locator("#tree .result[data-path='tree.children[2]']").inner_text()  # grasp's check
    # wall time without the paused spans: less than the record's, by at least the paused events' gaps
    events = json.loads(urllib.request.urlopen(f"{server}/api/trials/{trial_id}").read())["events"]
    paused_s = sum(nxt["t"] - e["t"] for e, nxt in zip(events, events[1:]) if e["kind"] == "paused")
    wall = json.loads(urllib.request.urlopen(f"{server}/api/trials/{trial_id}").read())["wall_time_s"]
    assert paused_s > 0.2 and abs(float(page.locator("#wall-active").inner_text()) - (wall - paused_s)) < 0.02
    scene = APPS[-1].state.scene
    for _ in range(100):  # the 3D view is bound to this trial's recorded scene
        if scene.current == f"replay:{trial_id}":
            break
        time.sleep(0.05)
    assert scene.current == f"replay:{trial_id}" and page.locator("#viser-frame").get_attribute("src") == "/viser/"
    assert page.locator("#timeline").get_attribute("data-bars") == "5"
    shot(page, "2-workspace-finished")
    at_end = {b: np.array(f.position) for b, f in scene._frames.items()}
    n_groundings_end = int(page.locator("#camera-panel").get_attribute("data-groundings"))
    assert n_groundings_end >= 2
    # each grounding keeps its own detection image: at the end, the last grounding's is shown with its candidates
    record = json.loads(urllib.request.urlopen(f"{server}/api/trials/{trial_id}").read())
    times = sorted({g["t_sim_s"] for g in record["groundings"]})
    assert len(times) >= 2, "stack_two grounds its labels at different times"
    imgs_end = _grounding_images(page)
    assert imgs_end and all(i.startswith(f"grounding-{n_groundings_end - 1:03d}-") for i in imgs_end)
    last = record["groundings"][-1]
    assert page.locator("#grounding-now").get_attribute("data-t") == str(last["t_sim_s"])
    kept = page.locator("#grounding-now table.candidates tr.chosen td").first.inner_text()
    assert kept == next(iter(last["cameras"].values()))["chosen"]
    # scrub to the start of the second node: the tree, the camera panel and the 3D view go back together
    t1 = float(page.locator("#event-table tr[data-kind=started]").nth(2).get_attribute("data-t"))
    page.locator("#scrub").fill(str(t1 + 1e-6))
    page.wait_for_selector(".node.running[data-path='tree.children[1]']")
    assert page.locator(".node.succeeded[data-path='tree.children[0]']").count() == 1
    assert page.locator(".node.pending[data-path='tree.children[4]']").count() == 1
    assert int(page.locator("#camera-panel").get_attribute("data-groundings")) < n_groundings_end
    imgs_mid = _grounding_images(page)  # an earlier grounding's image: the one in effect at the cursor
    assert imgs_mid and imgs_mid != imgs_end
    t_mid = float(page.locator("#grounding-now").get_attribute("data-t"))
    cursor_sim = float(page.locator("#cursor-time").inner_text().split("·")[1].split()[0])
    assert t_mid < last["t_sim_s"] and t_mid <= cursor_sim + 0.005  # the latest at or before the cursor
    assert page.locator("#grounding-now table.candidates tbody tr").count() >= 1
    # inside the first node: the earlier grounding in effect; a re-detection of the same label has its own image
    # (not "just before t1": the step's pause sits there, where sim time stands still at the next grounding's time)
    t0 = float(page.locator("#event-table tr[data-kind=started]").nth(1).get_attribute("data-t"))
    t0_end = float(page.locator("#event-table tr[data-kind=succeeded]").first.get_attribute("data-t"))
    assert t0 < t0_end < t1
    page.locator("#scrub").fill(str((t0 + t0_end) / 2))
    page.wait_for_function(f"() => document.querySelector('#grounding-now').dataset.t !== '{t_mid}'")
    imgs_before = _grounding_images(page)
    assert imgs_before and imgs_before != imgs_mid
    g_before = int(page.locator("#grounding-now").get_attribute("data-indices").split(",")[0])
    g_mid = int(imgs_mid[0].split("-")[1])
    assert g_before < g_mid and record["groundings"][g_before]["label"] == record["groundings"][g_mid]["label"]
    page.locator("#scrub").fill(str(t1 + 1e-6))
    page.wait_for_selector(".node.running[data-path='tree.children[1]']")
    assert _grounding_images(page) == imgs_mid
    for _ in range(100):
        moved = max(np.abs(np.array(f.position) - at_end[b]).max() for b, f in scene._frames.items())
        if moved > 0.01:
            break
        time.sleep(0.05)
    assert moved > 0.01, "the 3D view did not follow the cursor"
    assert page.locator("#event-table tr.future").count() > 0
    # the cameras at the cursor: rendered from the recorded state at that time
    page.wait_for_function(
        "() => [...document.querySelectorAll('#camera-at-cursor img')].some(i => i.complete && i.naturalWidth > 0)"
    )
    before = page.get_attribute("#camera-at-cursor img", "src")
    page.locator("#tree-pane").click()  # ← / → step the cursor through the events
    page.keyboard.press("ArrowRight")
    page.wait_for_selector(".node.succeeded[data-path='tree.children[1]']")
    assert page.get_attribute("#camera-at-cursor img", "src") != before
    page.keyboard.press("ArrowLeft")
    page.wait_for_selector(".node.running[data-path='tree.children[1]']")
    # the 3D view shows the image of the grounding in effect, as the camera panel does
    assert scene.image_key == f"replay:{trial_id}" and _grounding_images(page) == imgs_mid
    page.wait_for_timeout(800)  # let the embedded viser client draw the image before the screenshot
    shot(page, "3-workspace-scrubbed")
    # play the replay at 4x: the cursor advances and the 3D view follows it
    scrubbed = {b: np.array(f.position) for b, f in scene._frames.items()}
    page.select_option("#speed", "4")
    page.click("#play")
    page.wait_for_selector(".node.succeeded[data-path='tree.children[2]']", timeout=30_000)
    for _ in range(100):
        moved = max(np.abs(np.array(f.position) - scrubbed[b]).max() for b, f in scene._frames.items())
        if moved > 0.01:
            break
        time.sleep(0.05)
    assert moved > 0.01, "the 3D view did not follow the playing replay"
    # a legend names every colour; the event table filters by kind and by text
    legend = page.locator("#legend").inner_text()
    assert all(s in legend for s in ("pending", "running", "succeeded", "failed", "aborted", "paused", "breakpoint"))
    n_events = page.locator("#event-table tbody tr").count()
    page.select_option("select[name=event-kind]", "succeeded")
    kinds = page.eval_on_selector_all("#event-table tbody tr", "rs => rs.map(r => r.dataset.kind)")
    assert kinds and set(kinds) == {"succeeded"} and len(kinds) < n_events
    page.select_option("select[name=event-kind]", "")
    page.fill("input[name=event-filter]", "tree.children[2]")
    nodes = page.eval_on_selector_all("#event-table tbody tr", "rs => rs.map(r => r.cells[3].innerText)")
    assert nodes and set(nodes) == {"tree.children[2]"}
    page.fill("input[name=event-filter]", "")
    # the tree collapses; the panes resize by their handles
    page.click("#tree .twisty")
    assert page.locator("#tree .node[data-path='tree.children[0]']").count() == 0
    page.click("#tree .twisty")
    assert page.locator("#tree .node[data-path='tree.children[0]']").count() == 1
    width = page.locator("#tree-pane").bounding_box()["width"]
    handle = page.locator(".panes > .handle").first.bounding_box()
    page.mouse.move(handle["x"] + handle["width"] / 2, handle["y"] + 100)
    page.mouse.down()
    page.mouse.move(handle["x"] + 150, handle["y"] + 100, steps=5)
    page.mouse.up()
    assert page.locator("#tree-pane").bounding_box()["width"] > width + 100
    # leaving the page closes its event stream
    page.goto(server + "/#/history")
    page.wait_for_selector("#rows table")
    assert page.evaluate(
        "window.sparkSockets.filter(s => s.url.includes('/api/trials/')).every(s => s.readyState >= 2)"
    )


# At every animation frame (what is painted, not just what is in the DOM): the tree's nodes shown running.
PAINTED_RUNNING_JS = """(() => { window.__painted = new Set(); const f = () => {
  document.querySelectorAll('#tree .node.running').forEach((n) => window.__painted.add(n.dataset.path));
  requestAnimationFrame(f); }; requestAnimationFrame(f); })();"""


def test_a_watched_trial_paints_each_node_running_with_the_3d_view_on(server, page):
    """The bug: with the 3D view on, tree updates reached the screen in one burst (the viser client's
    environment-map setup stalled the page's frames for seconds after it loaded). Run from the dashboard at
    half real time: every leaf of the tree is painted running in some frame while the trial runs."""
    page.add_init_script(PAINTED_RUNNING_JS)
    page.goto(server + "/")
    page.click("button[data-task=stack_two]")
    page.select_option("#new-trial select[name=segmenter]", "privileged-keypoints")
    page.select_option("#new-trial select[name=pacing]", "0.5")
    page.click("#new-trial button[type=submit]")
    page.wait_for_url("**/#/trial/stack_two-*")
    page.wait_for_selector("#viser-frame")
    page.wait_for_selector("#verdict[data-verdict=success]", timeout=120_000)
    painted = set(page.evaluate("() => [...window.__painted]"))
    leaves = {f"tree.children[{i}]" for i in range(5)}
    assert leaves <= painted, f"never painted running: {sorted(leaves - painted)}"


def test_abort_shows_aborted_everywhere(server, page):
    page.goto(server + "/")
    page.click("button[data-task=stack_three]")
    page.select_option("#new-trial select[name=segmenter]", "privileged-keypoints")
    page.select_option("#new-trial select[name=pacing]", "0.25")  # watchable: a quarter of real time
    page.click("#new-trial button[type=submit]")
    page.wait_for_url("**/#/trial/stack_three-*")
    tid = page.url.split("/trial/")[1]
    page.wait_for_selector("#tree .node.running[data-path='tree.children[0]']", timeout=120_000)
    # pause works at this pace too (before the next node), then resume; abort while that node runs
    page.click("#pause")
    page.wait_for_selector("#tree .node.paused[data-path='tree.children[1]']", timeout=60_000)
    assert page.locator("#status").inner_text() == "paused" and page.is_enabled("#step")
    page.click("#resume")
    page.wait_for_selector("#tree .node.running[data-path='tree.children[1]']", timeout=60_000)
    assert page.locator("#status").inner_text() == "running"
    page.click("#abort")
    page.wait_for_selector("#verdict[data-verdict=aborted]", timeout=60_000)
    assert page.locator("#status").inner_text() == "done"
    assert page.locator("#tree .node.running, #tree .node.paused").count() == 0
    assert page.locator("#tree .node.aborted").count() >= 1
    assert page.locator("#explanation").inner_text() == "Aborted by the operator."  # said once
    assert not page.is_enabled("#abort") and not page.is_enabled("#pause")
    record = json.loads(urllib.request.urlopen(f"{server}/api/trials/{tid}").read())
    assert "0.25" in str(record["protocol"]["pacing"])
    page.goto(f"{server}/#/history")
    page.wait_for_selector(f"#rows tr[data-id='{tid}'] [data-verdict=aborted]")


def test_planner_error_and_unmet_condition_are_explained(server, page):
    page.goto(server + "/")
    page.click("button[data-task=lift_block]")
    page.select_option("#new-trial select[name=planner]", "rules")
    page.fill("#new-trial input[name=instruction]", "sing the anthem loudly")
    page.click("#new-trial button[type=submit]")
    page.wait_for_selector("#verdict[data-verdict=planner_error]", timeout=120_000)
    assert "What it said: no plan" in page.locator("#explanation").inner_text()
    assert "No plan" in page.locator("#no-plan").inner_text() and "waiting" not in page.locator("#no-plan").inner_text()
    shot(page, "4-planner-error")
    # your own plan, validated as you type, the error on its own line; every node passes, the task is unmet
    page.goto(server + "/")
    page.click("button[data-task=lift_block]")
    page.select_option("#new-trial select[name=segmenter]", "privileged-keypoints")
    page.click("#new-trial summary:has-text('Run your own plan')")
    page.click("#node-palette button[data-primitive=pick]")  # the registry's palette writes a leaf
    assert "- type: pick" in page.input_value("#new-trial textarea[name=plan]")
    page.wait_for_selector("#plan-ok")
    page.fill("#new-trial textarea[name=plan]", NUDGE.replace("dz: 0.05", "dz: 9"))
    page.wait_for_selector("#plan-errors li")
    assert page.locator(".plan-lines li.error-line").get_attribute("data-path").startswith("tree.children[0].params")
    assert not page.is_enabled("#new-trial button[type=submit]")
    page.fill("#new-trial textarea[name=plan]", NUDGE)
    page.wait_for_selector("#plan-ok")
    page.click("#new-trial button[type=submit]")
    page.wait_for_selector("#verdict[data-verdict=task_unmet]", timeout=120_000)
    text = page.locator("#explanation").inner_text()
    assert "Every node of the tree passed" in text and "red block bottom > 5 cm above the table and held" in text
    assert page.locator("#tree .node.failed").count() == 0
    shot(page, "5-task-unmet")


def test_dashboard_groups_and_searches_tasks(server, page):
    page.goto(server + "/")
    page.wait_for_selector("#task-browser details[data-suite=builtin]")
    assert page.locator("#task-browser details").count() >= 3
    page.fill("input[name=task-search]", "drawer")
    names = page.eval_on_selector_all("#task-browser button.task-item", "bs => bs.map(b => b.dataset.task)")
    assert {"open_drawer", "close_drawer", "block_in_drawer"} <= set(names) and "lift_block" not in names
    page.click("button[data-task=open_drawer]")
    assert "open_drawer" in page.locator("#task-card h3").inner_text() and page.locator("#task-predicate").inner_text()
    page.wait_for_function(
        "() => { const i = document.querySelector('#task-card img.preview');"
        " return i && i.complete && i.naturalWidth > 0; }"
    )
    shot(page, "6-dashboard")


def test_batch_is_found_again_from_the_batch_list(server, page):
    page.goto(server + "/")
    page.wait_for_selector("#new-batch select[name=tasks]")
    page.select_option("#new-batch select[name=tasks]", ["lift_block", "push_to_zone"])
    page.fill("#new-batch input[name=trials]", "2")
    page.select_option("#new-batch select[name=segmenter]", "privileged-keypoints")
    page.click("#new-batch button[type=submit]")
    page.wait_for_url("**/#/batch/batch-*")
    batch_id = page.url.split("/batch/")[1]
    page.wait_for_selector("#batch-count:has-text('4 / 4 · done')", timeout=180_000)
    assert not page.is_enabled("#batch-cancel") and page.is_enabled("#export-selected")
    page.goto(server + "/#/")
    page.click("a[href='#/batches']")
    page.click(f"#batch-list a[href='#/batch/{batch_id}']")
    page.wait_for_selector("#batch-table tbody tr")
    rows = page.locator("#batch-table tbody tr")
    assert (
        rows.count() == 2
        and "100.0 %" in rows.nth(0).inner_text()
        and "%" in rows.nth(0).locator("td").nth(3).inner_text()
    )
    assert page.locator("#batch-trials a[href^='#/trial/']").count() == 4
    assert page.locator("#success-chart canvas").count() == 1  # success per task with its interval (uPlot)
    page.wait_for_selector("#timing-chart canvas")  # time per primitive, stacked per task
    assert "pick" in page.locator("#timing-chart .legend").inner_text()
    page.wait_for_selector("#phase-chart canvas")  # and per pipeline phase, next to it
    assert {"setup", "planning", "execution"} <= set(page.locator("#phase-chart .legend").inner_text().split())
    assert "privileged-keypoints" in page.locator("#batch-settings").inner_text()
    shot(page, "7-batch")
    with page.expect_download() as dl:
        page.click("#batch-results-csv")
    text = Path(dl.value.path()).read_text()
    assert text.startswith("task,done,total,successes") and "lift_block,2,2,2" in text
    page.click("#batch-trials a[href^='#/trial/']")
    page.wait_for_selector("#verdict")


def test_a_cancelled_batch_shows_aborted_on_its_page_its_trials_and_the_batch_list(server, page):
    """Cancel only while running; the trials it stopped say aborted on the batch page (which keeps polling
    until each has settled), on their own page (header, tree) and the batch list says cancelled."""
    page.goto(server + "/")
    page.wait_for_selector("#new-batch select[name=tasks]")
    page.select_option("#new-batch select[name=tasks]", ["stack_three"])
    page.fill("#new-batch input[name=trials]", "6")
    page.select_option("#new-batch select[name=segmenter]", "privileged-keypoints")
    page.click("#new-batch button[type=submit]")
    page.wait_for_url("**/#/batch/batch-*")
    batch_id = page.url.split("/batch/")[1]
    page.wait_for_selector("#batch-cancel:enabled")  # running: cancel can act
    page.click("#batch-cancel")
    page.wait_for_selector("#batch-count:has-text('cancelled')")
    assert not page.is_enabled("#batch-cancel")
    page.wait_for_function(  # every trial settles with a verdict, without reloading the page
        "() => { const rs = [...document.querySelectorAll('#batch-trials tbody tr')];"
        " return rs.length === 6 && rs.every(r => r.querySelector('[data-verdict]')); }",
        timeout=120_000,
    )
    aborted = page.locator("#batch-trials tbody tr:has([data-verdict=aborted])")
    assert aborted.count() >= 1
    tid = aborted.first.get_attribute("data-id")
    page.click("a[href='#/batches']")
    assert "cancelled" in page.locator(f"#batch-list tr[data-id='{batch_id}']").inner_text()
    page.goto(f"{server}/#/trial/{tid}")
    page.wait_for_selector("#verdict[data-verdict=aborted]")
    # a trial cancelled before it started says so ("...: cancelled before it started"); one that was running
    # when the batch was cancelled says it was aborted: either way, said once
    explanation = page.locator("#explanation").inner_text()
    assert explanation.startswith("Aborted by the operator") and explanation.lower().count("aborted by") == 1
    assert page.locator("#tree .node.running, #tree .node.paused").count() == 0
    assert f"#/batch/{batch_id}" in page.locator(".trial-header").inner_html()


def test_planner_fields_follow_the_chosen_planner(server, page):
    """An LLM planner asks for its model (its default as placeholder) and one of the operator's endpoints; an
    offline one asks for neither; the batch form offers the same planners."""
    page.goto(server + "/")
    page.click("button[data-task=lift_block]")
    planners = page.eval_on_selector_all("#new-trial select[name=planner] option", "os => os.map(o => o.value)")
    assert {"reference", "rules", "openai"} <= set(planners)
    page.select_option("#new-trial select[name=planner]", "rules")
    assert page.locator("#new-trial input[name=model]").count() == 0
    page.select_option("#new-trial select[name=planner]", "openai")
    assert page.locator("#new-trial input[name=model]").get_attribute("placeholder")
    assert page.locator("#new-trial select[name=endpoint] option").first.inner_text() == "vendor default"
    batch = page.eval_on_selector_all("#new-batch select[name=planner] option", "os => os.map(o => o.value)")
    assert batch == planners


def _rows_once_sorted(page, cells_js: str, timeout_s: float = 15.0) -> list:
    """The history rows' cells once they come back in ascending order, or the last ones seen after `timeout_s`
    (the caller's assertion then fails, showing them)."""
    deadline = time.monotonic() + timeout_s
    while True:
        cells = page.eval_on_selector_all("#rows tbody tr", cells_js)
        if cells == sorted(cells) or time.monotonic() > deadline:
            return cells
        page.wait_for_timeout(100)


def test_history_sorts_filters_pages_and_compares(server, page):
    a = _post(server, "/api/trials", {"task": "lift_block", "segmenter": "privileged-keypoints", "seed": 1})["id"]
    b = _post(server, "/api/trials", {"task": "lift_block", "segmenter": "privileged-keypoints", "plan": NUDGE})["id"]
    _wait_done(server, a), _wait_done(server, b)
    store = APPS[-1].state.store  # enough finished records for two pages
    for i in range(60):
        store.create_trial(
            f"filler-{i:03d}",
            status="done",
            task="push_to_zone",
            instruction="push",
            seed=1000 + i,
            planner="reference",
            segmenter="sim",
            outcome="success",
            success=True,
            verdict="success",
        )
    page.goto(server + "/#/history")
    page.wait_for_selector("#rows table")
    total = int(page.locator("#page-info").inner_text().split()[0])
    assert total >= 62 and "1–50" in page.locator("#page-info").inner_text()
    page.click("#next")
    page.wait_for_selector(f"#page-info:has-text('51–{min(100, total)}')")
    assert page.locator("#rows tbody tr").count() == min(50, total - 50)
    page.click("#prev")
    page.wait_for_selector("#page-info:has-text('1–50')")
    page.click("th[data-sort=seed]")
    page.wait_for_selector("th[data-sort=seed]:has-text('▲')")
    # the arrow shows at once, the rows when the server's sorted page arrives
    seeds = _rows_once_sorted(page, "rs => rs.map(r => +r.cells[6].innerText)")
    assert seeds == sorted(seeds)
    for key in ("batch_id", "failure"):  # sorted by the server (SQLite: empty first)
        page.click(f"th[data-sort={key}]")
        page.wait_for_selector(f"th[data-sort={key}]:has-text('▲')")
        col = page.eval_on_selector_all("#rows thead th", f"hs => hs.findIndex(h => h.dataset.sort === '{key}')")
        cells = _rows_once_sorted(page, f"rs => rs.map(r => r.cells[{col}].innerText)")
        assert cells == sorted(cells)
    page.click("#verdict-filters button[data-verdict=task_unmet]")
    # the server's answer: only that verdict, b among them
    page.wait_for_function(
        "() => { const vs = [...document.querySelectorAll('#rows tbody [data-verdict]')].map(v => v.dataset.verdict);"
        " return vs.length > 0 && vs.every(v => v === 'task_unmet'); }"
    )
    assert page.locator(f"#rows tr[data-id='{b}']").count() == 1
    page.click("#verdict-filters button:has-text('any')")
    page.click("th[data-sort=created_at]")  # newest first again (a second click: descending)
    page.click("th[data-sort=created_at]")
    page.wait_for_selector("th[data-sort=created_at]:has-text('▼')")
    page.fill("#filters input[name=q]", "lift_block")  # the fillers are newer: search for the two
    page.wait_for_selector(f"#rows tr[data-id='{a}']")
    page.check(f"#rows .pick[value='{a}']")
    page.check(f"#rows .pick[value='{b}']")
    page.click("#compare")
    page.wait_for_selector("#divergence")
    assert "tree.children[0]" in page.locator("#divergence").inner_text()
    assert page.locator("#plan-diff .added").count() > 0 and page.locator("#plan-diff .removed").count() > 0
    assert int(page.locator("#compare-timeline").get_attribute("data-bars")) >= 2
    shot(page, "8-compare")


def test_history_selection_exports_a_lerobot_dataset(server, page):
    body = {"task": "lift_block", "segmenter": "privileged-keypoints", "capture": True}
    tid = _post(server, "/api/trials", body)["id"]
    _wait_done(server, tid)
    page.goto(server + "/#/history")
    page.wait_for_selector(f"#rows .pick[value='{tid}']")
    page.check(f"#rows .pick[value='{tid}']")
    page.click("#export-selected")
    page.wait_for_selector("#export-download", timeout=120_000)
    assert "1 episode(s)" in page.locator("#export-result").inner_text()
    with page.expect_download() as dl:
        page.click("#export-download")
    z = zipfile.ZipFile(io.BytesIO(Path(dl.value.path()).read_bytes()))
    assert json.loads(z.read("meta/info.json"))["total_episodes"] == 1
    # the result belongs to the selection it was made from: another selection does not show it as its own
    page.uncheck(f"#rows .pick[value='{tid}']")
    page.wait_for_selector("#export-download", state="detached")
    assert page.locator("#export-result").inner_text() == ""


def test_the_reference_planner_takes_no_instruction(server, page):
    """The reference planner runs the task's hand-written plan: an instruction typed for it would be recorded as
    what ran while the robot did something else. The field is off (and says why) until a planner that reads it,
    or a plan of one's own, is chosen; the server refuses one anyway, shown inline."""
    page.goto(server + "/")
    page.click("button[data-task=lift_block]")
    field = "#new-trial input[name=instruction]"
    assert page.input_value("#new-trial select[name=planner]") == "reference"
    assert page.is_disabled(field) and "reads no instruction" in page.locator("#instruction-note").inner_text()
    page.select_option("#new-trial select[name=planner]", "rules")
    assert page.is_enabled(field) and page.locator("#instruction-note").count() == 0
    page.fill(field, "put the red block on the blue block")
    page.select_option("#new-trial select[name=planner]", "reference")
    assert page.is_disabled(field)
    page.click("#new-trial summary:has-text('Run your own plan')")
    page.fill("#new-trial textarea[name=plan]", NUDGE)
    assert page.is_enabled(field)  # with a plan of one's own the instruction is its label
    page.fill("#new-trial textarea[name=plan]", "")
    page.evaluate(f"document.querySelector('{field}').disabled = false")  # past the form: the server says no
    page.click("#new-trial button[type=submit]")
    page.wait_for_selector("#form-error:has-text('the reference planner runs')")
    assert "#/trial/" not in page.url  # nothing was queued


def test_compare_never_shows_the_pair_it_left(server, page):
    """Going from one comparison to another while the first one's records are still on their way: the page shows
    the pair in its address, never the earlier pair's answer arriving late."""
    a = _post(server, "/api/trials", {"task": "lift_block", "segmenter": "privileged-keypoints", "plan": NUDGE})["id"]
    b = _post(server, "/api/trials", {"task": "lift_block", "segmenter": "privileged-keypoints", "seed": 5})["id"]
    _wait_done(server, a), _wait_done(server, b)
    page.goto(server + "/")
    page.wait_for_selector("#new-trial")
    # the first request for trial `a` (the first pair's) answers 1.5 s late
    page.evaluate(
        """(slow) => { const f = window.fetch; let first = true;
        window.fetch = (url, ...rest) => {
          if (first && String(url).endsWith('/api/trials/' + slow)) {
            first = false;
            return new Promise((ok) => setTimeout(ok, 1500)).then(() => f(url, ...rest));
          }
          return f(url, ...rest); }; }""",
        a,
    )
    page.evaluate(f"location.hash = '#/compare/{a}/{b}'")
    page.wait_for_timeout(100)
    page.evaluate(f"location.hash = '#/compare/{b}/{a}'")
    page.wait_for_selector(".compare tbody tr")
    page.wait_for_timeout(2500)  # past the late answer
    rows = page.eval_on_selector_all(".compare tbody tr td:nth-child(2)", "ts => ts.map(t => t.innerText)")
    assert rows == [b, a]


def test_form_reports_server_errors(server, page):
    page.goto(server + "/")
    page.wait_for_selector("#new-trial")
    page.evaluate("document.querySelector('#new-trial input[name=seed]').removeAttribute('min')")
    page.fill("#new-trial input[name=seed]", "-3")
    page.click("#new-trial button[type=submit]")
    page.wait_for_selector("#form-error:has-text('seed')")


def test_a_protocol_is_offered_on_its_suite_and_a_privileged_segmenter_under_it_is_refused(server, page):
    """The paper's protocols come from the catalog, only on the suites they are defined on; the server's refusal
    (a privileged segmenter under s2) is shown inline, naming why."""
    page.goto(server + "/")
    page.wait_for_selector("#task-browser details[data-suite=builtin]")
    page.fill("input[name=task-search]", "lift_block")
    page.click("button[data-task=lift_block]")
    page.wait_for_selector("#new-trial")
    assert page.locator("#new-trial select[name=protocol]").count() == 0  # no protocol is defined on builtin
    page.fill("input[name=task-search]", "Lift")
    page.click("button[data-task=Lift]")
    page.wait_for_selector("#new-trial select[name=protocol] option[value=s2]", state="attached")
    page.select_option("#new-trial select[name=protocol]", "s2")
    page.select_option("#new-trial select[name=segmenter]", "sim")
    page.click("#new-trial button[type=submit]")
    page.wait_for_selector("#form-error:has-text('privileged')")


def test_an_llm_trials_planner_calls_and_the_image_its_bt_call_got_are_shown(server, page, tmp_path):
    """A trial planned by the real openai client against a loopback server (recorded into the console's store):
    its page lists both calls (synthesis, then the BT call) and shows the annotated image the BT call got."""
    from spark_core.trace.sink import StoreSink
    from spark_core.trial import run_trial
    from tests.doubles.fake_openai import FakeOpenAI
    from tests.test_paper_loop import PLAN, SYNTHESIS, _config

    store = APPS[-1].state.store
    with FakeOpenAI() as fake:
        fake.script = [("ok", json.dumps(SYNTHESIS)), ("ok", json.dumps(PLAN))]
        out = run_trial(_config(fake), [StoreSink(store, tmp_path / "art")])
    page.goto(f"{server}/#/trial/{out.trial_id}")
    page.click("#planner-calls summary")
    kinds = page.eval_on_selector_all("#planner-calls .planner-call", "ds => ds.map(d => d.dataset.kind)")
    assert kinds == ["prompt_synthesis", "behavior_tree"]
    page.wait_for_function(
        "() => { const i = document.querySelector('#planner-calls img.planner-image');"
        " return i && i.complete && i.naturalWidth > 0; }"
    )


def test_api_docs_work_offline(server, page):
    requested = []

    def only_local(route):
        requested.append(route.request.url)
        if route.request.url.startswith(server):
            route.continue_()
        else:
            route.abort()

    page.route("**/*", only_local)
    page.goto(server + "/docs")
    page.wait_for_selector(".swagger-ui .info .title", timeout=30_000)
    assert "SPARK console" in page.locator(".swagger-ui .info .title").inner_text()
    assert all(u.startswith(server) for u in requested), [u for u in requested if not u.startswith(server)]


def test_a_live_trials_camera_panel_shows_each_grounding_as_it_is_made(server, page):
    """While the trial runs (paused after its first node), the camera panel already shows that node's grounding:
    its detection image and prompt candidates, stored as the grounding was made, not only at the end."""
    page.goto(server + "/")
    page.click("button[data-task=stack_two]")
    page.select_option("#new-trial select[name=segmenter]", "sim")
    page.check("#new-trial input[name=start_paused]")
    page.click("#new-trial button[type=submit]")
    page.wait_for_url("**/#/trial/stack_two-*")
    page.wait_for_selector(".node.paused[data-path='tree.children[0]']", timeout=120_000)
    page.click("#step")
    page.wait_for_selector(".node.paused[data-path='tree.children[1]']", timeout=120_000)
    assert page.locator("#status").inner_text() == "paused"
    page.wait_for_function(
        "() => { const is = [...document.querySelectorAll('#grounding-now img.detection-image')];"
        " return is.length > 0 && is.every(i => i.complete && i.naturalWidth > 0); }",
        timeout=15_000,
    )
    imgs = page.eval_on_selector_all("#grounding-now img.detection-image", "is => is.map(i => i.src)")
    assert all(s.rsplit("/", 1)[1].startswith("grounding-") for s in imgs)
    assert page.locator("#grounding-now table.candidates tbody tr").count() >= 1
    assert page.locator("#status").inner_text() == "paused"  # still live
    page.click("#abort")
    page.wait_for_selector("#verdict[data-verdict=aborted]", timeout=120_000)


def test_an_instruction_typed_for_one_task_is_never_sent_with_another(server, page):
    """Choosing another task empties the instruction field (its placeholder: the new task's own instruction), so
    Run sends the new task with its own instruction; the typed text is offered for the new task, and comes back
    when its own task is chosen again."""
    field = "#new-trial input[name=instruction]"
    catalog = json.loads(urllib.request.urlopen(f"{server}/api/catalog").read())
    own = {t["name"]: t["instruction"] for t in catalog["tasks"]}
    page.goto(server + "/")
    page.click("button[data-task=stack_two]")
    page.select_option("#new-trial select[name=planner]", "rules")
    page.fill(field, "put the red block on the blue block, gently")
    page.click("button[data-task=lift_block]")
    assert page.input_value(field) == ""
    assert page.get_attribute(field, "placeholder") == own["lift_block"]
    left = page.locator("#instruction-left")
    assert left.get_attribute("data-task") == "stack_two" and "gently" in left.inner_text()
    page.click("button[data-task=stack_two]")  # its own text comes back
    assert page.input_value(field) == "put the red block on the blue block, gently"
    assert page.locator("#instruction-left").count() == 0
    page.click("button[data-task=lift_block]")
    page.click("#instruction-dismiss")
    assert page.locator("#instruction-left").count() == 0 and page.input_value(field) == ""
    page.click("#new-trial button[type=submit]")  # the new task, with its own instruction
    page.wait_for_url("**/#/trial/lift_block-*")
    tid = page.url.split("/trial/")[1]
    trial = json.loads(urllib.request.urlopen(f"{server}/api/trials/{tid}").read())
    assert trial["task"] == "lift_block" and trial["instruction"] == own["lift_block"]
    with contextlib.suppress(urllib.error.HTTPError):  # 409: it has already ended
        _post(server, f"/api/trials/{tid}/control", {"action": "abort"})
    # the offer: one click uses the text for the task now chosen
    page.goto(server + "/")
    page.click("button[data-task=stack_two]")
    page.select_option("#new-trial select[name=planner]", "rules")
    page.fill(field, "lift the red block")
    page.click("button[data-task=block_on_plate]")
    assert page.input_value(field) == ""
    page.click("#instruction-use-mine")
    assert page.input_value(field) == "lift the red block" and page.locator("#instruction-left").count() == 0


def test_the_headers_clock_ticks_while_the_trial_runs_and_stops_when_it_ends(server, page):
    """The wall clock in the trial's header moves on its own while a node runs (no event in between) and stands
    still once the trial has ended, at the record's wall time."""
    plan = "task: wait\ntree:\n  type: sequence\n  children:\n    - type: wait\n      params: {duration: 6.0}\n"
    body = {"task": "lift_block", "segmenter": "privileged-keypoints", "plan": plan, "pacing": 1.0}
    tid = _post(server, "/api/trials", body)["id"]
    deadline = time.time() + 120
    while not any(
        e["kind"] == "started" and e["node_path"] == "tree.children[0]"
        for e in json.loads(urllib.request.urlopen(f"{server}/api/trials/{tid}").read()).get("events", [])
    ):
        assert time.time() < deadline, "the wait node never started"
        time.sleep(0.05)
    time.sleep(1.0)  # the page opens mid-node: what it learns of the node comes from the stream's replay
    page.goto(f"{server}/#/trial/{tid}")
    page.wait_for_selector(".node.running[data-path='tree.children[0]']", timeout=120_000)
    rows = page.locator("#event-table tbody tr").count()
    # the page read the node's start from the stream's replay or live: either way the clock shows the server's time
    last = json.loads(urllib.request.urlopen(f"{server}/api/trials/{tid}").read())["events"][-1]
    expected = last["t"] + time.time() - last["wall_s"]  # browser and server share this machine's clock
    assert abs(float(page.locator("#wall-active").inner_text()) - expected) < 0.5
    # sampled in the page itself (a loaded CI machine delays the test's own reads, not the page's timers)
    samples = page.evaluate(
        """async () => {
          const read = () => [performance.now() / 1000, parseFloat(document.querySelector('#wall-active').textContent)];
          const out = [read()];
          for (let i = 0; i < 12; i++) { await new Promise((r) => setTimeout(r, 100)); out.push(read()); }
          return out;
        }"""
    )
    assert page.locator("#event-table tbody tr").count() == rows, "an event arrived: the test needs a quiet node"
    values = [v for _, v in samples]
    assert values == sorted(values) and values[-1] > values[0], values
    elapsed = samples[-1][0] - samples[0][0]
    assert 0.5 * elapsed < values[-1] - values[0] < 1.5 * elapsed + 0.25, (samples, elapsed)
    page.wait_for_selector("#verdict[data-verdict]", timeout=120_000)
    record = _wait_done(server, tid)
    page.wait_for_function("() => document.querySelector('#status').dataset.status === 'done'")
    c = float(page.locator("#wall-active").inner_text())
    time.sleep(0.5)
    assert float(page.locator("#wall-active").inner_text()) == c
    assert abs(c - record["wall_time_s"]) < 0.02


def test_privileged_perception_is_marked_live_in_history_and_in_compare(server, page):
    """Whether a trial's perception was privileged (the catalog's flag for its segmenter) shows on the live trial's
    page, in History's rows and in Compare's, not only in a finished trial's header."""
    catalog = json.loads(urllib.request.urlopen(f"{server}/api/catalog").read())
    flag = {s["name"]: s["privileged"] for s in catalog["segmenters"]}
    assert flag["sim"] and not flag["learned"]
    body = {"task": "stack_two", "start_paused": True}
    a = _post(server, "/api/trials", {**body, "segmenter": "sim"})["id"]
    b = _post(server, "/api/trials", {**body, "segmenter": "learned"})["id"]
    page.goto(f"{server}/#/trial/{a}")
    page.wait_for_selector("#privileged")
    assert page.locator("#status").get_attribute("data-status") in ("queued", "running", "paused")
    page.goto(f"{server}/#/trial/{b}")
    page.wait_for_selector("#status")
    assert page.locator("#privileged").count() == 0
    for tid in (a, b):
        _post(server, f"/api/trials/{tid}/control", {"action": "abort"})
    for tid in (a, b):
        _wait_done(server, tid)
    page.goto(f"{server}/#/history")
    page.wait_for_selector(f"#rows tr[data-id='{a}']")
    assert page.locator(f"#rows tr[data-id='{a}'] [data-privileged]").count() == 1
    assert page.locator(f"#rows tr[data-id='{b}'] [data-privileged]").count() == 0
    page.goto(f"{server}/#/compare/{a}/{b}")
    page.wait_for_selector("td[data-segmenter=learned]")
    assert page.locator("td[data-segmenter=sim] [data-privileged]").count() == 1
    assert page.locator("td[data-segmenter=learned] [data-privileged]").count() == 0


def test_history_marks_the_trials_with_training_data_and_filters_on_it(server, page):
    body = {"task": "lift_block", "segmenter": "privileged-keypoints"}
    with_data = _post(server, "/api/trials", {**body, "capture": True})["id"]
    without = _post(server, "/api/trials", body)["id"]
    frames = next(a["frames"] for a in _wait_done(server, with_data)["artifacts"] if a["name"] == "episode.npz")
    _wait_done(server, without)
    page.goto(f"{server}/#/history")
    page.wait_for_selector(f"#rows tr[data-id='{with_data}']")
    marked = page.locator(f"#rows tr[data-id='{with_data}'] [data-training]")
    assert marked.get_attribute("data-training") == str(frames) and f"{frames} frames" in marked.inner_text()
    assert page.locator(f"#rows tr[data-id='{without}'] [data-training]").count() == 0
    page.select_option("#filters select[name=training]", "true")
    page.wait_for_selector(f"#rows tr[data-id='{without}']", state="detached")
    assert page.locator(f"#rows tr[data-id='{with_data}']").count() == 1
    assert page.locator("#rows tbody tr").count() == page.locator("#rows tbody tr [data-training]").count()
    page.select_option("#filters select[name=training]", "false")
    page.wait_for_selector(f"#rows tr[data-id='{with_data}']", state="detached")
    assert page.locator(f"#rows tr[data-id='{without}']").count() == 1


def test_the_forms_instruction_follows_the_catalogs_reads_instruction_flag(server, browser):
    """The trial form turns its instruction field off for a planner the catalog says reads none, whatever its
    name (here the catalog is altered on its way to the page: rules reads none, reference reads one)."""
    ctx = browser.new_context(viewport={"width": 1400, "height": 1000})

    def altered(route):
        cat = json.loads(route.fetch().text())
        for p in cat["planners"]:
            p["reads_instruction"] = p["name"] != "rules"
        route.fulfill(json=cat)

    ctx.route("**/api/catalog", altered)
    page = ctx.new_page()
    try:
        field = "#new-trial input[name=instruction]"
        page.goto(server + "/")
        page.click("button[data-task=lift_block]")
        page.select_option("#new-trial select[name=planner]", "reference")
        assert page.is_enabled(field) and page.locator("#instruction-note").count() == 0
        page.select_option("#new-trial select[name=planner]", "rules")
        assert page.is_disabled(field)
        note = page.locator("#instruction-note").inner_text()
        assert "the rules planner" in note and "reads no instruction" in note and "choose reference" in note
    finally:
        ctx.close()
