"""What the console's pages rely on from the server: the 3D view bound to the trial a page shows (live feeds
cached, finished trials at a cursor), keypoint labels on their markers, every batch listed, /docs without a CDN,
and client types that match the live OpenAPI document."""

import json
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest
from fastapi.testclient import TestClient

from server.app import create_app
from server.settings import Settings
from server.view3d.viser_scene import ViserScene
from spark_core import visual_geoms
from spark_core.sim.tasks import BUILTIN

from .test_api import wait_done

ROOT = Path(__file__).resolve().parents[2]


def _app(tmp_path, **kw):
    kw.setdefault("workers", 1)
    return create_app(Settings(store_url=f"sqlite:///{tmp_path / 'c.db'}", artifacts_dir=str(tmp_path / "a"), **kw))


def test_keypoint_labels_sit_on_their_markers():
    scene = ViserScene()
    try:
        scene.show("k", [])
        scene.markers("k", {"red block": [0.5, -0.1, 0.02], "plate": [0.6, 0.2, 0.01]})
        # each label is a child of its marker: its position is relative to the marker, 3 cm above it
        for label in ("red block", "plate"):
            np.testing.assert_allclose(scene._labels[label].position, [0.0, 0.0, 0.03])
        scene.markers("k", {"red block": [0.5, -0.1, 0.02]})  # fewer keypoints (scrubbed back): the other goes
        assert list(scene._labels) == ["red block"] and len(scene._markers) == 1
    finally:
        scene.stop()


def test_a_pinned_view_is_not_taken_by_another_trial_and_focus_draws_a_cached_feed():
    world = BUILTIN["lift_block"].make_world(0)
    scene = ViserScene()
    try:
        geoms = visual_geoms(world.model)
        scene.focus("a")
        scene.sink("b", "trial b")("scene", geoms)  # b starts while a page shows a: the view stays with a
        assert scene.current != "b"
        xpos = np.zeros((world.model.nbody, 3))
        xpos[:, 2] = 0.7
        xquat = np.tile([1.0, 0, 0, 0], (world.model.nbody, 1))
        scene.sink("b", "trial b")("poses", (xpos, xquat, {}))
        assert scene.focus("b") and scene.current == "b"  # opening b's page draws its latest state at once
        b = next(iter(scene._frames))
        np.testing.assert_allclose(scene._frames[b].position, xpos[b])
    finally:
        scene.stop()
        world.close()


def test_focus_binds_the_view_to_a_finished_trial_at_the_cursor(tmp_path):
    with TestClient(_app(tmp_path)) as c:
        tid = c.post("/api/trials", json={"task": "lift_block", "segmenter": "sim"}).json()["id"]
        assert wait_done(c, tid)["success"]
        scene = c.app.state.scene
        block = BUILTIN["lift_block"].make_world(0)
        bid = block.model.body("red block").id
        block.close()
        start = c.post("/api/viser/focus", params={"trial": tid, "t_sim_s": 0}).json()
        assert start["showing"] == f"replay:{tid}" and start["index"] == 0
        z0 = float(scene._frames[bid].position[2])
        assert not scene._labels  # nothing grounded yet at t = 0
        end = c.post("/api/viser/focus", params={"trial": tid}).json()
        assert end["index"] == end["states"] - 1
        assert float(scene._frames[bid].position[2]) > z0 + 0.05  # lifted by the end
        assert list(scene._labels) == ["red block"]
        assert scene.image_key == f"replay:{tid}"  # its own detection image, from its grounding on
        # another trial, with no detections (no cameras): the view shows no image, not the previous trial's
        other = c.post("/api/trials", json={"task": "lift_block", "segmenter": "privileged-keypoints"}).json()["id"]
        wait_done(c, other)
        c.post("/api/viser/focus", params={"trial": other})
        assert scene.current == f"replay:{other}" and scene.image_key is None
        assert not scene._image.image.any()
        assert c.post("/api/viser/focus", params={"trial": "nope"}).status_code == 404
        # the camera at a time: the recorded state rendered, different before and after the lift
        import cv2

        def camera(t):
            r = c.get(f"/api/trials/{tid}/camera.png", params={"t_sim_s": t, "camera": "agentview"})
            assert r.status_code == 200 and r.headers["content-type"] == "image/png"
            return cv2.imdecode(np.frombuffer(r.content, np.uint8), cv2.IMREAD_COLOR).astype(int)

        start, lifted = camera(0), camera(end["t_sim_s"])
        assert start.shape == (240, 320, 3) and np.abs(start - lifted).mean() > 1.0
        bad = c.get(f"/api/trials/{tid}/camera.png", params={"t_sim_s": 0, "camera": "nope"})
        assert bad.status_code == 409 and "agentview" in bad.json()["detail"]
        assert c.get("/api/trials/nope/camera.png", params={"t_sim_s": 0}).status_code == 404
        assert c.post("/api/viser/focus").json()["pinned"] is None


def test_every_batch_is_listed_with_settings_and_progress(tmp_path):
    with TestClient(_app(tmp_path, viser=False)) as c:
        ids = [
            c.post(
                "/api/batches", json={"tasks": ["lift_block"], "trials": 1, "segmenter": "privileged-keypoints"}
            ).json()["id"]
            for _ in range(2)
        ]
        for bid in ids:
            for t in c.get(f"/api/batches/{bid}").json()["trials"]:
                wait_done(c, t["id"])
        listed = c.get("/api/batches").json()
        assert listed["total"] == 2 and {b["id"] for b in listed["items"]} == set(ids)
        for b in listed["items"]:
            assert b["status"] == "done" and b["progress"] == {"done": 1, "total": 1, "successes": 1}
            assert b["spec"]["segmenter"] == "privileged-keypoints" and "manifest" not in b["spec"]
        assert len(c.get("/api/batches", params={"limit": 1}).json()["items"]) == 1
        # where the time went, per primitive of the plans (lift_block's reference plan is one pick)
        timing = c.get(f"/api/batches/{ids[0]}/timing").json()["rows"]
        assert [(r["task"], r["primitive"], r["runs"]) for r in timing] == [("lift_block", "pick", 1)]
        assert timing[0]["mean_sim_s"] > 0.5 and timing[0]["mean_wall_s"] > 0
        # and per phase of the trial pipeline, from the outcome's phases_s kept in each trial record
        phases = {r["phase"]: r for r in c.get(f"/api/batches/{ids[0]}/timing").json()["phases"]}
        assert {"setup", "perception", "planning", "execution"} <= set(phases)
        assert all(r["task"] == "lift_block" and r["trials"] == 1 for r in phases.values())
        assert phases["setup"]["mean_wall_s"] > 0 and phases["execution"]["mean_wall_s"] > 0
        assert c.get("/api/batches/batch-nope/timing").status_code == 404


def test_docs_load_swagger_from_our_own_origin(tmp_path):
    with TestClient(_app(tmp_path, viser=False)) as c:
        html = c.get("/docs")
        if not (ROOT / "web" / "dist" / "swagger").is_dir():
            assert html.status_code == 503 and "make install" in html.text
            pytest.skip("front end not built")
        assert html.status_code == 200 and "cdn" not in html.text.lower()
        assert '"/swagger/swagger-ui-bundle.js"' in html.text
        assert c.get("/swagger/swagger-ui-bundle.js").status_code == 200


@pytest.mark.skipif(not (ROOT / "web" / "node_modules" / "openapi-typescript").is_dir(), reason="npm ci not run")
def test_the_committed_client_types_match_the_live_openapi_document(tmp_path):
    """Regenerate: node web/scripts/gen-api.mjs OPENAPI.json web/src/api/schema.d.ts"""
    app = _app(tmp_path, viser=False)
    doc = tmp_path / "openapi.json"
    doc.write_text(json.dumps(app.openapi()))
    out = tmp_path / "schema.d.ts"
    subprocess.run(
        [shutil.which("node") or "node", "scripts/gen-api.mjs", str(doc), str(out)], cwd=ROOT / "web", check=True
    )
    assert out.read_text() == (ROOT / "web" / "src" / "api" / "schema.d.ts").read_text(), (
        "web/src/api/schema.d.ts is stale: regenerate it (see this test's docstring)"
    )


def test_a_task_preview_is_a_picture_of_its_scene(tmp_path):
    import cv2

    with TestClient(_app(tmp_path, viser=False)) as c:
        r = c.get("/api/tasks/lift_block/preview.png")
        assert r.status_code == 200 and r.headers["content-type"] == "image/png"
        img = cv2.imdecode(np.frombuffer(r.content, np.uint8), cv2.IMREAD_COLOR)
        assert img.shape == (240, 320, 3) and img.std() > 10  # a drawn scene, not a blank frame
        assert c.get("/api/tasks/juggle/preview.png").status_code == 404


def test_a_focus_request_overtaken_by_a_later_one_does_not_draw(tmp_path):
    """A page left trial A for trial B while A's seek was still waiting to draw (behind a camera render or a world
    being built): B's view stays B's, not A's arriving late; a later unbind (the page left) is not undone either."""
    import threading
    import time

    with TestClient(_app(tmp_path)) as c:
        a, b = (
            c.post("/api/trials", json={"task": t, "segmenter": "privileged-keypoints"}).json()["id"]
            for t in ("lift_block", "push_to_zone")
        )
        wait_done(c, a), wait_done(c, b)
        replays, scene = c.app.state.replays, c.app.state.scene
        seek = replays.seek

        def slow_for_a(trial_id, t_sim_s, ticket=None):  # A's request is held up before it can draw
            if trial_id == a:
                time.sleep(1.0)
            return seek(trial_id, t_sim_s, ticket=ticket)

        replays.seek = slow_for_a
        late = {}
        first = threading.Thread(target=lambda: late.update(c.post("/api/viser/focus", params={"trial": a}).json()))
        first.start()
        time.sleep(0.3)
        shown = c.post("/api/viser/focus", params={"trial": b}).json()
        assert shown["showing"] == f"replay:{b}"
        first.join(10)
        assert late.get("superseded") is True
        assert scene.current == f"replay:{b}" and scene.pinned == f"replay:{b}"
        # the page leaves (unbinds) while another request for A is still on its way: nothing pins A again
        first = threading.Thread(target=lambda: c.post("/api/viser/focus", params={"trial": a}))
        first.start()
        time.sleep(0.3)
        assert c.post("/api/viser/focus").json()["pinned"] is None
        first.join(10)
        assert scene.pinned is None and scene.current == f"replay:{b}"


def test_an_api_path_no_route_takes_is_answered_by_the_api_not_the_front_ends_files(tmp_path):
    """The front end is mounted at "/", and used to answer every /api/... request no API route took: a typo'd
    POST /api/trial got 405 `allow: GET, HEAD` (as if the path existed), PUT /api/trials the same although it
    takes GET and POST, HEAD /api/health 404."""
    if not (ROOT / "web" / "dist" / "index.html").is_file():
        pytest.skip("front end not built")
    with TestClient(_app(tmp_path, workers=0, viser=False)) as c:
        r = c.post("/api/trial", json={"task": "lift_block"})
        assert r.status_code == 404, r.text
        r = c.put("/api/trials", json={})
        assert r.status_code == 405 and r.headers["allow"] == "GET, HEAD, POST"  # the path's methods, all of them
        assert c.head("/api/health").status_code == 200  # HEAD wherever GET works (tests/server/test_http_methods.py)
        assert c.head("/api/trial").status_code == 404  # and no route is no route, whatever the method
        assert c.delete("/api/exports/..").status_code == 404
        assert c.get("/").status_code == 200 and "<html" in c.get("/").text.lower()  # the pages are still served
        assert c.get("/favicon.svg").status_code == 200 and c.get("/api/health").json() == {"status": "ok"}
