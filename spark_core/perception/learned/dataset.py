"""Training data for the learned segmenter: randomised scenes rendered with the cameras the suites use, labelled
per pixel (category, instance, colour) from the renderer's ids.

TRAINING ONLY: the labels are simulator ground truth (privileged). Nothing here is imported by the segmenter.

Sources: "builtin" (random_world below), "libero" (libero_data.py: LIBERO-PRO tasks' scenes from LIBERO's
own placement samplers, never an evaluation init state) and "capbench" (capbench_data.py: the CaP-Bench robosuite
envs reset from seeds far from the benchmark's 0..999).

Seeds: scene `i` of a dataset with first seed `s` is built from seed `s + i`. Training data uses seeds from
TRAIN_SEED0; the perception benchmark's held-out scenes use BENCH_SEED0; both are far above every evaluation
seed range of the task benchmarks (seeds 0..999).
"""

from __future__ import annotations

import time
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import mujoco
import numpy as np

from .categories import BACKGROUND, COLOUR_INDEX, ROBOT, TABLE, category_of_kind

TRAIN_SEED0 = 1_000_000
# The perception benchmark's held-out scenes. Moved from 900,000 on 2026-11-26: some scenes of that range were
# looked at while developing the learned segmenter; DEV_SEED0 keeps them for tests and diagnostics.
BENCH_SEED0 = 940_000
DEV_SEED0 = 900_000
RENDER_SIZE = (640, 480)  # (width, height): the cameras' run-time resolution; the network sees it at full scale
CROP_SIZE = (320, 240)  # (width, height) of the stored training crops
RANDOM_KINDS = ("block", "bowl", "plate", "mug", "tray", "basket", "sponge", "bottle", "peg", "nut", "brush", "zone")
STACKABLE_ON = {"block": 0.04, "plate": 0.016, "tray": 0.004, "bowl": 0.006, "basket": 0.006, "zone": 0.001}


@dataclass
class LabelledFrame:
    """One rendered view with its per-pixel labels (all at the same resolution)."""

    camera: str
    rgb: np.ndarray  # (H, W, 3) uint8
    depth_m: np.ndarray  # (H, W) float32
    category: np.ndarray  # (H, W) uint8, index into CATEGORIES
    instance: np.ndarray  # (H, W) uint8, 0 = none, else one id per object/part in the frame
    colour: np.ndarray  # (H, W) uint8, index into COLOURS (0 where not an object)
    K: np.ndarray
    T_world_camera: np.ndarray


def _palette() -> tuple[np.ndarray, np.ndarray]:
    from ...sim.objects import COLORS

    names = [("brown" if n == "wood" else n) for n in COLORS]
    return np.array([COLOUR_INDEX[n] for n in names], np.uint8), np.array([c[:3] for c in COLORS.values()])


def geom_tables(world) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Per geom id: category index, instance id (object/part, 0 = none) and colour index, from the scene's
    object table (the same ids the `sim` segmenter's frames carry)."""
    from ...sim.cameras import label_table

    m = world.model
    labels, geom_to_obj = label_table(world)
    obj_cat = {}
    for i, label in labels.items():
        if label in world.scene.objects:
            obj_cat[i] = category_of_kind(world.scene.objects[label].spec.kind)
        else:
            body, _ = world.scene.parts[label]
            owner = next(o for o in world.scene.objects.values() if body.startswith(o.body + "/"))
            obj_cat[i] = category_of_kind(label[len(owner.label) + 1 :])
    cat = np.full(m.ngeom, BACKGROUND, np.uint8)
    robot_bodies = {m.body(b).id for n in world.scene.robots.values() for b in n.bodies}
    for g in range(m.ngeom):
        if geom_to_obj[g]:
            cat[g] = obj_cat[int(geom_to_obj[g])]
        elif m.geom(g).name == "table":
            cat[g] = TABLE
        elif int(m.geom_bodyid[g]) in robot_bodies or m.geom_bodyid[g] != 0:
            cat[g] = ROBOT
    idx, rgb = _palette()
    nearest = idx[np.argmin(((m.geom_rgba[:, None, :3] - rgb[None]) ** 2).sum(-1), axis=1)]
    colour = np.where(geom_to_obj > 0, nearest, 0).astype(np.uint8)
    return cat, geom_to_obj.astype(np.int32), colour


def render_labelled(world, camera: str, tables) -> LabelledFrame:
    """Render at 640x480, as the cameras do at run time, with per-pixel labels (on the world's rendering
    thread, where its EGL context lives)."""
    return world.on_render_thread(_render_labelled, world, camera, tables)


def _render_labelled(world, camera: str, tables) -> LabelledFrame:
    from ...sim.cameras import _renderer, intrinsics, without_sites

    m, d = world.model, world.data
    W, H = RENDER_SIZE
    r = _renderer(world, W, H)
    r.update_scene(d, camera=camera, scene_option=without_sites())
    rgb = r.render().copy()
    r.enable_depth_rendering()
    r.update_scene(d, camera=camera, scene_option=without_sites())
    depth = r.render().astype(np.float32).copy()
    r.disable_depth_rendering()
    r.enable_segmentation_rendering()
    r.update_scene(d, camera=camera, scene_option=without_sites())
    seg = r.render()
    r.disable_segmentation_rendering()
    cat_t, inst_t, col_t = tables
    gid = seg[:, :, 0]
    is_geom = (seg[:, :, 1] == int(mujoco.mjtObj.mjOBJ_GEOM)) & (gid >= 0)
    g = np.where(is_geom, gid, 0)
    cat = np.where(is_geom, cat_t[g], BACKGROUND).astype(np.uint8)
    inst = np.where(is_geom, inst_t[g], 0).astype(np.uint8)
    col = np.where(is_geom, col_t[g], 0).astype(np.uint8)
    cid = m.camera(camera).id
    T = np.eye(4)
    T[:3, :3] = d.cam_xmat[cid].reshape(3, 3) @ np.diag([1.0, -1.0, -1.0])
    T[:3, 3] = d.cam_xpos[cid] - getattr(world, "origin_m", 0.0)
    return LabelledFrame(camera, rgb, depth, cat, inst, col, intrinsics(m, camera, W, H), T)


def crops(frame: LabelledFrame, rng: np.random.Generator, size: tuple[int, int] = CROP_SIZE) -> list[tuple[int, int]]:
    """Top-left corners (row, col) of two crops: one around a random object pixel (objects are small in the
    table views), one anywhere."""
    w, h = size
    H, W = frame.category.shape
    corners = []
    vs, us = np.nonzero(frame.instance)
    if len(vs):
        k = int(rng.integers(len(vs)))
        r0 = int(np.clip(vs[k] - h // 2 + rng.integers(-h // 3, h // 3 + 1), 0, H - h))
        c0 = int(np.clip(us[k] - w // 2 + rng.integers(-w // 3, w // 3 + 1), 0, W - w))
        corners.append((r0, c0))
    corners.append((int(rng.integers(0, H - h + 1)), int(rng.integers(0, W - w + 1))))
    return corners


def _random_requests(rng: np.random.Generator):
    from ...sim.objects import COLORS
    from ...sim.scene import ObjectRequest

    colours = [c for c in COLORS if c != "wood"]
    reqs = []
    if rng.random() < 0.15:
        reqs.append(ObjectRequest("cabinet", "cabinet", "brown", (0.74, 0.78), (0.18, 0.26)))
    if rng.random() < 0.15:
        reqs.append(ObjectRequest("stove", "stove", "grey", (0.56, 0.62), (-0.1, 0.1)))
    n = int(rng.integers(2, 7))
    for i in range(n):
        kind = str(rng.choice(RANDOM_KINDS))
        colour = str(rng.choice(colours))
        label = f"{colour} {kind} {i}"
        base = reqs[int(rng.integers(len(reqs)))] if reqs and rng.random() < 0.2 else None
        if kind == "block" and base is not None and base.kind in STACKABLE_ON and base.near is None:
            reqs.append(
                ObjectRequest(
                    label,
                    kind,
                    colour,
                    (-0.015, 0.015),
                    (-0.015, 0.015),
                    (-0.8, 0.8),
                    STACKABLE_ON[base.kind],
                    base.label,
                )
            )
        else:
            reqs.append(ObjectRequest(label, kind, colour, (0.3, 0.72), (-0.32, 0.32), (-3.14, 3.14)))
    return reqs


def random_world(seed: int):
    """A randomised builtin world: a builtin task's scene (half the time) or random objects, a random embodiment,
    arm pose and lighting."""
    from ...sim.embodiments import robots_for
    from ...sim.scene import build_scene
    from ...sim.tasks import BUILTIN
    from ...sim.world import MujocoWorld

    rng = np.random.default_rng(seed)
    emb = str(rng.choice(["panda", "panda", "panda", "ur10", "bimanual"]))
    world = None
    if rng.random() < 0.5:
        task = BUILTIN[str(rng.choice(sorted(BUILTIN)))]
        if emb in task.embodiments:
            world = task.make_world(seed, emb)
    while world is None:
        try:
            world = MujocoWorld(build_scene(robots_for(emb), _random_requests(rng), seed))
        except RuntimeError:  # placement impossible for this draw: draw again
            continue
    m, d = world.model, world.data
    m.light_diffuse[:] = m.light_diffuse * rng.uniform(0.6, 1.35)
    m.light_pos[:, :2] += rng.normal(0, 0.25, (m.nlight, 2))
    m.geom_rgba[m.geom("table").id, :3] = np.clip(m.geom_rgba[m.geom("table").id, :3] + rng.normal(0, 0.04, 3), 0, 1)
    if rng.random() < 0.7:
        for arm in world.arms:
            adr = world._qadr[arm]
            d.qpos[adr] = d.qpos[adr] + rng.normal(0, 0.3, len(adr))
    mujoco.mj_forward(m, d)
    return world, rng


SOURCES = ("builtin", "libero", "capbench")
DEFAULT_CAMERAS = {
    "builtin": ("agentview", "side", "wrist"),
    "libero": ("agentview", "frontview", "wrist"),
    "capbench": ("agentview", "sideview", "wrist"),
}


def _scenes(
    source: str, seeds: list[int], rearrange: bool = False, mid_task: bool = False
) -> Iterator[tuple[int, Any, tuple, np.random.Generator]]:
    """(seed, world, label tables, rng) per scene; the world is valid until the next one is drawn."""
    if source == "builtin":
        for seed in seeds:
            world, rng = random_world(seed)
            try:
                yield seed, world, geom_tables(world), rng
            finally:
                world.close()
    elif source == "libero":
        from .libero_data import LiberoScenes, libero_geom_tables, task_index

        scenes = LiberoScenes(rearrange=rearrange, mid_task=mid_task)
        try:  # a task's scenes one after another: its env is built once
            for seed in sorted(seeds, key=lambda s: (task_index(s), s)):
                world = scenes.scene(seed)
                yield seed, world, libero_geom_tables(world), np.random.default_rng([seed, 1])
        finally:
            scenes.close()
    elif source == "capbench":
        from .capbench_data import CapbenchScenes, capbench_geom_tables
        from .capbench_data import task_index as capbench_task

        cap = CapbenchScenes()
        try:  # a task's scenes one after another (its env is built once per block of seeds)
            for seed in sorted(seeds, key=lambda s: (capbench_task(s), s)):
                world = cap.scene(seed)
                yield seed, world, capbench_geom_tables(world), np.random.default_rng([seed, 1])
        finally:
            cap.close()
    else:
        raise ValueError(f"unknown dataset source {source!r}; have: {', '.join(SOURCES)}")


def generate(
    out_dir: Path,
    n_scenes: int,
    seed0: int = TRAIN_SEED0,
    cameras: tuple[str, ...] | None = None,
    size: tuple[int, int] = CROP_SIZE,
    log: Callable[[str], None] = print,
    source: str = "builtin",
    rearrange: bool = False,
    mid_task: bool = False,
) -> dict:
    """Render `n_scenes` scenes of `source` (seeds seed0 .. seed0+n_scenes-1), every listed camera of each
    ("wrist" = one robot's wrist camera; default: the source's DEFAULT_CAMERAS) at 640x480, and store two crops of
    `size` (width, height) per view into out_dir/shard_<seed0>.npz. `rearrange` (libero only): objects trade
    places or stand on others (rearrange.py); `mid_task` (libero only): a drawer pulled out, the hand at an object,
    sometimes holding it (mid_task.py). Returns a summary."""
    if source not in SOURCES:
        raise ValueError(f"unknown dataset source {source!r}; have: {', '.join(SOURCES)}")
    if rearrange and source != "libero":
        raise ValueError("--rearrange applies to the libero source only (builtin scenes randomise placement already)")
    if mid_task and source != "libero":
        raise ValueError("--mid-task applies to the libero source only (builtin scenes have no LIBERO cabinets)")
    cameras = cameras or DEFAULT_CAMERAS[source]
    out_dir.mkdir(parents=True, exist_ok=True)
    keys = ("rgb", "depth_mm", "category", "instance", "colour", "seeds")
    rows: dict[str, list[np.ndarray]] = {k: [] for k in keys}
    w, h = size
    t0 = time.perf_counter()
    for i, (seed, world, tables, rng) in enumerate(
        _scenes(source, list(range(seed0, seed0 + n_scenes)), rearrange, mid_task)
    ):
        for cam in cameras:
            name = cam
            if cam == "wrist":
                name = world.scene.robots[str(rng.choice(list(world.scene.robots)))].wrist_camera
            f = render_labelled(world, name, tables)
            depth_mm = np.clip(f.depth_m * 1000, 0, 65535).astype(np.uint16)
            for r0, c0 in crops(f, rng, size):
                win = (slice(r0, r0 + h), slice(c0, c0 + w))
                for k, a in zip(keys, (f.rgb, depth_mm, f.category, f.instance, f.colour)):
                    rows[k].append(a[win])
                rows["seeds"].append(np.array(seed))
        if (i + 1) % 20 == 0:
            log(f"scene {i + 1}/{n_scenes} ({time.perf_counter() - t0:.0f} s)")
    path = out_dir / f"shard_{seed0}.npz"
    arrays: dict[str, np.ndarray] = {k: np.stack(v) for k, v in rows.items()}
    # written under another name, then renamed: a render stopped mid-write leaves no truncated shard_*.npz for
    # training to trip over (one did: an empty shard, "No data left in file")
    partial = out_dir / f"partial_{seed0}.npz"
    np.savez_compressed(partial, **arrays)  # type: ignore[arg-type]  # numpy's stub types **kwds as allow_pickle
    partial.replace(path)
    return {
        "path": str(path),
        "source": source,
        "crops": len(rows["rgb"]),
        "scenes": n_scenes,
        "seconds": time.perf_counter() - t0,
    }


def load_shards(data_dir: Path) -> dict[str, np.ndarray]:
    """Every shard of a dataset directory concatenated (arrays keyed as in `generate`)."""
    shards = sorted(Path(data_dir).glob("shard_*.npz"))
    if not shards:
        raise FileNotFoundError(f"no dataset shards (shard_*.npz) in {data_dir}: run `spark perception dataset`")
    parts = [dict(np.load(p)) for p in shards]
    return {k: np.concatenate([p[k] for p in parts]) for k in parts[0]}
