"""The console in a real browser: Playwright driving Debian's headless chromium against a real server."""

import shutil
import socket
import threading
import time
from pathlib import Path

import pytest

ARTIFACTS = Path(__file__).resolve().parents[2] / "test-artifacts"
APPS = []  # the app behind the `server` fixture, to look at its 3D view
CHROMIUM = shutil.which("chromium-headless-shell") or shutil.which("chromium")


@pytest.fixture(scope="module")
def server(tmp_path_factory):
    import uvicorn

    from server.app import create_app
    from server.settings import Settings

    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    tmp = tmp_path_factory.mktemp("web")
    app = create_app(Settings(port=port, store_url=f"sqlite:///{tmp / 'ui.db'}", workers=2,
                              artifacts_dir=str(tmp / "art"), exports_dir=str(tmp / "exports")))
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
def page(server):
    from playwright.sync_api import sync_playwright

    assert CHROMIUM, "Debian's chromium-headless-shell is missing: make test installs it (scripts/apt-deps.sh)"
    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path=CHROMIUM, args=[
            "--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--disable-background-networking"])
        pg = browser.new_page(viewport={"width": 1280, "height": 1000})
        yield pg
        browser.close()


def shot(page, name):
    ARTIFACTS.mkdir(exist_ok=True)
    page.screenshot(path=str(ARTIFACTS / f"{name}.png"), full_page=True)


def test_submit_step_breakpoint_resume_and_history(server, page):
    page.goto(server + "/")
    page.select_option("select[name=task]", "stack_two")
    page.select_option("select[name=segmenter]", "sim")  # cameras + masks: the trial has detection images
    page.check("input[name=start_paused]")
    page.click("button[type=submit]")
    page.wait_for_url("**/#/trial/stack_two-*")
    first = page.locator(".node[data-path='tree.children[0]']")
    first.wait_for()
    page.wait_for_selector(".node.paused[data-path='tree.children[0]']", timeout=120_000)
    # set a breakpoint by clicking a node of the tree
    page.click(".node[data-path='tree.children[3]']")
    page.wait_for_selector(".node.breakpoint[data-path='tree.children[3]']")
    shot(page, "1-paused-with-breakpoint")
    # step: exactly one primitive runs, then it pauses again
    page.click("#step")
    page.wait_for_selector(".node.succeeded[data-path='tree.children[0]']", timeout=120_000)
    page.wait_for_selector(".node.paused[data-path='tree.children[1]']", timeout=120_000)
    assert page.locator(".node.succeeded").count() == 1
    # resume: runs until the breakpoint
    page.click("#resume")
    page.wait_for_selector(".node.paused[data-path='tree.children[3]']", timeout=120_000)
    assert page.locator(".node.succeeded[data-path='tree.children[2]']").count() == 1
    shot(page, "2-at-breakpoint")
    page.click("#resume")
    page.wait_for_selector("#verdict.ok", timeout=120_000)
    page.wait_for_selector("#timeline rect")
    # the 3D view comes from the console's own origin, and the browser's viser client connects through the relay
    assert page.locator("#viser-frame").get_attribute("src") == "/viser/"
    scene = APPS[-1].state.scene
    for _ in range(300):
        if scene.server.get_clients():
            break
        time.sleep(0.1)
    assert scene.server.get_clients(), "the embedded viser client never connected through /viser"
    trial_id = page.url.split("/trial/")[1]
    page.click("#replay")
    for _ in range(100):
        if scene.current == f"replay:{trial_id}":
            break
        time.sleep(0.05)
    assert scene.current == f"replay:{trial_id}"
    shot(page, "3-finished")
    trial_url = page.url
    # history: the finished trial is listed and opens with its tree and timeline
    page.goto(server + "/#/history")
    page.wait_for_selector("#rows table")
    page.click(f"#rows a[href='#/trial/{trial_url.split('/trial/')[1]}']")
    page.wait_for_selector(".node.succeeded[data-path='tree.children[4]']")
    assert page.locator("#timeline rect").count() >= 5
    assert "move_to_keypoint" in page.locator("#timeline").text_content()
    page.wait_for_selector("#detections img")
    assert page.eval_on_selector("#detections img", "img => img.complete && img.naturalWidth") > 0  # served, decodes
    assert "red block" in page.locator("#groundings").inner_text()
    shot(page, "4-history-detail")


def test_form_reports_server_errors(server, page):
    page.goto(server + "/")
    page.wait_for_selector("select[name=task]")
    page.evaluate("document.querySelector('select[name=task]').add(new Option('juggle', 'juggle'))")
    page.select_option("select[name=task]", "juggle")
    page.click("button[type=submit]")
    page.wait_for_selector("#form-error:has-text(\"unknown task 'juggle'\")")



def test_batch_from_the_form_shows_progress_and_results(server, page):
    page.goto(server + "/")
    page.wait_for_selector("#new-batch select[name=tasks]")
    page.select_option("#new-batch select[name=tasks]", ["lift_block", "push_to_zone"])
    page.fill("#new-batch input[name=trials]", "2")
    page.select_option("#new-batch select[name=segmenter]", "privileged-keypoints")
    page.click("#new-batch button[type=submit]")
    page.wait_for_url("**/#/batch/batch-*")
    page.wait_for_selector("#batch-count:has-text('4 / 4 · done')", timeout=120_000)
    assert page.eval_on_selector("#batch-progress", "p => p.value / p.max") == 1
    rows = page.locator("#batch-table tr")
    assert rows.count() == 3 and "100.0 %" in rows.nth(1).inner_text()
    shot(page, "5-batch")
    # the result table downloads as CSV from the page's link
    with page.expect_download() as dl:
        page.click("#batch-results-csv")
    text = Path(dl.value.path()).read_text()
    assert text.startswith("task,done,total,successes") and "lift_block,2,2,2" in text


def test_history_selection_exports_a_lerobot_dataset(server, page):
    import io
    import json
    import urllib.request
    import zipfile

    req = urllib.request.Request(server + "/api/trials", method="POST", headers={"content-type": "application/json"},
                                 data=json.dumps({"task": "lift_block", "segmenter": "privileged-keypoints", "capture": True}).encode())
    tid = json.loads(urllib.request.urlopen(req).read())["id"]
    for _ in range(1200):
        if json.loads(urllib.request.urlopen(f"{server}/api/trials/{tid}").read())["status"] == "done":
            break
        time.sleep(0.1)
    page.goto(server + "/#/history")
    page.wait_for_selector(f"#rows .pick[value='{tid}']")
    page.check(f"#rows .pick[value='{tid}']")
    page.click("#export-selected")
    page.wait_for_selector("#export-download", timeout=120_000)
    assert "1 episode(s)" in page.locator("#export-result").inner_text()
    shot(page, "6-history-export")
    with page.expect_download() as dl:
        page.click("#export-download")
    z = zipfile.ZipFile(io.BytesIO(Path(dl.value.path()).read_bytes()))
    assert json.loads(z.read("meta/info.json"))["total_episodes"] == 1
