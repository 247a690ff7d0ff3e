"""The CaP-Bench robosuite environments as CaP-X defines them, built and seeded for one trial.

CaP-X changes to stock robosuite 1.4 (see notes/STACK_FACTS.md): Stack samples both cubes over x +-0.18 m,
y +-0.12 m; CubeRestack is Stack with two 4 cm cubes and the green one starting on the red one (goal: red on
green); horizons (robosuite steps at 20 Hz) Lift 1500, Wipe 4000, NutAssemblySquare 1000. robosuite 1.4 has no
seed argument: its samplers and initialisation noise draw from numpy's global generator, seeded here right
before the reset.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from .robosuite_world import ROBOSUITE_CONTROL_HZ, require_robosuite


@dataclass(frozen=True)
class CapEnv:
    """How to build one CaP-Bench task's robosuite env."""

    env_name: str
    horizon_steps: int
    robots: tuple[str, ...] = ("Panda",)
    kwargs: Callable[[], dict[str, Any]] | None = None  # extra suite.make arguments, built at make time

    @property
    def horizon_s(self) -> float:
        return self.horizon_steps / ROBOSUITE_CONTROL_HZ


def _wide_stack_sampler() -> dict[str, Any]:
    from robosuite.utils.placement_samplers import UniformRandomSampler

    return {
        "placement_initializer": UniformRandomSampler(
            name="ObjectSampler",
            x_range=[-0.18, 0.18],
            y_range=[-0.12, 0.12],
            rotation=None,
            ensure_object_boundary_in_range=False,
            ensure_valid_placement=True,
            reference_pos=(0, 0, 0.8),
            z_offset=0.01,
        )
    }


def _cube_restack_class():
    """Stack with two 4 cm cubes, green (cubeB) placed on red (cubeA) at reset."""
    from robosuite.environments.manipulation.stack import Stack
    from robosuite.models.objects import BoxObject
    from robosuite.models.tasks import ManipulationTask

    class CubeRestack(Stack):
        def _load_model(self):
            super()._load_model()
            green = BoxObject(
                name="cubeB", size_min=[0.02] * 3, size_max=[0.02] * 3, rgba=[0, 1, 0, 1], material=self.cubeB.material
            )
            self.cubeB = green
            self.placement_initializer.reset()
            self.placement_initializer.add_objects([self.cubeA, self.cubeB])
            self.model = ManipulationTask(
                mujoco_arena=self.model.mujoco_arena,
                mujoco_robots=[r.robot_model for r in self.robots],
                mujoco_objects=[self.cubeA, self.cubeB],
            )

        def _reset_internal(self):
            super()._reset_internal()
            ja, jb = self.cubeA.joints[0], self.cubeB.joints[0]
            pose = np.array(self.sim.data.get_joint_qpos(ja))
            pose[2] += 0.04  # green's centre one cube height above red's: resting on it
            self.sim.data.set_joint_qpos(jb, pose)
            self.sim.forward()

    return CubeRestack


ENVS: dict[str, CapEnv] = {
    "Lift": CapEnv("Lift", 1500),
    "Stack": CapEnv("Stack", 1000, kwargs=_wide_stack_sampler),
    "CubeRestack": CapEnv("CubeRestack", 1000, kwargs=_wide_stack_sampler),
    "Wipe": CapEnv("Wipe", 4000),
    "NutAssemblySquare": CapEnv("NutAssemblySquare", 1000),
    "TwoArmLift": CapEnv("TwoArmLift", 1000, ("Panda", "Panda")),
    "TwoArmHandover": CapEnv("TwoArmHandover", 1000, ("Panda", "Panda")),
}


WIPE_MARKERS = 100  # robosuite Wipe's default task_config: 100 dirt markers in one trail


class WipeReferee:
    """robosuite Wipe's bookkeeping, which robosuite does inside `env.step` (not called here: we step physics).

    Every 50 ms of simulated time (one robosuite step at 20 Hz) it runs robosuite's own `env.reward()`, which
    wipes (makes transparent) every marker lying within 2 cm above the pad's pressed face while something is in
    contact, unless the arm touches something or nears a joint limit. Like robosuite's early termination, the
    episode ends for good at the first such arm contact or joint limit: nothing is wiped after it."""

    def __init__(self, env):
        self.env = env
        self.next_t_s = 0.0
        self.ended: str = ""

    def __call__(self, world) -> None:
        if self.ended or world.sim_time_s + 1e-9 < self.next_t_s:
            return
        self.next_t_s = world.sim_time_s + 1.0 / ROBOSUITE_CONTROL_HZ
        env = self.env
        env.reward()  # robosuite's marker update
        if env.check_contact(env.robots[0].robot_model):
            self.ended = f"the arm touched the table at t={world.sim_time_s:.2f} s (robosuite ends the episode)"
        elif env.robots[0].check_q_limits():
            self.ended = (
                f"a joint came within 0.1 rad of its limit at t={world.sim_time_s:.2f} s (robosuite ends the episode)"
            )

    @property
    def summary(self) -> str:
        wiped = len(self.env.wiped_markers)
        return f"{wiped} of {WIPE_MARKERS} markers wiped" + (f"; {self.ended}" if self.ended else "")


def make_env(name: str, seed: int):
    """Build and reset the env for `seed` (deterministic: same seed, same start state)."""
    suite = require_robosuite()
    spec = ENVS[name]
    kwargs = dict(
        has_renderer=False,
        has_offscreen_renderer=False,
        use_camera_obs=False,
        use_object_obs=True,
        control_freq=ROBOSUITE_CONTROL_HZ,
        horizon=spec.horizon_steps,
        ignore_done=True,
        hard_reset=False,
        robots=list(spec.robots) if len(spec.robots) > 1 else spec.robots[0],
    )
    if len(spec.robots) > 1:
        kwargs["env_configuration"] = "single-arm-opposed"
    kwargs.update(spec.kwargs() if spec.kwargs else {})
    state = np.random.get_state()
    try:
        np.random.seed(seed)
        if name == "CubeRestack":
            env = _cube_restack_class()(**kwargs)
        else:
            env = suite.make(spec.env_name, **kwargs)
        np.random.seed(seed)
        env.reset()
    finally:
        np.random.set_state(state)
    return env
