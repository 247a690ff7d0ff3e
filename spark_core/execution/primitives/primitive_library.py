"""PrimitiveLibrary: the Actuator that executes grammar primitives on a World."""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from ...grammar import PrimitiveCall
from ...perception import Keypoint
from ..motion import ArmMotion
from ..protocols import ActionOutcome, FailureKind, Resolver
from ..world_protocol import World
from . import articulated, bimanual, contact, gripper, motions, pick_place, pouring  # noqa: F401 - register implementations
from .base import IMPLEMENTATIONS, ArmMemory, Ctx


class PrimitiveLibrary:
    """Performs one primitive per call on `world`, timing it in simulated seconds.

    `resolver` (optional) lets post-conditions look again (e.g. did the pushed object move?).
    """

    def __init__(self, world: World, resolver: Resolver | None = None, seed: int = 0, speed: float = 0.8):
        self.world = world
        self.arms = tuple(world.arms)
        self.resolver = resolver
        self.rng = np.random.default_rng(seed)
        self.motion = {
            a: ArmMotion(world, a, speed=speed, rng=np.random.default_rng(seed + i)) for i, a in enumerate(self.arms)
        }
        self.memory = {a: ArmMemory() for a in self.arms}

    def timeout_scale(self, arm: str | None) -> float:
        """How much longer than the grammar's timeouts this arm (both, for a two-arm skill) may take."""
        arms = [arm] if arm in self.world.kinematics else list(self.arms)
        return max(self.world.kinematics[a].robot.timeout_scale for a in arms)

    @staticmethod
    def implemented() -> frozenset[str]:
        return frozenset(IMPLEMENTATIONS)

    def perform(
        self, call: PrimitiveCall, keypoints: Mapping[str, Keypoint], arm: str, timeout_s: float
    ) -> ActionOutcome:
        impl = IMPLEMENTATIONS.get(call.primitive)
        if impl is None:
            return ActionOutcome.fail(f"{call.primitive} is not implemented on this embodiment", FailureKind.PLANNER)
        t0 = self.world.sim_time_s
        peers = {a: (self.motion[a], self.memory[a]) for a in self.arms}
        own = arm if arm in self.motion else self.arms[0]  # "both" (two-arm skills): they address arms via peers
        ctx = Ctx(
            self.world,
            own,
            self.motion[own],
            dict(call.args),
            keypoints,
            self.memory[own],
            self.resolver,
            self.rng,
            peers,
        )
        outcome = impl(ctx)
        outcome.sim_time_s = self.world.sim_time_s - t0
        return outcome
