"""Mid-task looks for LIBERO training scenes, drawn from the scene seed: a cabinet drawer pulled out, the hand posed
just above an object or at an open drawer, sometimes holding the object. LIBERO's resets always show closed drawers
and the arm at home, so a network trained on them alone had never seen a drawer's open inside or a hand at a bowl:
after "open the top drawer" it painted the drawer's inside and the fingers as more bowls and lost the real one.
The poses are random (IK to random points near random objects), never an evaluation init state.

TRAINING ONLY: works on the simulator's state (joints, geoms); the segmenter never imports this.
"""

from __future__ import annotations

import mujoco
import numpy as np

from ...control.ik import Unreachable, solve_ik
from ...control.pose import Pose
from .rearrange import _subtree, movables, world_box

OPEN_P = 0.5  # a scene with drawers gets one pulled out
OPEN_FRACTION = (0.4, 1.0)  # how far, as a fraction of the slide's travel
REACH_P = 0.6  # the hand is posed at an object (the other scenes keep the seeded joint jitter)
DRAWER_P = 0.5  # with a drawer open, the hand goes to it this often
HOLD_P = 0.3  # a movable object the hand reaches for is held between the fingers this often
ABOVE_M = (0.02, 0.15)  # the hand's grip point above the object's top
XY_JITTER_M = 0.03


def drawer_joints(world) -> list[int]:
    """Slide joints outside the robot (the cabinets' drawers; LIBERO's other fixtures do not slide)."""
    m = world.model
    robot = {m.body(b).id for r in world.scene.robots.values() for b in r.bodies}
    return [
        j
        for j in range(m.njnt)
        if m.jnt_type[j] == mujoco.mjtJoint.mjJNT_SLIDE and int(m.jnt_bodyid[j]) not in robot and m.jnt_limited[j]
    ]


def open_drawer(world, rng: np.random.Generator) -> int | None:
    """Pull one drawer out (before the settle, so what it holds rides along); returns its body id, or None."""
    joints = drawer_joints(world)
    if not joints or rng.random() >= OPEN_P:
        return None
    m, d = world.model, world.data
    j = int(rng.choice(joints))
    lo, hi = m.jnt_range[j]
    out = lo if abs(lo) > abs(hi) else hi  # closed is 0; the far end of the travel is open
    d.qpos[m.jnt_qposadr[j]] = out * rng.uniform(*OPEN_FRACTION)
    mujoco.mj_forward(m, d)
    return int(m.jnt_bodyid[j])


def _grip_down(world, arm: str, yaw_rad: float) -> np.ndarray:
    """The hand's rotation at home (LIBERO's home holds the fingers pointing down), turned by `yaw_rad` about z."""
    c, s = np.cos(yaw_rad), np.sin(yaw_rad)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]]) @ world.tcp_pose(arm).rotation


def pose_arm(world, rng: np.random.Generator, drawer_body: int | None) -> str:
    """After the settle: IK the first arm's grip point to just above a random object (or into the open drawer) and
    sometimes put a movable object in the hand. Returns what was done ("" when nothing)."""
    if not world.arms or rng.random() >= REACH_P:
        return ""
    m, d = world.model, world.data
    arm = world.arms[0]
    objects = list(world.scene.objects.items())
    if drawer_body is not None and rng.random() < DRAWER_P:
        lo, hi = world_box(m, d, m.geom_bodyid == drawer_body)
        label, target_top = "open drawer", np.array([(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, hi[2]])
    else:
        label, obj = objects[int(rng.integers(len(objects)))]
        lo, hi = world_box(m, d, _subtree(m, m.body(obj.body).id))
        target_top = np.array([(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, hi[2]])
    goal = target_top + np.array([*rng.normal(0.0, XY_JITTER_M, 2), rng.uniform(*ABOVE_M)])
    rot = _grip_down(world, arm, rng.uniform(-np.pi / 2, np.pi / 2))
    try:
        q = solve_ik(world.kinematics[arm], Pose(goal - world.origin_m, rot), world.q(arm), rng=rng, restarts=4).q
    except Unreachable:
        return ""
    d.qpos[world._qadr[arm]] = q
    width = float(rng.uniform(0.0, world.scene.robot_descriptions[arm].gripper.max_width_m))
    mujoco.mj_forward(m, d)
    held = next((mv for mv in movables(world) if mv.label == label), None)
    if held is not None and rng.random() < HOLD_P:
        lo, hi = world_box(m, d, _subtree(m, held.body))
        grip = d.site_xpos[world._tcp[arm]]
        # the object's box centre to the grip point: it hangs between the fingers, which close on its width
        d.qpos[held.qadr : held.qadr + 3] += grip - (lo + hi) / 2
        d.qvel[held.dadr : held.dadr + 6] = 0.0
        width = float(min(hi[0] - lo[0], hi[1] - lo[1], world.scene.robot_descriptions[arm].gripper.max_width_m))
        label = f"holding {label}"
    for f in world._fingers.get(arm, []):  # each finger opens towards the far end of its slide (signs differ)
        j = int(np.flatnonzero(m.jnt_qposadr == f)[0])
        lo, hi = m.jnt_range[j]
        d.qpos[f] = np.sign(lo if abs(lo) > abs(hi) else hi) * width / 2
    mujoco.mj_forward(m, d)
    return f"hand at {label}"
