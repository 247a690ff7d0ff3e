"""A deterministic KINEMATIC World double for executor tests: no physics, no rendering.

It exists only so the executor core can be tested before (and independently of) the MuJoCo world. Objects are
points, the TCP teleports at a fixed speed (sim time = distance / speed), grasping succeeds when the TCP is
within 3 cm of a free object. Failures can be injected per primitive. Never used for reported figures.
"""

from __future__ import annotations

import threading
import time
from collections.abc import Mapping
from dataclasses import dataclass, field

import numpy as np

from spark_core.execution import ActionOutcome, FailureKind
from spark_core.grammar import PrimitiveCall
from spark_core.perception import Keypoint, LabelNotFound

HOME = np.array([0.3, 0.0, 0.4])
GRASP_RADIUS_M = 0.03
DIRS = {"forward": (1, 0), "backward": (-1, 0), "left": (0, 1), "right": (0, -1)}


@dataclass
class Injection:
    failure: FailureKind
    reason: str
    sim_time_s: float = 0.1


@dataclass
class KinematicWorld:
    objects: dict[str, np.ndarray]
    arms: tuple[str, ...] = ("right",)
    speed_m_s: float = 0.5
    wall_delay_s: float = 0.0  # real sleep per primitive, to make thread interleaving observable
    unreachable: set[str] = field(default_factory=set)
    log: list[tuple[str, str, dict]] = field(default_factory=list)  # (arm, primitive, args)

    def __post_init__(self) -> None:
        self.objects = {k: np.asarray(v, float) for k, v in self.objects.items()}
        self.tcp = {a: HOME.copy() for a in self.arms}
        self.held: dict[str, str | None] = {a: None for a in self.arms}
        self._inject: dict[str, list[Injection]] = {}
        self._lock = threading.RLock()

    def inject(
        self,
        primitive: str,
        n: int = 1,
        failure: FailureKind = FailureKind.CONTROL,
        reason: str = "injected failure",
        sim_time_s: float = 0.1,
    ) -> None:
        self._inject.setdefault(primitive, []).extend(Injection(failure, reason, sim_time_s) for _ in range(n))

    def move_object(self, label: str, xyz) -> None:
        with self._lock:
            self.objects[label] = np.asarray(xyz, float)

    # -- Actuator ----------------------------------------------------------------------------------------------
    def perform(
        self, call: PrimitiveCall, keypoints: Mapping[str, Keypoint], arm: str, timeout_s: float
    ) -> ActionOutcome:
        with self._lock:
            self.log.append((arm, call.primitive, dict(call.args)))
            queue = self._inject.get(call.primitive)
            injected = queue.pop(0) if queue else None
        if self.wall_delay_s:
            time.sleep(self.wall_delay_s)
        if injected:
            return ActionOutcome.fail(injected.reason, injected.failure, injected.sim_time_s)
        with self._lock:
            handler = getattr(self, f"_do_{call.primitive}", None)
            return handler(call.args, keypoints, arm) if handler else ActionOutcome.success(1.0, modelled=False)

    # -- primitive models --------------------------------------------------------------------------------------
    def _go(self, arm: str, target: np.ndarray) -> float:
        dt = float(np.linalg.norm(target - self.tcp[arm])) / self.speed_m_s
        self.tcp[arm] = target.copy()
        if self.held[arm]:
            self.objects[self.held[arm]] = target.copy()
        return dt

    def _kp(self, keypoints: Mapping[str, Keypoint], label: str) -> Keypoint | ActionOutcome:
        if label in self.unreachable:
            return ActionOutcome.fail(
                f"IK found no solution for {label!r} within joint limits", FailureKind.KINEMATIC_LIMIT
            )
        return keypoints[label]

    def _do_move_to_keypoint(self, a, keypoints, arm):
        kp = self._kp(keypoints, a["keypoint_label"])
        if isinstance(kp, ActionOutcome):
            return kp
        target = kp.position_m + np.array([a["offset_x"], a["offset_y"], a["offset_z"]])
        return ActionOutcome.success(self._go(arm, target))

    _do_move_to_keypoint_arm = _do_move_to_keypoint

    def _do_move_relative(self, a, keypoints, arm):
        return ActionOutcome.success(self._go(arm, self.tcp[arm] + np.array([a["dx"], a["dy"], a["dz"]])))

    def _do_retract(self, a, keypoints, arm):
        return ActionOutcome.success(self._go(arm, self.tcp[arm] + np.array([0, 0, a["distance"]])))

    def _do_lift(self, a, keypoints, arm):
        if not self.held[arm]:
            return ActionOutcome.fail("lift with an empty gripper")
        return ActionOutcome.success(self._go(arm, self.tcp[arm] + np.array([0, 0, a["height"]])))

    def _do_go_home(self, a, keypoints, arm):
        return ActionOutcome.success(self._go(arm, HOME.copy()))

    def _do_grasp(self, a, keypoints, arm):
        held = {h for h in self.held.values() if h}
        near = [
            k for k, p in self.objects.items() if k not in held and np.linalg.norm(p - self.tcp[arm]) <= GRASP_RADIUS_M
        ]
        if not near:
            return ActionOutcome.fail("gripper closed on nothing: finger gap at the closed-empty width", sim_time_s=0.5)
        self.held[arm] = near[0]
        return ActionOutcome.success(0.5, object=near[0])

    def _do_release(self, a, keypoints, arm):
        self.held[arm] = None
        return ActionOutcome.success(0.5)

    def _do_wait(self, a, keypoints, arm):
        return ActionOutcome.success(a["duration"])

    def _do_wiggle(self, a, keypoints, arm):
        return ActionOutcome.success(0.5)

    def _do_grasp_perturb(self, a, keypoints, arm):
        self.held[arm] = None
        return ActionOutcome.success(0.5)

    def _do_pick(self, a, keypoints, arm):
        out = self._do_move_to_keypoint(
            {"keypoint_label": a["keypoint_label"], "offset_x": 0, "offset_y": 0, "offset_z": 0}, keypoints, arm
        )
        if not out.ok:
            return out
        g = self._do_grasp(a, keypoints, arm)
        if not g.ok:
            return ActionOutcome.fail(g.reason, sim_time_s=out.sim_time_s + g.sim_time_s)
        return ActionOutcome.success(
            out.sim_time_s + g.sim_time_s + self._go(arm, self.tcp[arm] + np.array([0, 0, a["lift_height"]]))
        )

    _do_pick_with_arm = _do_pick

    def _do_place(self, a, keypoints, arm):
        if not self.held[arm]:
            return ActionOutcome.fail("place with an empty gripper")
        target = keypoints[a["target_label"]].position_m + np.array([0, 0, 0.05])
        dt = self._go(arm, target)
        self.held[arm] = None
        return ActionOutcome.success(dt + 0.5)

    def _do_place_with_arm(self, a, keypoints, arm):
        if a.get("target_label") is not None:
            return self._do_place(a, keypoints, arm)
        if not self.held[arm]:  # the paper's form: set it down where the hand is
            return ActionOutcome.fail("place with an empty gripper")
        self.objects[self.held[arm]] = self.tcp[arm].copy()
        self.held[arm] = None
        return ActionOutcome.success(0.5)

    def _do_push_object(self, a, keypoints, arm):
        label = a["keypoint_label"]
        dx, dy = DIRS[a["direction"]]
        dt = self._go(arm, keypoints[label].position_m.copy())
        self.objects[label] = self.objects[label] + np.array([dx, dy, 0]) * a["distance"]
        return ActionOutcome.success(dt + a["distance"] / self.speed_m_s)

    def _do_handoff(self, a, keypoints, arm):
        giver, taker = a["from_arm"], a["to_arm"]
        if self.held.get(giver) != a["keypoint_label"]:
            return ActionOutcome.fail(f"{giver} arm does not hold {a['keypoint_label']!r}")
        self.held[taker], self.held[giver] = self.held[giver], None
        return ActionOutcome.success(3.0)


class KinematicResolver:
    """Late-binding resolver over the double: `refresh()` snapshots object positions (a 'detection')."""

    SOURCE = "privileged:kinematic-double"

    def __init__(self, world: KinematicWorld, extent_m: float = 0.04):
        self.world = world
        self.extent_m = extent_m
        self.hidden: set[str] = set()  # labels perception currently misses
        self.refreshes = 0
        self.resolved: list[tuple[str, tuple[float, ...]]] = []
        self._snapshot: dict[str, np.ndarray] = {}
        self.refresh()
        self.refreshes = 0

    def refresh(self) -> None:
        self.refreshes += 1
        with self.world._lock:
            self._snapshot = {k: v.copy() for k, v in self.world.objects.items()}

    def resolve(self, label: str) -> Keypoint:
        if label in self.hidden or label not in self._snapshot:
            raise LabelNotFound(label)
        pos = self._snapshot[label]
        self.resolved.append((label, tuple(float(x) for x in pos)))
        return Keypoint(label, pos.copy(), np.full(3, self.extent_m), source=self.SOURCE)
