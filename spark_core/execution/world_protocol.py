"""The World protocol: what the executor's primitives need from an embodiment (simulated or real).

Sensing is what a robot can measure (joint angles, TCP pose from forward kinematics, finger gap, touch);
ground-truth object state is NOT part of it.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Protocol, runtime_checkable

import numpy as np

from ..control.kinematics import ArmKinematics
from ..control.pose import Pose
from ..control.trajectory import JointTrajectory


@runtime_checkable
class World(Protocol):
    arms: tuple[str, ...]
    kinematics: dict[str, ArmKinematics]

    @property
    def sim_time_s(self) -> float: ...

    def q(self, arm: str) -> np.ndarray: ...

    def tcp_pose(self, arm: str) -> Pose: ...

    def gripper_width_m(self, arm: str) -> float: ...

    def pinched_bodies(self, arm: str) -> set[int]:
        """Touch sensing: ids of things both fingers are in contact with."""
        ...

    def wrist_force_n(self, arm: str) -> float:
        """External contact force (N) on the hand and the object it holds (a wrist F/T sensor)."""
        ...

    def execute(
        self, arm: str, traj: JointTrajectory, stop: Callable[[], bool] | None = None, settle_s: float = 0.1
    ): ...

    def set_gripper(self, arm: str, width_m: float, force_n: float, duration_s: float = 0.6) -> float: ...

    def settle(self, seconds: float, arm: str | None = None) -> float: ...
