"""The live 3D view: fed from the simulation as plain arrays, served from the console's origin through a
websocket relay, following running trials (target pose, markers, active node) and replaying finished ones."""

import time

import numpy as np
import pytest
import viser
from fastapi.testclient import TestClient
from starlette.testclient import WebSocketDenialResponse

from server.app import create_app
from server.settings import Settings
from server.view3d.scene_feed import SceneFeed
from server.view3d.viser_scene import ViserScene
from spark_core.sim.geometry import body_poses
from spark_core.sim.tasks import BUILTIN

from .test_api import wait_done


def test_feed_mirrors_the_world_at_its_rate():
    world = BUILTIN["stack_two"].make_world(0)
    scene = ViserScene()
    try:
        feed = SceneFeed(world, scene.sink("w"), rate_hz=30).start()
        robot_links = [b for b in scene._frames if world.model.body(b).name.startswith("robot/")]
        assert len(robot_links) >= 8 and world.model.body("red block").id in scene._frames
        world.set_body_position("red block", [0.61, 0.21, 0.0])
        t0 = scene.ticks
        time.sleep(0.5)
        assert scene.ticks - t0 >= 5
        b = world.model.body("red block").id
        np.testing.assert_allclose(scene._frames[b].position, world.data.xpos[b], atol=1e-9)
        feed.stop()
        frozen = scene.ticks
        time.sleep(0.2)
        assert scene.ticks == frozen  # stopped: no more updates
        scene.show("other", [])  # another trial takes the view: late frames of the old one are ignored
        feed._publish()
        assert scene.ticks == frozen
    finally:
        scene.stop()
        world.close()


def _app(tmp_path, **kw):
    return create_app(
        Settings(store_url=f"sqlite:///{tmp_path / 'v.db'}", workers=1, artifacts_dir=str(tmp_path / "a"), **kw)
    )


def test_trials_stream_into_the_view_which_is_relayed_from_the_console_origin_and_replays(tmp_path):
    with TestClient(_app(tmp_path)) as c:
        v = c.get("/api/viser").json()
        assert v["enabled"] and v["path"] == "/viser/" and v["port"] > 0
        page = c.get("/viser/")
        assert page.status_code == 200 and "<script" in page.text  # viser's own client, from our origin
        scene = c.app.state.scene
        tid = c.post("/api/trials", json={"task": "lift_block", "segmenter": "sim", "pacing": 1.0}).json()["id"]
        trial = wait_done(c, tid)
        assert trial["success"] is True
        # paced at real time (~4 s of simulated time): the 30 Hz feed publishes many frames, however fast the machine
        assert c.get("/api/viser").json()["frames_published"] > 30 and scene.current == tid
        assert "right" in scene._targets  # the TCP target pose was drawn
        assert "lift_block" in scene._active.content or "tree" in scene._active.content
        # the relay: a raw client speaking viser's subprotocol gets the scene through /viser
        with c.websocket_connect("/viser", subprotocols=[f"viser-v{viser.__version__}"]) as ws:
            assert len(ws.receive_bytes()) > 0
        # replay from the stored scene states: the view ends on the last recorded state
        r = c.post(f"/api/trials/{tid}/replay", params={"speed": 20}).json()
        assert r["states"] > 20 and r["duration_s"] > 1
        assert scene.current == f"replay:{tid}"
        time.sleep(r["duration_s"] / 20 + 1.5)
        states = c.app.state.store.scene_states(tid)
        world = BUILTIN["lift_block"].make_world(0)
        import mujoco

        xpos, _ = body_poses(world.model, mujoco.MjData(world.model), np.asarray(states[-1][1]))
        b = world.model.body("red block").id  # it was lifted: far from where the scene starts it
        assert abs(xpos[b][2] - world.data.xpos[b][2]) > 0.03
        np.testing.assert_allclose(scene._frames[b].position, xpos[b], atol=1e-6)
        assert "finished" in scene._active.content
        world.close()
        assert c.post("/api/trials/nope/replay").status_code == 404
    with TestClient(_app(tmp_path, viser=False)) as c:
        assert c.get("/api/viser").json() == {"enabled": False}
        assert c.get("/viser/").status_code == 404


def test_websockets_need_the_token_beyond_loopback(tmp_path):
    with TestClient(_app(tmp_path, host="0.0.0.0", api_token="s3cret", viser=False)) as c:
        for path in ("/api/events", "/api/trials/x/events", "/viser", "/api/events?token=s3cret"):
            try:
                with c.websocket_connect(path) as ws:
                    ws.receive_json()
                raise AssertionError(f"{path} accepted a client without the token")
            except WebSocketDenialResponse as e:  # answered 401 before the upgrade; a token in the URL does not count
                assert e.status_code == 401
        with c.websocket_connect("/api/events", headers={"Authorization": "Bearer s3cret"}):
            pass


def test_frame_rate_benchmark_runs():
    from spark_cli.console_bench.viser import run, section

    r = run(task="lift_block", seeds=1)
    assert r["fps_mean"] > 0 and r["fps_min"] <= r["fps_mean"]
    assert "viser scene" in section(r, "spark bench viser")


def test_a_robosuite_replay_draws_bodies_in_the_world_frame_of_the_keypoints():
    pytest.importorskip("robosuite", reason="benchmark extras: make bench-deps")
    from server.view3d.replay import _play
    from spark_core.sim.tasks import TASKS

    world = TASKS["Lift"].make_world(0)
    base, cube = world.model.body("robot0_base").id, world.model.body("cube_main").id
    cube_in_world = world.body_position("cube_main")

    class View:
        current = "k"

        def show(self, *a, **k): ...
        def markers(self, *a, **k): ...
        def active(self, *a, **k): ...

        def update(self, key, xpos, xquat):
            self.xpos = xpos

    view = View()
    _play(view, "k", "t", world, [(0.0, world.data.qpos.copy())], {}, 1.0)
    assert np.allclose(view.xpos[base][:2], 0.0, atol=1e-6)  # our origin is under robot0's base
    assert np.allclose(view.xpos[cube], cube_in_world, atol=1e-4)


def test_the_environment_map_is_off_unless_asked_for(monkeypatch):
    """Its one-time setup in a software-WebGL browser stalled every frame of the page for ~4 s
    (docs/profiles/console_latency.md): off by default, SPARK_VISER_ENV_MAP=1 keeps viser's own."""
    from viser._scene_api import SceneApi

    calls = []
    real = SceneApi.configure_environment_map
    monkeypatch.setattr(
        SceneApi, "configure_environment_map", lambda self, *a, **k: (calls.append(a), real(self, *a, **k))
    )
    for env_map in (False, True):
        scene = ViserScene(env_map=env_map)
        scene.stop()
    assert calls == [(None,)]
    monkeypatch.setenv("SPARK_VISER_ENV_MAP", "1")
    assert Settings.from_env().viser_env_map
    monkeypatch.delenv("SPARK_VISER_ENV_MAP")
    assert not Settings.from_env().viser_env_map
