"""Deferred RGB on robosuite/LIBERO worlds: a frame's RGB drawn when first read is the picture of the moment it
was captured (the same pixels as drawing it then), and reading only depth/ids never draws it."""

from __future__ import annotations

import numpy as np
import pytest

pytest.importorskip("libero", reason="benchmark extras: make bench-deps")

from spark_core.sim.cameras import DeferredFrame, without_sites
from spark_core.sim.tasks import SUITES


@pytest.fixture(scope="module")
def world():
    task = next(t for name, t in SUITES["liberopro"].items() if name.startswith("libero_object_swap:"))
    w = task.make_world(0, task.embodiments[0])
    yield w
    w.close()


def _eager(world, camera: str):
    world.defer_rgb = False  # this instance only: draw the RGB now
    try:
        return world.render(camera, 320, 240)
    finally:
        del world.defer_rgb


def test_deferred_rgb_is_the_picture_of_the_capture_moment(world):
    frame = world.render("agentview", 320, 240)
    assert isinstance(frame, DeferredFrame) and not frame.rgb_drawn
    eager_then = _eager(world, "agentview")
    assert frame.shape == (240, 320) and not frame.rgb_drawn  # the shape does not need the RGB
    np.testing.assert_array_equal(frame.depth_m, eager_then.depth_m)
    np.testing.assert_array_equal(frame.object_ids, eager_then.object_ids)
    # the world moves on: the arm swings and a colour changes before anyone reads the RGB
    q = world.q("right").copy()
    world.data.qpos[world._qadr["right"]] = q + 0.3
    world._command_joints("right", q + 0.3)
    world.settle(0.2)
    g = int(np.argmax(world.model.geom_rgba[:, 3] > 0))
    rgba = world.model.geom_rgba[g].copy()
    world.model.geom_rgba[g] = [1.0, 0.0, 1.0, 1.0]
    try:
        eager_now = _eager(world, "agentview")
        rgb = frame.rgb
        np.testing.assert_array_equal(world.model.geom_rgba[g], [1.0, 0.0, 1.0, 1.0])  # the draw put colours back
    finally:
        world.model.geom_rgba[g] = rgba
    assert frame.rgb_drawn and rgb.shape == (240, 320, 3) and rgb.dtype == np.uint8
    np.testing.assert_array_equal(rgb, eager_then.rgb)
    assert not np.array_equal(rgb, eager_now.rgb)  # the scene did change: the check above could have failed


@pytest.mark.parametrize("camera", ["agentview", "frontview"])
def test_depth_read_from_the_id_pass_is_the_depth_pass(world, camera):
    import mujoco

    frame = world.render(camera, 320, 240)

    def own_depth(sites: bool):
        r = mujoco.Renderer(world.model, 240, 320)
        try:
            r.enable_depth_rendering()
            r.update_scene(world.data, camera=camera, scene_option=None if sites else without_sites())
            return r.render().copy()
        finally:
            r.close()

    depth = world.on_render_thread(lambda: own_depth(False))
    assert np.isfinite(depth).all() and depth.min() > 0
    np.testing.assert_array_equal(frame.depth_m, depth)
    # LIBERO's transparent sites (placement regions, robosuite's gripper cylinder) are in MuJoCo's default depth
    # pass but not in the frame's: the camera sees surfaces only
    with_sites = world.on_render_thread(lambda: own_depth(True))
    assert (np.abs(with_sites - depth) > 0.005).sum() > 50
    assert not (with_sites > depth + 0.005).any()  # a site only ever hides what is behind it
