"""Put a robot description into a MuJoCo scene: URDF import, position actuators with armature and gravity
compensation, a force-limited coupled parallel gripper, a TCP site and a wrist camera."""

from __future__ import annotations

from dataclasses import dataclass

import mujoco
import numpy as np

from ..control.robot import RobotDescription

GRIPPER_KP = 6000.0  # N/m: stiff enough that closing on an object saturates at the force limit set per grasp


@dataclass(frozen=True)
class RobotNames:
    """Names of one robot's elements in the compiled scene (all carry the robot's prefix)."""

    prefix: str
    arm_joints: tuple[str, ...]
    arm_actuators: tuple[str, ...]
    finger_joints: tuple[str, ...]  # empty, like gripper_actuator, for a mounted tool without fingers
    gripper_actuator: str
    tcp_site: str
    wrist_camera: str
    bodies: tuple[str, ...]
    finger_bodies: tuple[str, ...]
    base_body: str


def _robot_spec(robot: RobotDescription) -> mujoco.MjSpec:
    text = robot.urdf_text().replace(
        "</robot>", '<mujoco><compiler fusestatic="false" discardvisual="false" strippath="true"/></mujoco></robot>'
    )
    spec = mujoco.MjSpec.from_string(text)
    spec.meshdir = str(robot.mesh_dir)
    return spec


def add_robot(scene: mujoco.MjSpec, robot: RobotDescription, prefix: str, T_world_base: np.ndarray) -> RobotNames:
    """Attach `robot` to `scene` at `T_world_base` (4x4) with every name prefixed by `prefix`."""
    child = _robot_spec(robot)
    # Assets (meshes) must resolve from the robot's own directory once merged into the scene.
    for mesh in child.meshes:
        mesh.file = str(robot.mesh_dir / mesh.file.split("/")[-1])
    names = [b.name for b in child.bodies if b.name != "world"]
    quat = np.zeros(4)
    mujoco.mju_mat2Quat(quat, np.asarray(T_world_base, float)[:3, :3].flatten())
    frame = scene.worldbody.add_frame(pos=T_world_base[:3, 3], quat=quat)
    base = frame.attach_body(child.body(robot.base_link), prefix, "")
    collide = {prefix + n for n in robot.collision_links}
    for body in scene.bodies:
        if not body.name.startswith(prefix):
            continue
        body.gravcomp = 1.0
        for geom in body.geoms:
            if body.name in collide:
                geom.friction = [1.5, 0.01, 0.001]
                geom.condim = 4 if "finger" in body.name else 3
                geom.solref = [0.01, 1.0]
            else:  # links that do not reach into the workspace do not need contacts (keeps physics fast)
                geom.contype = 0
                geom.conaffinity = 0
            geom.rgba = [0.92, 0.92, 0.94, 1.0] if "finger" not in body.name else [0.2, 0.2, 0.22, 1.0]
    arm_joints = tuple(prefix + j for j in robot.arm_joints)
    actuators = []
    for j, kp, _q0 in zip(arm_joints, robot.kp, robot.home_q_rad):
        joint = scene.joint(j)
        joint.armature = robot.armature
        joint.damping = 2.0
        joint.ref = 0.0
        act = scene.add_actuator(name=j + "_act", target=j, trntype=mujoco.mjtTrn.mjTRN_JOINT)
        act.set_to_position(kp=kp, kv=2 * np.sqrt(kp * (robot.armature + 0.5)))
        act.ctrlrange = joint.range
        act.ctrllimited = True
        actuators.append(act.name)
    f1, f2 = (prefix + f for f in robot.gripper.finger_joints)
    for f in (f1, f2):
        scene.joint(f).armature = 0.01
        scene.joint(f).damping = 5.0
    grip = scene.add_actuator(name=prefix + "gripper", target=f1, trntype=mujoco.mjtTrn.mjTRN_JOINT)
    grip.set_to_position(kp=GRIPPER_KP, kv=60.0)
    grip.ctrlrange = [0.0, robot.gripper.max_width_m / 2]
    grip.ctrllimited = True
    grip.forcelimited = True
    grip.forcerange = [-robot.gripper.max_force_n / 2, robot.gripper.max_force_n / 2]
    eq = scene.add_equality(name=prefix + "finger_coupling", type=mujoco.mjtEq.mjEQ_JOINT, name1=f2, name2=f1)
    eq.data[:5] = [0.0, 1.0, 0.0, 0.0, 0.0]
    eq.solref = [0.005, 1.0]
    tcp_body = scene.body(prefix + robot.tcp_frame)
    tcp_body.add_site(name=prefix + "tcp", size=[0.005, 0, 0], rgba=[1, 0, 0, 0.5], group=5)
    hand = scene.body(prefix + robot.tcp_frame).parent
    hand.add_camera(
        name=prefix + "wrist", pos=[0.05, 0.0, 0.04], quat=[0.0, 1.0, 0.0, 0.0], fovy=75.0
    )  # looks along the TCP approach axis
    finger_bodies = tuple(scene.joint(f).parent.name for f in (f1, f2))
    # Closed fingers rest on their joint limits, not on each other (sibling bodies would otherwise collide).
    scene.add_exclude(bodyname1=finger_bodies[0], bodyname2=finger_bodies[1])
    return RobotNames(
        prefix=prefix,
        arm_joints=arm_joints,
        arm_actuators=tuple(actuators),
        finger_joints=(f1, f2),
        gripper_actuator=grip.name,
        tcp_site=prefix + "tcp",
        wrist_camera=prefix + "wrist",
        bodies=tuple(prefix + n for n in names),
        finger_bodies=finger_bodies,
        base_body=base.name,
    )
