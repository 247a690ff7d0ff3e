"""Control: robot descriptions, kinematics (pinocchio), IK, jerk-limited trajectories (ruckig)."""

from .ik import IKResult, Unreachable, solve_ik
from .kinematics import ArmKinematics
from .pose import Pose, top_down_rotation
from .robot import GripperSpec, RobotDescription
from .trajectory import JointTrajectory, Limits, chain_joint_waypoints, line_trajectory

__all__ = [
    "ArmKinematics",
    "GripperSpec",
    "IKResult",
    "JointTrajectory",
    "Limits",
    "Pose",
    "RobotDescription",
    "Unreachable",
    "chain_joint_waypoints",
    "line_trajectory",
    "solve_ik",
    "top_down_rotation",
]
