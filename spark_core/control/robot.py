"""Robot descriptions: what differs between embodiments is data, not executor code."""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np


@dataclass(frozen=True)
class GripperSpec:
    """Parallel-jaw gripper. Widths are the full finger gap in metres; force is the closing force limit in N."""

    finger_joints: tuple[str, str]
    max_width_m: float
    closed_empty_width_m: float  # gap reading when closed on nothing (sensor noise floor + margin)
    max_force_n: float = 140.0
    finger_speed_m_s: float = 0.15  # per finger


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
    collision_links: tuple[str, ...] = field(default_factory=tuple)  # links that collide with the scene

    def urdf_text(self) -> str:
        """The URDF with visual meshes stripped (MuJoCo cannot read .dae) and package paths made absolute."""
        text = self.urdf_path.read_text()
        text = re.sub(r"<visual>.*?</visual>", "", text, flags=re.S)
        return text.replace(self.package_prefix, str(self.urdf_path.parent.parent) + "/")
