"""The `liberopro` suite: LIBERO-PRO's six position/task perturbation cells, 10 tasks each, through the robosuite
adapter. A trial's seed is the init-state index (0-49). There are no reference plans: a planner writes each
plan from the env's instruction and what perception finds. Success is LIBERO's BDDL goal check within the
paper's step limit. Needs the benchmark extras (`make bench-deps`).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING, cast

from ..libero_envs import LiberoTask, make_env, objects, tasks
from ..robosuite_world import RobosuiteWorld
from .spec import TaskSpec

if TYPE_CHECKING:
    from ..world import MujocoWorld

LIBERO_PANDA = "libero-panda"


def _world(task: LiberoTask, seed: int) -> RobosuiteWorld:
    env = make_env(task, seed)
    world = RobosuiteWorld(env.env, objects(env), seed=seed, perception_cameras=("agentview", "frontview"))
    world.instruction = env.language_instruction  # the env's, never the file name's
    return world


def _success(world: RobosuiteWorld) -> bool:
    return bool(world.env._check_success())


def _spec(t: LiberoTask) -> TaskSpec:
    def world_factory(seed: int) -> RobosuiteWorld:
        return _world(t, seed)

    return TaskSpec(
        t.name,
        t.instruction,
        (),
        cast("Callable[[MujocoWorld], bool]", _success),  # its worlds are RobosuiteWorlds: see world_factory
        "LIBERO BDDL goal (env.check_success())",
        max_sim_s=t.horizon_s,
        tags=("liberopro", t.cell),
        embodiments=(LIBERO_PANDA,),
        world_factory=world_factory,
    )


SUITE: dict[str, TaskSpec] = {t.name: _spec(t) for t in tasks()}
