"""A task: the scene it needs, the instruction, a success predicate over simulator state, a reference plan."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from importlib import resources

import numpy as np

from ..embodiments import robots_for
from ..scene import ObjectRequest, build_scene
from ..world import MujocoWorld


@dataclass(frozen=True)
class TaskSpec:
    """`success(world)` reads privileged state: it is the evaluation, never an input to planning or control.

    `setup(world, rng)` prepares the start state (a drawer left open, beads in a mug) and may register monitors;
    `max_sim_s` bounds a trial in simulated seconds.
    """

    name: str
    instruction: str
    objects: tuple[ObjectRequest, ...]
    success: Callable[[MujocoWorld], bool]
    predicate: str  # the success predicate in words, for reports
    setup: Callable[[MujocoWorld, np.random.Generator], None] | None = None
    max_sim_s: float = 60.0
    tags: tuple[str, ...] = field(default_factory=tuple)
    embodiments: tuple[str, ...] = ("panda", "ur10", "bimanual")  # where the task fits; the first is the default
    # Worlds not built by our scene builder (robosuite, LIBERO): seed -> world, already in its start state
    world_factory: Callable[[int], MujocoWorld] | None = None

    @property
    def has_reference_plan(self) -> bool:
        return resources.files(__package__).joinpath("reference", f"{self.name}.yaml").is_file()

    def reference_plan_text(self) -> str:
        if not self.has_reference_plan:  # e.g. LIBERO-PRO: its plans come from a planner
            raise FileNotFoundError(
                f"task {self.name!r} has no reference plan: run it with a planner (rules, gemini or openai)"
            )
        return resources.files(__package__).joinpath("reference", f"{self.name}.yaml").read_text(encoding="utf-8")

    def make_world(self, seed: int, embodiment: str | None = None) -> MujocoWorld:
        embodiment = embodiment or self.embodiments[0]
        if embodiment not in self.embodiments:
            raise ValueError(
                f"task {self.name!r} needs one of the embodiments {', '.join(self.embodiments)}, not {embodiment!r}"
            )
        if self.world_factory is not None:
            world = self.world_factory(seed)
        else:
            world = MujocoWorld(build_scene(robots_for(embodiment), list(self.objects), seed))
        if self.setup is not None:
            self.setup(world, np.random.default_rng(seed + 10_000))
        world.settle(0.3)
        return world
