"""Franka Emika Panda from example-robot-data (offline, cmeel layout)."""

from __future__ import annotations

from functools import lru_cache
from pathlib import Path

import numpy as np

from .robot import GripperSpec, RobotDescription


def example_robot_data_dir() -> Path:
    import sysconfig

    import cmeel  # noqa: F401 - the cmeel prefix is where example-robot-data installs its share/ tree

    root = Path(sysconfig.get_paths()["purelib"]) / "cmeel.prefix/share/example-robot-data/robots"
    if not root.is_dir():
        raise FileNotFoundError(f"example-robot-data robots not found at {root}: install example-robot-data==6.0.0")
    return root


@lru_cache(maxsize=1)
def panda() -> RobotDescription:
    root = example_robot_data_dir() / "panda_description"
    return RobotDescription(
        name="panda",
        urdf_path=root / "urdf/panda.urdf",
        package_prefix="package://example-robot-data/robots/panda_description/",
        mesh_dir=root / "meshes/collision",
        base_link="panda_link0",
        tcp_frame="panda_hand_tcp",
        arm_joints=tuple(f"panda_joint{i}" for i in range(1, 8)),
        home_q_rad=np.array([0.0, -0.785398, 0.0, -2.356194, 0.0, 1.570796, 0.785398]),
        gripper=GripperSpec(
            ("panda_finger_joint1", "panda_finger_joint2"), max_width_m=0.08, closed_empty_width_m=0.004
        ),
        kp=(4500.0, 4500.0, 3500.0, 3500.0, 2000.0, 2000.0, 2000.0),
        max_velocity_rad_s=(2.175, 2.175, 2.175, 2.175, 2.61, 2.61, 2.61),
        collision_links=("panda_hand", "panda_leftfinger", "panda_rightfinger", "panda_link7", "panda_link6"),
    )
