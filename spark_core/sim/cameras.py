"""On-demand camera frames: RGB, metric depth, per-pixel object ids, intrinsics and extrinsics (OpenCV convention).

Rendering is the expensive part of simulation; nothing renders unless perception (or the UI) asks.
"""

from __future__ import annotations

import mujoco
import numpy as np

from ..perception.frame import CameraFrame


def _renderer(world, width: int, height: int) -> mujoco.Renderer:
    r = world.renderer
    if r is None or (r.width, r.height) != (width, height):
        if r is not None:
            r.close()
        r = world.renderer = mujoco.Renderer(world.model, height, width)
    return r


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


def render_frame(world, camera: str, width: int, height: int) -> CameraFrame:
    m, d = world.model, world.data
    r = _renderer(world, width, height)
    r.update_scene(d, camera=camera)
    rgb = r.render().copy()
    r.enable_depth_rendering()
    r.update_scene(d, camera=camera)
    depth = r.render().astype(np.float32).copy()
    r.disable_depth_rendering()
    r.enable_segmentation_rendering()
    r.update_scene(d, camera=camera)
    seg = r.render()
    r.disable_segmentation_rendering()
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
    return CameraFrame(camera, rgb, depth, intrinsics(m, camera, width, height), T, world.sim_time_s, obj, labels)
