"""Arm kinematics in pinocchio, built from the same URDF MuJoCo simulates (fingers locked)."""

from __future__ import annotations

import numpy as np
import pinocchio as pin

from .pose import Pose
from .robot import RobotDescription


class ArmKinematics:
    """Forward kinematics and Jacobians of one arm's TCP in the WORLD frame.

    `T_world_base` places the robot's base link in the world (4x4, metres). Not thread-safe: one per arm.
    """

    def __init__(self, robot: RobotDescription, T_world_base: np.ndarray | None = None):
        full = pin.buildModelFromXML(robot.urdf_text())
        lock = [full.getJointId(j) for j in robot.gripper.finger_joints]
        self.model = pin.buildReducedModel(full, lock, pin.neutral(full))
        self.data = self.model.createData()
        self.robot = robot
        self.tcp_id = self.model.getFrameId(robot.tcp_frame)
        T = np.eye(4) if T_world_base is None else np.asarray(T_world_base, float)
        self.T_world_base = T
        self._base = pin.SE3(T[:3, :3], T[:3, 3])
        self.lower = self.model.lowerPositionLimit.copy()
        self.upper = self.model.upperPositionLimit.copy()
        if robot.ik_limits_rad is not None:
            lo, hi = np.array(robot.ik_limits_rad, float).T
            self.lower, self.upper = np.maximum(self.lower, lo), np.minimum(self.upper, hi)
        assert self.model.nq == len(robot.arm_joints), "reduced model must contain exactly the arm joints"

    @property
    def nq(self) -> int:
        return self.model.nq

    def _tcp_se3(self, q: np.ndarray) -> pin.SE3:
        pin.forwardKinematics(self.model, self.data, q)
        pin.updateFramePlacement(self.model, self.data, self.tcp_id)
        return self._base * self.data.oMf[self.tcp_id]

    def fk(self, q: np.ndarray) -> Pose:
        T = self._tcp_se3(np.asarray(q, float))
        return Pose(T.translation.copy(), T.rotation.copy())

    def jacobian(self, q: np.ndarray) -> np.ndarray:
        """6xN Jacobian (linear; angular) of the TCP in world-aligned axes."""
        J = pin.computeFrameJacobian(self.model, self.data, np.asarray(q, float), self.tcp_id, pin.LOCAL_WORLD_ALIGNED)
        R = self.T_world_base[:3, :3]
        return np.vstack([R @ J[:3], R @ J[3:]])

    def within_limits(self, q: np.ndarray, margin: float = 0.0) -> bool:
        return bool(np.all(q >= self.lower + margin) and np.all(q <= self.upper - margin))
