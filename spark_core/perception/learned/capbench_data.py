"""CaP-Bench scenes for the learned segmenter's training data and held-out benchmark: the seven robosuite tasks as
CaP-X builds them (`sim.capbench_envs.make_env`: its wide Stack sampler, CubeRestack, the two-arm envs), every
object placed by the env's own samplers and initialisation noise (numpy's global RNG seeded from the scene seed
right before the reset, as `make_env` does for a trial), never a trial's start state: `spark bench capbench` uses
seeds 0..999 and nothing here draws from that range.

TRAINING / SCORING ONLY: labels come from the renderer's ids (privileged). The segmenter never imports this.

Seeds: scene seed `s` is a scene of task TASKS[(s // 5) % 7]; its env is built from the block's first seed
(`s - s % 5`: robosuite draws some sizes, e.g. Lift's cube, when it builds the model), so the same seed gives
the same scene whatever was rendered before. Training uses CAPBENCH_TRAIN_SEED0 + k, the perception benchmark
CAPBENCH_BENCH_SEED0 + k, tests and diagnostics CAPBENCH_DEV_SEED0 + k; all three are = 0 mod 35 (their first
scene is Lift's) and disjoint from every other source's ranges.
"""

from __future__ import annotations

import gc
import re
from typing import Any

import mujoco
import numpy as np

from ...sim.capbench_envs import ENVS
from .categories import BACKGROUND, CATEGORIES, CATEGORY_INDEX, COLOUR_INDEX, ROBOT, TABLE
from .scene_jitter import jitter, seeded_numpy

CAPBENCH_TRAIN_SEED0 = 1_700_020
CAPBENCH_BENCH_SEED0 = 960_050
CAPBENCH_DEV_SEED0 = 955_010
TASKS: tuple[str, ...] = tuple(ENVS)  # Lift, Stack, CubeRestack, Wipe, NutAssemblySquare, TwoArmLift, TwoArmHandover
# 5: a dataset's validation crops (its highest-seed 5 %: 30 of 600 scenes) then span six of the seven tasks
SCENES_PER_TASK = 5
PERCEPTION_CAMERAS = ("agentview", "sideview")  # what tasks/capbench.py's worlds look through (RobosuiteWorld's)
SETTLE_STEPS = 250  # 0.5 s of physics after the reset: CubeRestack's green cube settles on the red one

# The robosuite body that roots each CaP-Bench object -> (category, colour). Colours only where the task names
# one (robosuite's textures say nothing: the cubes are "redwood" and "greenwood").
OBJECT_BODIES: dict[str, tuple[str, str]] = {
    "cube_main": ("block", "red"),  # Lift
    "cubeA_main": ("block", "red"),  # Stack, CubeRestack
    "cubeB_main": ("block", "green"),
    "SquareNut_main": ("nut", "none"),  # ring and handle: one nut
    "RoundNut_main": ("nut", "none"),  # NutAssemblySquare moves it out of the scene (single-object mode)
    "peg1": ("peg", "none"),  # square peg
    "peg2": ("peg", "none"),  # round peg
    "pot_root": ("pot", "none"),  # TwoArmLift, handles included
    "hammer_root": ("hammer", "none"),  # TwoArmHandover
}
DIRT_BODY = re.compile(r"contact\d+_main$")  # Wipe's 100 marker discs: together one region, as tasks/capbench.py


def category_index(name: str) -> int:
    """Index of a CaP-Bench object's category (the pot, hammer and dirt have their own since 2026-11-27)."""
    return CATEGORY_INDEX[name]


def task_index(seed: int) -> int:
    """Scene seed -> index into TASKS: SCENES_PER_TASK consecutive seeds share a task (and its env)."""
    return (seed // SCENES_PER_TASK) % len(TASKS)


def task_of_seed(seed: int) -> str:
    return TASKS[task_index(seed)]


class CapbenchScenes:
    """Randomised CaP-Bench scenes, one env kept while consecutive scenes use it (a task's block of
    SCENES_PER_TASK seeds). `scene(seed)` resets the env from `seed` with the env's own samplers, settles it, then
    (from the same seed) jitters lighting and, in 70 % of scenes, the arms' joints, and returns the world (valid
    until the next `scene` call or `close`)."""

    def __init__(self, perturb: bool = True):
        self.perturb = perturb
        self.task: str | None = None
        self._key: tuple[str, int] | None = None
        self._env: Any = None
        self._world: Any = None
        self._light0: tuple[np.ndarray, np.ndarray] | None = None

    def scene(self, seed: int, task: str | None = None):
        from ...sim.capbench_envs import make_env
        from ...sim.robosuite_world import RobosuiteWorld
        from ...sim.tasks.capbench import OBJECTS

        task = task or task_of_seed(seed)
        key = (task, seed - seed % SCENES_PER_TASK)
        if key != self._key:
            self.close()
            gc.collect()  # the old env's reference cycles: a 2-scene-per-block loop plateaued at 2.0 GB, 1.5 with this
            self._env, self._key, self.task = make_env(task, key[1]), key, task
        env = self._env
        with seeded_numpy(seed):
            env.reset()
        if self._world is None:
            env._spark_release = lambda: None  # close() hands the env back instead of freeing it
            self._world = RobosuiteWorld(env, OBJECTS[task], seed=seed, perception_cameras=PERCEPTION_CAMERAS)
            m = self._world.model
            self._light0 = (m.light_diffuse.copy(), m.light_pos.copy())
        world = self._world
        world.reset()  # hold the arms where the reset left them
        world._tick(SETTLE_STEPS)
        m, d = world.model, world.data
        assert self._light0 is not None
        jitter(world, self._light0, seed, self.perturb)
        mujoco.mj_forward(m, d)
        world._label_cache = None
        return world

    def close(self) -> None:
        if self._world is not None:
            self._world.close()
        self._world = self._env = self._key = self.task = None


def _object_root(m, body: int) -> tuple[int, str] | None:
    """The CaP-Bench object a body belongs to: (root body id, its name), or None."""
    b = body
    while b > 0:
        name = m.body(b).name
        if name in OBJECT_BODIES or DIRT_BODY.match(name):
            return b, name
        b = int(m.body_parentid[b])
    return None


def capbench_geom_tables(world) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Per geom id: category index, instance id (0 = none) and colour index for a CaP-Bench world: each object
    one instance, parts included (the nut's handle, the pot's handles: a boundary inside one object would teach
    the network to cut it), Wipe's markers together one; robot geoms ROBOT, the table's TABLE, the rest
    background. Instance ids are the scene's object ids (sim.cameras.label_table) where the object has one, as
    the perception bench's true-mask keypoints expect."""
    from ...sim.cameras import label_table

    m = world.model
    labels, _ = label_table(world)
    ids: dict[str, int] = {}
    for i, label in sorted(labels.items()):  # a body's whole object, else its first part (the nut is its ring)
        if label in world.scene.objects:
            ids[world.scene.objects[label].body] = i
        else:  # Wipe's dirt is a part of the table body
            ids.setdefault("dirt" if label == "dirt" else world.scene.parts[label][0].split("#")[0], i)
    robot_bodies = {m.body(b).id for n in world.scene.robots.values() for b in n.bodies}
    table = mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_BODY, "table")
    thing = np.array([c.thing for c in CATEGORIES])
    cat = np.full(m.ngeom, BACKGROUND, np.uint8)
    inst = np.zeros(m.ngeom, np.int32)
    colour = np.zeros(m.ngeom, np.uint8)
    for g in range(m.ngeom):
        body = int(m.geom_bodyid[g])
        root = _object_root(m, body)
        if root is not None:
            name = "dirt" if DIRT_BODY.match(root[1]) else root[1]
            category, colour_name = ("dirt", "none") if name == "dirt" else OBJECT_BODIES[name]
            cat[g] = category_index(category)
            if thing[cat[g]]:
                inst[g] = ids.setdefault(name, max([0, *labels, *ids.values()]) + 1)  # e.g. the hidden round nut
                colour[g] = COLOUR_INDEX[colour_name]
        elif body == table and table >= 0:
            cat[g] = TABLE
        elif body in robot_bodies:
            cat[g] = ROBOT
    return cat, inst, colour
