"""Shared context and helpers for primitive implementations on a World."""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ...control.pose import Pose, top_down_rotation, wrap_grasp_yaw, yaw_of
from ...perception import Keypoint, LabelNotFound
from ..motion import ArmMotion
from ..protocols import ActionOutcome, FailureKind, Resolver
from ..world_protocol import World

IMPLEMENTATIONS: dict[str, Callable[[Ctx], ActionOutcome]] = {}
TABLE_CLEARANCE_M = 0.012  # lowest TCP height above the table for a top-down grasp
CONTACT_FORCE_N = 3.0


def primitive(name: str):
    """Register the implementation of grammar primitive `name`."""

    def deco(fn: Callable[[Ctx], ActionOutcome]):
        IMPLEMENTATIONS[name] = fn
        return fn

    return deco


@dataclass
class ArmMemory:
    """What an arm knows about what it carries (from its own grasp, not from ground truth)."""

    held_label: str | None = None
    held_extent_m: np.ndarray | None = None
    grasp_offset_z_m: float = 0.0  # TCP height above the held object's bottom
    # The held object's centre relative to the TCP in the hand's own (yaw) frame, m: non-zero for an off-centre
    # grasp such as a bowl's rim, so putting down can centre the object (not the hand) on its target.
    grasp_offset_xy_hand_m: np.ndarray = field(default_factory=lambda: np.zeros(2))
    held_length_m: float = 0.0  # the held object's own length along its long axis (the hand's x axis), m


@dataclass
class Ctx:
    world: World
    arm: str
    motion: ArmMotion
    args: dict[str, Any]
    keypoints: Mapping[str, Keypoint]
    memory: ArmMemory
    resolver: Resolver | None = None
    rng: np.random.Generator = field(default_factory=lambda: np.random.default_rng(0))
    peers: Mapping[str, tuple[ArmMotion, ArmMemory]] = field(default_factory=dict)  # every arm, for two-arm skills

    def for_arm(self, arm: str) -> Ctx:
        """The same call seen from another arm (handoff, two-handed lift)."""
        if arm not in self.peers:
            raise KeyError(f"no arm {arm!r} on this embodiment (arms: {', '.join(self.peers) or self.arm})")
        motion, memory = self.peers[arm]
        return Ctx(self.world, arm, motion, self.args, self.keypoints, memory, self.resolver, self.rng, self.peers)

    # -- perception ---------------------------------------------------------------------------------------------
    def kp(self, slot: str) -> Keypoint:
        return self.keypoints[self.args[slot]]

    def observe(self, label: str) -> Keypoint | None:
        """Look again (post-conditions that need perception). None when the label is not seen."""
        if self.resolver is None:
            return None
        try:
            self.resolver.refresh()
            return self.resolver.resolve(label)
        except LabelNotFound:
            return None

    def whole_of(self, label: str) -> Keypoint | None:
        """The object a part label belongs to ("hammer handle" -> "hammer", "drawer handle" -> "drawer"); see
        `wholes_of`."""
        return next(self.wholes_of(label), None)

    def wholes_of(self, label: str):
        """What a part label belongs to, innermost first ("cabinet top drawer handle" -> "cabinet top drawer",
        then "cabinet top", "cabinet"): each leading part of the label that perception resolves to something
        bigger than the part (not the part itself, nor a sibling part such as another drawer's handle)."""
        if self.resolver is None:
            return
        part = self.keypoints.get(label)
        words = label.split()
        for n in range(len(words) - 1, 0, -1):
            try:
                whole = self.resolver.resolve(" ".join(words[:n]))
            except (LabelNotFound, KeyError):
                continue
            if part is None or float(np.max(whole.extent_m)) > float(np.max(part.extent_m)) + 0.01:
                yield whole

    # -- geometry -----------------------------------------------------------------------------------------------
    @property
    def tcp(self) -> Pose:
        return self.world.tcp_pose(self.arm)

    def current_yaw(self) -> float:
        return wrap_grasp_yaw(yaw_of(self.tcp.rotation))

    def grasp_yaw(self, kp: Keypoint) -> float:
        """Fingers close across the object's short side: yaw from its principal axis, else keep the current."""
        if kp.yaw_rad is None:
            return self.current_yaw()
        own = kp.own_extent_xy_m
        longer_along_yaw = own[0] >= own[1] if own is not None else kp.extent_m[0] >= kp.extent_m[1]
        yaw = kp.yaw_rad if longer_along_yaw else kp.yaw_rad + np.pi / 2
        return wrap_grasp_yaw(yaw)

    def top_down(self, position, yaw: float | None = None) -> Pose:
        return Pose(np.asarray(position, float), top_down_rotation(self.current_yaw() if yaw is None else yaw))

    def grasp_height(self, kp: Keypoint) -> float:
        """TCP z for a top-down grasp: the object's centre, a little below its top for tall objects."""
        top = kp.top_z_m
        depth = self.world.kinematics[self.arm].robot.gripper.grasp_depth_m
        return float(max(min(kp.position_m[2], top - 0.02), TABLE_CLEARANCE_M, top - depth))

    # -- sensing ------------------------------------------------------------------------------------------------
    def holding(self) -> bool:
        g = self.world.kinematics[self.arm].robot.gripper
        if g.mounted_tool:
            return True  # a tool fixed to the flange is always held
        return self.world.gripper_width_m(self.arm) > g.closed_empty_width_m and bool(
            self.world.pinched_bodies(self.arm)
        )

    def no_fingers(self) -> ActionOutcome | None:
        """A failure for finger skills on an arm that carries a mounted tool, else None."""
        tool = self.world.kinematics[self.arm].robot.gripper.mounted_tool
        return (
            self.fail(f"arm {self.arm!r} carries a mounted {tool} and has no fingers to grasp or release with")
            if tool
            else None
        )

    def contact(self, threshold_n: float = CONTACT_FORCE_N) -> Callable[[], bool]:
        return lambda: self.world.wrist_force_n(self.arm) > threshold_n

    def sustained_contact(self, threshold_n: float, ticks: int) -> Callable[[], bool]:
        """Force above the threshold for `ticks` consecutive control periods (ignores impact spikes)."""
        count = [0]

        def check() -> bool:
            count[0] = count[0] + 1 if self.world.wrist_force_n(self.arm) > threshold_n else 0
            return count[0] >= ticks

        return check

    def fail(self, reason: str, kind: FailureKind = FailureKind.CONTROL) -> ActionOutcome:
        return ActionOutcome.fail(reason, kind)
