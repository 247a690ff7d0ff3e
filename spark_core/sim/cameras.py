"""On-demand camera frames: RGB, metric depth, per-pixel object ids, intrinsics and extrinsics (OpenCV convention).

Rendering is the expensive part of simulation; nothing renders unless perception (or the UI) asks. A world
with `defer_rgb` set (the robosuite/LIBERO worlds, whose shaded RGB pass costs ~0.4 s a camera on this
machine's software GL, 5x the depth and id passes) gets frames whose RGB is drawn on first access, from a
copy of the physics state taken when the frame was captured: the same pixels, but never drawn for a
segmenter that reads only depth and ids (the privileged `sim` segmenter).
"""

from __future__ import annotations

import copy
import threading
import time
from collections.abc import Callable
from typing import Any

import mujoco
import numpy as np

from ..perception.frame import CameraFrame


def _renderer(world, width: int, height: int) -> mujoco.Renderer:
    r = world.renderer
    if r is None or (r.width, r.height) != (width, height):
        if r is not None:
            r.close()
        r = world.renderer = mujoco.Renderer(world.model, height, width)
    world._render_thread_id = threading.get_ident()  # the thread whose GL context is current (see _draw_later)
    return r


class _DeferredRGB:
    """Data descriptor for `DeferredFrame.rgb`: holds either the image or a pending draw, which runs once."""

    def __set__(self, obj: Any, value: Any) -> None:
        obj.__dict__["_rgb"] = value  # a frozen dataclass's __init__ sets fields with object.__setattr__

    def __get__(self, obj: Any, owner: type | None = None) -> Any:
        if obj is None:
            return self
        value = obj.__dict__["_rgb"]
        if callable(value):
            value = value()
            obj.__dict__["_rgb"] = value
        return value


class DeferredFrame(CameraFrame):
    """A CameraFrame whose `rgb` (H, W, 3 uint8) is drawn on first access from the state it was captured in."""

    rgb = _DeferredRGB()

    @property
    def shape(self) -> tuple[int, int]:
        return self.depth_m.shape[:2]  # without drawing the RGB

    @property
    def rgb_drawn(self) -> bool:
        return not callable(self.__dict__["_rgb"])


def _draw_later(world, camera: str, width: int, height: int) -> Callable[[], np.ndarray]:
    """A draw of `camera`'s RGB as the scene is now: the physics state and geom colours (a wiped marker turns
    transparent) are copied, so a later draw shows this moment, whatever the world has done since."""
    m = world.model
    data, rgba = copy.copy(world.data), m.geom_rgba.copy()  # MjData's copy is MuJoCo's mj_copyData

    def draw() -> np.ndarray:
        r = _renderer(world, width, height)
        now = m.geom_rgba.copy()
        m.geom_rgba[:] = rgba
        try:
            r.update_scene(data, camera=camera, scene_option=without_sites())
            return r.render().copy()
        finally:
            m.geom_rgba[:] = now

    def on_render_thread() -> np.ndarray:
        t0 = time.perf_counter()
        try:
            if getattr(world, "_render_thread_id", None) == threading.get_ident():
                return draw()  # asked from the render thread itself (it cannot wait for itself)
            with world._lock:  # the colours are swapped for the draw: no physics step reads them meanwhile
                return world.on_render_thread(draw)
        finally:
            world.wall_s["rendering"] += time.perf_counter() - t0

    return on_render_thread


def label_table(world) -> tuple[dict[int, str], np.ndarray]:
    """Object ids and a geom-id -> object-id lookup. A part's own id wins over its object's; a part may be a
    body or (robosuite) some geoms of a body, listed in `world.part_geoms`."""
    m = world.model
    part_geoms: dict[str, set[int]] = getattr(world, "part_geoms", {})
    named = [(label, world.scene.objects[label].body) for label in world.scene.objects]
    named += [(label, body) for label, (body, _) in world.scene.parts.items()]
    labels = {i: label for i, (label, _) in enumerate(named, start=1)}
    body_to_obj = np.zeros(m.nbody, dtype=np.int32)
    depth: dict[int, int] = {}
    for i, (_label, body) in enumerate(named, start=1):
        if body in part_geoms:
            continue
        root = m.body(body).id
        for b in range(m.nbody):
            d = _depth_below(m, b, root)
            if d is not None and (b not in depth or d < depth[b]):
                depth[b] = d
                body_to_obj[b] = i
    geom_to_obj = body_to_obj[m.geom_bodyid]
    for i, (_label, body) in enumerate(named, start=1):
        if body in part_geoms:
            geom_to_obj[sorted(part_geoms[body])] = i
    return labels, geom_to_obj


def _depth_below(m: mujoco.MjModel, b: int, root: int) -> int | None:
    d = 0
    while True:
        if b == root:
            return d
        if b == 0:
            return None
        b = m.body_parentid[b]
        d += 1


def intrinsics(model: mujoco.MjModel, camera: str, width: int, height: int) -> np.ndarray:
    fovy = np.radians(model.camera(camera).fovy[0])
    f = 0.5 * height / np.tan(fovy / 2)
    return np.array([[f, 0, (width - 1) / 2], [0, f, (height - 1) / 2], [0, 0, 1.0]])


def _depth_of_last_pass(r: mujoco.Renderer) -> np.ndarray:
    """Metric depth (H, W float32, m) from the depth buffer of the pass just drawn, converted as mujoco.Renderer
    converts it (3.3.7's code). The id pass draws with the same flags as Renderer's depth pass (segment and
    id colours on), so its depth buffer is the depth pass's, without drawing the scene a third time;
    tests/sim/test_robosuite_deferred_rgb.py checks it equals Renderer's own depth render."""
    out = np.empty((r.height, r.width), dtype=np.float32)
    mujoco.mjr_readPixels(None, out, r._rect, r._mjr_context)
    m = r.model
    zfar = np.float32(m.vis.map.zfar * m.stat.extent)
    znear = np.float32(m.vis.map.znear * m.stat.extent)
    c_coef = -(zfar + znear) / (zfar - znear)
    d_coef = -(np.float32(2) * zfar * znear) / (zfar - znear)
    c_coef = np.float32(-0.5) * c_coef - np.float32(0.5)  # reversed Z
    d_coef = np.float32(-0.5) * d_coef
    depth = (d_coef / (out.astype(np.float64) + c_coef)).astype(np.float32)
    return np.flipud(depth).copy() if r._gl_context else depth


def without_sites() -> mujoco.MjvOption:
    """Scene options that draw no site: robosuite and LIBERO give the gripper and every placement region a site
    with alpha 0, invisible in RGB but written into the depth buffer (a 30 cm cylinder below robosuite's gripper;
    1,579 depth pixels of one LIBERO agentview frame, up to 2 m nearer than the surface behind). A camera sees
    surfaces, so no pass draws them."""
    opt = mujoco.MjvOption()
    opt.sitegroup[:] = 0
    return opt


def render_frame(world, camera: str, width: int, height: int) -> CameraFrame:
    """One frame of `camera` (width x height px) as the world is now; on the world's render thread. A world with
    `defer_rgb` gets a DeferredFrame (its RGB drawn when first read, identical to drawing it now)."""
    m, d = world.model, world.data
    r = _renderer(world, width, height)
    deferred = bool(getattr(world, "defer_rgb", False))
    rgb: Any
    if deferred:
        rgb = _draw_later(world, camera, width, height)
    else:
        r.update_scene(d, camera=camera, scene_option=without_sites())
        rgb = r.render().copy()
    r.enable_segmentation_rendering()
    r.update_scene(d, camera=camera, scene_option=without_sites())
    seg = r.render()
    r.disable_segmentation_rendering()
    depth = _depth_of_last_pass(r)
    if getattr(world, "_label_cache", None) is None:
        world._label_cache = label_table(world)
    labels, geom_to_obj = world._label_cache
    geom_ids = seg[:, :, 0]
    is_geom = (seg[:, :, 1] == int(mujoco.mjtObj.mjOBJ_GEOM)) & (geom_ids >= 0)
    obj = np.zeros(geom_ids.shape, dtype=np.int32)
    obj[is_geom] = geom_to_obj[geom_ids[is_geom]]
    cid = m.camera(camera).id
    T = np.eye(4)
    T[:3, :3] = d.cam_xmat[cid].reshape(3, 3) @ np.diag([1.0, -1.0, -1.0])
    T[:3, 3] = d.cam_xpos[cid] - getattr(world, "origin_m", 0.0)  # in the world's frame
    kind = DeferredFrame if deferred else CameraFrame
    return kind(camera, rgb, depth, intrinsics(m, camera, width, height), T, world.sim_time_s, obj, labels)
