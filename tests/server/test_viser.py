"""The live 3D view: the scene mirrors the world's bodies, and the server exposes it for the UI."""

import time

import numpy as np
from fastapi.testclient import TestClient

from server.app import create_app
from server.settings import Settings
from server.viser_scene import ViserScene
from spark_core.sim.tasks import BUILTIN


def test_scene_mirrors_the_world_at_its_rate():
    world = BUILTIN["stack_two"].make_world(0)
    scene = ViserScene(rate_hz=30)
    try:
        scene.show(world)
        robot_links = [b for b in scene._frames if world.model.body(b).name.startswith("robot/")]
        assert len(robot_links) >= 8 and world.model.body("red block").id in scene._frames
        world.set_body_position("red block", [0.61, 0.21, 0.0])
        t0 = scene.ticks
        time.sleep(0.5)
        assert scene.ticks - t0 >= 5
        b = world.model.body("red block").id
        np.testing.assert_allclose(scene._frames[b].position, world.data.xpos[b], atol=1e-9)
        scene.detach(world)
        frozen = scene.ticks
        time.sleep(0.2)
        assert scene.ticks == frozen  # detached: no more updates
    finally:
        scene.stop()
        world.close()


def test_server_reports_the_view_and_mirrors_trials(tmp_path):
    with TestClient(create_app(Settings(store_url=f"sqlite:///{tmp_path / 'v.db'}", workers=1, artifacts_dir=str(tmp_path)))) as c:
        v = c.get("/api/viser").json()
        assert v["enabled"] and v["port"] > 0
        tid = c.post("/api/trials", json={"task": "lift_block", "resolver": "sim"}).json()["id"]
        for _ in range(600):
            if c.get(f"/api/trials/{tid}").json()["status"] == "done":
                break
            time.sleep(0.1)
        assert c.get("/api/viser").json()["frames_published"] > 0
    with TestClient(create_app(Settings(store_url=f"sqlite:///{tmp_path / 'w.db'}", workers=1, viser=False))) as c:
        assert c.get("/api/viser").json() == {"enabled": False}


def test_frame_rate_benchmark_runs():
    from server.bench_viser import run, section

    r = run(task="lift_block", seeds=1)
    assert r["fps_mean"] > 0 and r["fps_min"] <= r["fps_mean"]
    assert "viser scene" in section(r, "spark bench viser")
