"""Arm motions on a World: IK (pinocchio) + jerk-limited joint trajectories (ruckig) + straight Cartesian lines."""

from __future__ import annotations

import threading
from collections.abc import Callable

import numpy as np

from ..control.ik import Unreachable, solve_ik
from ..control.pose import Pose, rotation_error
from ..control.trajectory import Limits, chain_joint_waypoints, line_trajectory
from .protocols import ActionOutcome, FailureKind
from .world_protocol import World

POSITION_TOL_M = 0.01
ARM_CLEARANCE_M = 0.15  # closest a planned TCP path may come to another arm's hand (now or where it is heading)


class ArmMotion:
    """Motion helper for one arm. `speed` scales the joint velocity/acceleration/jerk limits (0..1]."""

    def __init__(self, world: World, arm: str, speed: float = 0.6, rng: np.random.Generator | None = None):
        self.world = world
        self.arm = arm
        self.kin = world.kinematics[arm]
        desc = self.kin.robot
        self.limits = Limits(
            np.array(desc.max_velocity_rad_s),
            np.full(len(desc.arm_joints), desc.max_acceleration_rad_s2),
            np.full(len(desc.arm_joints), desc.max_jerk_rad_s3),
        ).scaled(speed)
        self.rng = rng or np.random.default_rng(0)
        self.clearance_m = ARM_CLEARANCE_M  # cooperative primitives (handoff, two-handed lift) lower it

    def workspace_conflict(self, tcp_path_m: np.ndarray) -> str | None:
        """Shared-workspace check for multi-arm cells: why the TCP path (N x 3, world, m) would bring this hand
        within `clearance_m` of another arm's hand, counting where that arm is and where it is moving to."""
        others = [a for a in getattr(self.world, "arms", ()) if a != self.arm]
        for other in others:
            a = self.world.tcp_pose(other).position_m
            target = getattr(self.world, "target_tcp", {}).get(other)
            b = a if target is None else target.position_m
            ab = b - a
            t = np.clip(((tcp_path_m - a) @ ab) / max(float(ab @ ab), 1e-12), 0.0, 1.0)
            d = np.linalg.norm(tcp_path_m - (a + t[:, None] * ab), axis=1)
            k = int(np.argmin(d))
            if d[k] < self.clearance_m:
                return (
                    f"the {self.arm} arm's path would pass {100 * d[k]:.0f} cm from the {other} arm's hand "
                    f"(keeps {100 * self.clearance_m:.0f} cm): refused before moving"
                )
        return None

    def _guard(self, q_path: np.ndarray) -> ActionOutcome | None:
        """Check the path against the other arms and, if clear, claim its end as this arm's target, atomically:
        two arms planning at the same moment must not both see the other still at rest."""
        if len(getattr(self.world, "arms", ())) < 2:
            return None
        step = max(len(q_path) // 40, 1)
        tcp = np.array([self.kin.fk(q).position_m for q in q_path[::step]] + [self.kin.fk(q_path[-1]).position_m])
        with _claims_lock(self.world):
            why = self.workspace_conflict(tcp)
            if why:
                return ActionOutcome.fail(why, FailureKind.COLLISION)
            targets = getattr(self.world, "target_tcp", None)
            if targets is not None:
                targets[self.arm] = self.kin.fk(q_path[-1])
        return None

    def ik(self, pose: Pose, seed: np.ndarray | None = None, what: str = "target") -> np.ndarray:
        return solve_ik(self.kin, pose, self.world.q(self.arm) if seed is None else seed, rng=self.rng, what=what).q

    def move_to(
        self,
        pose: Pose | list[Pose],
        what: str = "target",
        settle_s: float = 0.05,
        reconfigure_via: np.ndarray | None = None,
    ) -> ActionOutcome:
        """Joint-space move through one or more TCP poses (one smooth chained trajectory).

        `reconfigure_via` (m, world frame): when reaching the first pose needs a large joint change (> 1.5 rad on
        some joint: a wrist flip, an elbow swing), pass through that pose offset by this vector first, so the
        reconfiguration happens in free space rather than next to the target."""
        poses = pose if isinstance(pose, list) else [pose]
        q = self.world.q(self.arm)
        waypoints = [q]
        try:
            for p in poses:
                waypoints.append(self.ik(p, waypoints[-1], what))
            if reconfigure_via is not None and np.max(np.abs(waypoints[1] - q)) > 1.5:
                via = self.ik(Pose(poses[0].position_m + reconfigure_via, poses[0].rotation), q, what)
                waypoints = [q, via, self.ik(poses[0], via, what)] + waypoints[2:]
        except Unreachable as e:
            return ActionOutcome.fail(str(e), FailureKind.KINEMATIC_LIMIT)
        traj = chain_joint_waypoints(waypoints, self.limits)
        refused = self._guard(np.asarray(traj.q_rad))
        if refused:
            return refused
        res = self.world.execute(self.arm, traj, settle_s=settle_s)
        return self._check(poses[-1], res.sim_time_s, what)

    def move_joints(self, q_target: np.ndarray, what: str = "joint target") -> ActionOutcome:
        traj = chain_joint_waypoints([self.world.q(self.arm), q_target], self.limits)
        refused = self._guard(np.asarray(traj.q_rad))
        if refused:
            return refused
        res = self.world.execute(self.arm, traj)
        err = float(np.max(np.abs(self.world.q(self.arm) - q_target)))
        if err > 0.05:
            return ActionOutcome.fail(f"joints {err:.3f} rad from the {what}", FailureKind.CONTROL, res.sim_time_s)
        return ActionOutcome.success(res.sim_time_s)

    def plan_line(
        self, target: Pose, q_start: np.ndarray | None = None, start: Pose | None = None, what: str = "line target"
    ) -> np.ndarray:
        """Joint path (dense IK, 1 cm / 3 deg steps) for a straight TCP line; raises Unreachable."""
        q = self.world.q(self.arm) if q_start is None else np.asarray(q_start, float)
        start = start or self.kin.fk(q)
        dist = float(np.linalg.norm(target.position_m - start.position_m))
        ang = rotation_error(start.rotation, target.rotation)
        n = max(int(np.ceil(max(dist / 0.01, ang / 0.05))), 1)
        path = [q]
        for k in range(1, n + 1):
            s = k / n
            pose = Pose(
                start.position_m + s * (target.position_m - start.position_m),
                _slerp(start.rotation, target.rotation, s),
            )
            try:
                q = solve_ik(self.kin, pose, q, restarts=0, tol_m=5e-4, tol_rad=5e-3, rng=self.rng, what=what).q
            except Unreachable:
                raise Unreachable(
                    f"the straight line to the {what} leaves the workspace or joint limits {100 * s:.0f} % of the way"
                ) from None
            if np.max(np.abs(q - path[-1])) > 0.5:
                raise Unreachable(f"the straight line to the {what} needs a joint flip (singularity or limit)")
            path.append(q)
        return np.array(path)

    def move_line(
        self,
        target: Pose,
        speed_m_s: float = 0.25,
        stop: Callable[[], bool] | None = None,
        what: str = "line target",
        check: bool = True,
    ) -> ActionOutcome:
        """Straight-line TCP motion (dense IK, min-jerk timing). `stop()` ends it early (contact-aware moves)."""
        start = self.world.tcp_pose(self.arm)
        dist = float(np.linalg.norm(target.position_m - start.position_m))
        ang = rotation_error(start.rotation, target.rotation)
        try:
            path = self.plan_line(target, start=start, what=what)
        except Unreachable as e:
            return ActionOutcome.fail(str(e), FailureKind.KINEMATIC_LIMIT)
        duration = max(dist / speed_m_s, ang / 1.0, 0.2)
        refused = self._guard(path)
        if refused:
            return refused
        res = self.world.execute(self.arm, line_trajectory(path, duration), stop=stop)
        if not res.completed or not check:
            return ActionOutcome.success(res.sim_time_s, stopped_early=not res.completed)
        return self._check(target, res.sim_time_s, what)

    def _check(self, target: Pose, sim_s: float, what: str) -> ActionOutcome:
        err = float(np.linalg.norm(self.world.tcp_pose(self.arm).position_m - target.position_m))
        if err > POSITION_TOL_M:
            return ActionOutcome.fail(
                f"TCP {err * 100:.1f} cm from the {what} (tolerance 1 cm): blocked or dragged",
                FailureKind.CONTROL,
                sim_s,
            )
        return ActionOutcome.success(sim_s)


_CLAIMS = threading.Lock()


def _claims_lock(world) -> threading.Lock:
    """The world's lock for checking and claiming arm targets (one per world; a module lock as fallback)."""
    return getattr(world, "claims_lock", _CLAIMS)


def _slerp(R0: np.ndarray, R1: np.ndarray, s: float) -> np.ndarray:
    import pinocchio as pin

    return R0 @ pin.exp3(s * pin.log3(R0.T @ R1))
