"""LIBERO scenes for the learned segmenter's training data and held-out benchmark: the LIBERO-PRO tasks' own
BDDL files, each object placed by LIBERO's placement samplers (the env's reset, its global numpy RNG seeded with
the scene seed), NEVER an init state: the LIBERO-PRO init states (data/liberopro/init_files) and the libero
package's init files are what `spark bench liberopro` evaluates on, and nothing here reads them.

TRAINING / SCORING ONLY: labels come from the renderer's ids (privileged). The segmenter never imports this.

Seeds: scene seed `s` uses task `tasks()[(s // 10) % 60]`; training uses LIBERO_TRAIN_SEED0 + k, the perception
benchmark LIBERO_BENCH_SEED0 + k, tests and diagnostics LIBERO_DEV_SEED0 + k: disjoint ranges, all far from
the benchmarks' init-state indices (0..49).
"""

from __future__ import annotations

from typing import Any

import mujoco
import numpy as np

from .categories import BACKGROUND, CATEGORIES, CATEGORY_INDEX, COLOUR_INDEX, ROBOT, TABLE, category_of_libero
from .scene_jitter import jitter, seeded_numpy

LIBERO_TRAIN_SEED0 = 1_500_000
# = 0 mod 600: seed LIBERO_BENCH_SEED0 + 10 * i + k is a scene of task i. Moved from 912,000 on 2026-11-26: some
# scenes of that range were looked at while developing; LIBERO_DEV_SEED0 keeps them for tests and diagnostics.
LIBERO_BENCH_SEED0 = 918_000
LIBERO_DEV_SEED0 = 912_000
CAMERAS = ("agentview", "frontview", "robot0_eye_in_hand")  # the suite's perception cameras and the wrist
SCENES_PER_TASK = 10
SETTLE_STEPS = 250  # 0.5 s of physics after the reset (the benchmark's 10 no-op robosuite steps)


def libero_tasks() -> list:
    from ...sim.libero_envs import tasks

    out = tasks()
    if not out:
        raise RuntimeError("no LIBERO-PRO task files found (data/liberopro/bddl_files): see sim/libero_envs.py")
    return out


def task_index(seed: int) -> int:
    """Scene seed -> index into libero_tasks(): SCENES_PER_TASK consecutive seeds share a task (and its env)."""
    return (seed // SCENES_PER_TASK) % len(libero_tasks())


def task_of_seed(seed: int):
    return libero_tasks()[task_index(seed)]


def build_env(task) -> Any:
    """LIBERO's ControlEnv for a task's BDDL file (placement samplers as LIBERO defines them; no init state)."""
    from ...sim.libero_envs import build_control_env

    return build_control_env(task)


def make_world(env, seed: int):
    """A RobosuiteWorld on `env` (the env survives the world's close: it is reused for the task's next scene)."""
    from ...sim.libero_envs import objects
    from ...sim.robosuite_world import RobosuiteWorld

    env.env._spark_release = lambda: None  # close() hands the env back instead of freeing it
    return RobosuiteWorld(env.env, objects(env), seed=seed, perception_cameras=("agentview", "frontview"))


class LiberoScenes:
    """Randomised LIBERO scenes, one env per task kept while consecutive scenes use it. `scene(seed)` resets the
    env with LIBERO's samplers from `seed`, settles it, then (from the same seed) jitters lighting and, in 70 %
    of scenes, the arm's joints, and returns the world (valid until the next `scene` call or `close`). With
    `rearrange`, objects also trade places or are set on top of others (rearrange.py) before the settle; with
    `mid_task`, a drawer may be pulled out and the hand posed at an object, sometimes holding it (mid_task.py)."""

    def __init__(self, perturb: bool = True, rearrange: bool = False, mid_task: bool = False):
        self.perturb = perturb
        self.rearrange = rearrange
        self.mid_task = mid_task
        self.moves: list[tuple[str, str, str]] = []  # what rearrange did to the last scene (rearrange.Move)
        self.mid: list[str] = []  # what mid_task did to the last scene ("drawer opened", "hand at ...")
        self._task = None
        self._env: Any = None
        self._world: Any = None
        self._light0: tuple[np.ndarray, np.ndarray] | None = None

    def scene(self, seed: int, task=None):
        task = task or task_of_seed(seed)
        if self._task is None or task.name != self._task.name:
            self.close()
            self._env, self._task = build_env(task), task
        env = self._env
        with seeded_numpy(seed):
            env.reset()
        if self._world is None:
            self._world = make_world(env, seed)
            m = self._world.model
            self._light0 = (m.light_diffuse.copy(), m.light_pos.copy())
        world = self._world
        self.moves = []
        if self.rearrange:
            from .rearrange import rearrange

            self.moves = rearrange(world, np.random.default_rng([seed, 2]), float(world.origin_m[2]))
        self.mid = []
        mid_rng = np.random.default_rng([seed, 3])
        drawer = None
        if self.mid_task:
            from .mid_task import open_drawer

            drawer = open_drawer(world, mid_rng)
            self.mid += ["drawer opened"] if drawer is not None else []
        world.reset()  # hold the arm where the reset left it
        world._tick(SETTLE_STEPS)
        m, d = world.model, world.data
        assert self._light0 is not None
        jitter(world, self._light0, seed, self.perturb)
        if self.mid_task:
            from .mid_task import pose_arm

            mujoco.mj_forward(m, d)
            done = pose_arm(world, mid_rng, drawer)  # replaces the jitter where it poses the hand
            self.mid += [done] if done else []
        mujoco.mj_forward(m, d)
        world._label_cache = None  # same bodies, but a fresh table costs nothing next to a render
        return world

    def close(self) -> None:
        if self._world is not None:
            self._world.close()
        self._world = self._env = self._task = None


def libero_geom_tables(world) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Per geom id: category index, instance id (0 = none) and colour index for a LIBERO world. Colours are
    supervised only where the object's name says one ("akita black bowl"): LIBERO's objects are textured, so
    their geom colours say nothing."""
    from ...sim.cameras import label_table

    m = world.model
    labels, geom_to_obj = label_table(world)
    obj_cat = {i: category_of_libero(label) for i, label in labels.items()}
    obj_col = {
        i: next((COLOUR_INDEX[w] for w in label.split() if w in COLOUR_INDEX and w != "none"), 0)
        for i, label in labels.items()
    }
    robot_bodies = {m.body(b).id for n in world.scene.robots.values() for b in n.bodies}
    table = mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_BODY, "table")
    cat = np.full(m.ngeom, BACKGROUND, np.uint8)
    colour = np.zeros(m.ngeom, np.uint8)
    for g in range(m.ngeom):
        body = int(m.geom_bodyid[g])
        if geom_to_obj[g]:
            cat[g] = obj_cat[int(geom_to_obj[g])]
            colour[g] = obj_col[int(geom_to_obj[g])]
        elif body == table and table >= 0:
            cat[g] = TABLE
        elif body in robot_bodies:
            cat[g] = ROBOT
    _label_drawers(m, cat, geom_to_obj, colour)
    thing = np.array([CATEGORIES[c].thing for c in range(len(CATEGORIES))])
    inst = np.where(thing[cat], geom_to_obj, 0)  # a labelled floor or table is no instance
    return cat, inst.astype(np.int32), colour


DRAWER_HANDLE_MAX_HALF_M = 0.05  # a drawer body's geoms no larger than this (half extent) are its handle


def _label_drawers(m, cat: np.ndarray, inst: np.ndarray, colour: np.ndarray) -> None:
    """Every drawer of a cabinet (a body on a slide joint whose geoms are labelled cabinet, drawer or handle) as
    two instances, open or closed: its handle (its small geoms) and the drawer (the rest). The adapter names a
    drawer's parts only where its handle stands out of the closed front (sim/libero_envs.py), which would label
    the same-looking drawer `cabinet` in one scene and `drawer` in the next."""
    cabinetish = {CATEGORY_INDEX[n] for n in ("cabinet", "drawer", "drawer handle")}
    slide_bodies = {int(m.jnt_bodyid[j]) for j in range(m.njnt) if m.jnt_type[j] == mujoco.mjtJoint.mjJNT_SLIDE}
    next_id = int(inst.max()) + 1
    for b in sorted(slide_bodies):
        geoms = [g for g in range(m.ngeom) if m.geom_bodyid[g] == b]
        if not geoms or any(cat[g] not in cabinetish for g in geoms):
            continue
        handle = [g for g in geoms if float(m.geom_aabb[g][3:].max()) <= DRAWER_HANDLE_MAX_HALF_M]
        rest = [g for g in geoms if g not in handle]
        for part, members in (("drawer handle", handle), ("drawer", rest)):
            if members:
                cat[members] = CATEGORY_INDEX[part]
                inst[members] = next_id
                colour[members] = 0
                next_id += 1
