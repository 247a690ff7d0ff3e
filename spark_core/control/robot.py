"""Robot descriptions: what differs between embodiments is data, not executor code."""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np


@dataclass(frozen=True)
class GripperSpec:
    """Parallel-jaw gripper. Widths are the full finger gap in metres; force is the closing force limit in N.

    `mounted_tool` names a tool fixed to the flange in place of fingers (robosuite's wiping pad): the arm always
    holds it and has nothing to open or close. `finger_joints` still names the URDF's finger joints, which the
    kinematics locks."""

    finger_joints: tuple[str, str]
    max_width_m: float
    closed_empty_width_m: float  # gap reading when closed on nothing (sensor noise floor + margin)
    max_force_n: float = 140.0
    finger_speed_m_s: float = 0.15  # per finger
    grasp_depth_m: float = 0.045  # how far below an object's top the TCP may go before the palm touches it
    mounted_tool: str = ""
    tool_size_m: tuple[float, float] = (0.0, 0.0)  # a mounted tool's contact face along the hand's (x, y) axes


@dataclass(frozen=True)
class RobotDescription:
    """One arm: kinematic source, joint chain, TCP frame, gripper, limits and home pose.

    `urdf_path` feeds both MuJoCo (physics) and pinocchio (IK), so the two models cannot drift apart.
    Joint limits come from the URDF; `home_q_rad` is the arm's rest configuration.
    """

    name: str
    urdf_path: Path
    package_prefix: str  # the `package://...` prefix the URDF uses for its meshes
    mesh_dir: Path  # directory of the collision meshes
    base_link: str
    tcp_frame: str
    arm_joints: tuple[str, ...]
    home_q_rad: np.ndarray
    gripper: GripperSpec
    kp: tuple[float, ...]  # position-actuator stiffness per arm joint (N m / rad)
    max_velocity_rad_s: tuple[float, ...]
    max_acceleration_rad_s2: float = 8.0
    max_jerk_rad_s3: float = 80.0
    armature: float = 0.1
    reach_m: float = 0.85
    # Primitive timeouts (the grammar's, from the paper) are stretched by this on a slower arm: robosuite's
    # Panda wrist tops out near 1 rad/s where the real one turns 2.6 rad/s.
    timeout_scale: float = 1.0
    collision_links: tuple[str, ...] = field(default_factory=tuple)  # links that collide with the scene
    extra_urdf: str = ""  # links and joints appended to the URDF (e.g. a gripper built for this arm)
    # Narrower joint ranges for IK (rad), per arm joint, or None for the URDF's: keeps solutions in one arm
    # configuration (e.g. the UR10's elbow up, shoulder above the base plane) so moves never flip the arm.
    ik_limits_rad: tuple[tuple[float, float], ...] | None = None

    def urdf_text(self) -> str:
        """The URDF with visual meshes stripped (MuJoCo cannot read .dae), package paths made absolute and
        `extra_urdf` appended: the one text both MuJoCo and pinocchio load."""
        text = self.urdf_path.read_text()
        text = re.sub(r"<visual>.*?</visual>", "", text, flags=re.S)
        text = text.replace(self.package_prefix, str(self.urdf_path.parent.parent) + "/")
        return text.replace("</robot>", self.extra_urdf + "</robot>") if self.extra_urdf else text
