"""Universal Robots UR10 from example-robot-data (`ur_description`), with a parallel-jaw gripper built here
(Robotiq-2F-85-like: 85 mm stroke, two prismatic fingers, force-limited), mounted on the flange (`tool0`).

The gripper is URDF appended to the arm's URDF, so MuJoCo (physics) and pinocchio (IK) read one model. Its
TCP frame follows the Panda's convention (z = approach, fingers move along y), so primitives are unchanged."""

from __future__ import annotations

from functools import lru_cache

import numpy as np

from .panda import example_robot_data_dir
from .robot import GripperSpec, RobotDescription

STROKE_M = 0.085
FINGER_JOINT_Z_M = 0.09  # finger slides sit 9 cm from the flange
TCP_Z_M = 0.14  # between the finger pads, 1 cm above the fingertips (like the Panda's TCP)


def _finger(name: str, joint: str, yaw: float) -> str:
    return f"""
  <link name="{name}">
    <inertial><mass value="0.06"/><origin xyz="0 0.006 0.03"/>
      <inertia ixx="2e-5" iyy="2e-5" izz="1e-5" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><origin xyz="0 0.008 0.03"/><geometry><box size="0.022 0.016 0.06"/></geometry></collision>
  </link>
  <joint name="{joint}" type="prismatic">
    <parent link="ur_gripper_base"/><child link="{name}"/>
    <origin xyz="0 0 {FINGER_JOINT_Z_M}" rpy="0 0 {yaw}"/><axis xyz="0 1 0"/>
    <limit lower="0" upper="{STROKE_M / 2}" effort="120" velocity="0.15"/>
  </joint>"""


GRIPPER_URDF = f"""
  <link name="ur_gripper_base">
    <inertial><mass value="0.9"/><origin xyz="0 0 0.045"/>
      <inertia ixx="1.5e-3" iyy="1.5e-3" izz="1e-3" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><origin xyz="0 0 0.045"/><geometry><box size="0.075 0.13 0.09"/></geometry></collision>
  </link>
  <joint name="ur_gripper_mount" type="fixed">
    <parent link="tool0"/><child link="ur_gripper_base"/><origin xyz="0 0 0"/>
  </joint>{_finger("ur_left_finger", "ur_finger_joint1", 0.0)}{_finger("ur_right_finger", "ur_finger_joint2", np.pi)}
  <link name="ur_tcp"/>
  <joint name="ur_tcp_joint" type="fixed">
    <parent link="ur_gripper_base"/><child link="ur_tcp"/><origin xyz="0 0 {TCP_Z_M}"/>
  </joint>
"""


@lru_cache(maxsize=1)
def ur10() -> RobotDescription:
    root = example_robot_data_dir() / "ur_description"
    return RobotDescription(
        name="ur10",
        urdf_path=root / "urdf/ur10_robot.urdf",  # joints +-2 pi, as on the real arm
        package_prefix="package://example-robot-data/robots/ur_description/",
        mesh_dir=root / "meshes/ur10/collision",
        base_link="base_link",
        tcp_frame="ur_tcp",
        arm_joints=(
            "shoulder_pan_joint",
            "shoulder_lift_joint",
            "elbow_joint",
            "wrist_1_joint",
            "wrist_2_joint",
            "wrist_3_joint",
        ),
        home_q_rad=np.array(HOME_Q_RAD),
        gripper=GripperSpec(("ur_finger_joint1", "ur_finger_joint2"), max_width_m=STROKE_M, closed_empty_width_m=0.004),
        kp=(9000.0, 9000.0, 6000.0, 2500.0, 2500.0, 2000.0),
        max_velocity_rad_s=(2.09, 2.09, 3.14, 3.14, 3.14, 3.14),
        reach_m=1.3,
        extra_urdf=GRIPPER_URDF,
        # one configuration family: base turned at most half a turn, shoulder above the base plane, elbow up
        ik_limits_rad=(
            (-np.pi, np.pi),
            (-np.pi, 0.0),
            (0.0, np.pi),
            (-2 * np.pi, 2 * np.pi),
            (-2 * np.pi, 2 * np.pi),
            (-2 * np.pi, 2 * np.pi),
        ),
        collision_links=("ur_gripper_base", "ur_left_finger", "ur_right_finger", "wrist_3_link", "wrist_2_link"),
    )


# TCP at (0.45, 0, 0.45) m in the base frame, approach axis down, x forward (the Panda's home orientation);
# solved once with solve_ik from (0, -pi/2, pi/2, -pi/2, -pi/2, 0).
HOME_Q_RAD = (-0.3729, -2.0257, 2.0167, -1.5618, -1.5708, -1.9437)
