"""Free-space and straight-line TCP motions."""

from __future__ import annotations

import numpy as np

from ...control.pose import Pose, rot_x, top_down_rotation, wrap_grasp_yaw
from ..protocols import ActionOutcome, FailureKind
from .base import Ctx, primitive


@primitive("move_to_keypoint")
@primitive("move_to_keypoint_arm")
def move_to_keypoint(ctx: Ctx) -> ActionOutcome:
    kp = ctx.kp("keypoint_label")
    a = ctx.args
    target = kp.position_m + np.array([a["offset_x"], a["offset_y"], a["offset_z"]])
    target[2] = max(target[2], 0.005)
    pose = ctx.top_down(target, ctx.grasp_yaw(kp))
    tcp = ctx.tcp.position_m
    what = f"point {a['offset_z']:+.2f} m above {kp.label!r}"
    if np.linalg.norm(target[:2] - tcp[:2]) < 0.03 and abs(target[2] - tcp[2]) > 0.005:
        return ctx.motion.move_line(pose, what=what)  # straight down/up over the object
    if target[2] < kp.top_z_m + 0.03:  # going down to the object from elsewhere: come in from above, never sideways
        above = ctx.top_down([target[0], target[1], max(tcp[2], kp.top_z_m + 0.08)], ctx.grasp_yaw(kp))
        out = ctx.motion.move_to(above, what=f"point above {kp.label!r}")
        return ctx.motion.move_line(pose, what=what) if out.ok else out
    return ctx.motion.move_to(pose, what=what)


@primitive("move_above")
def move_above(ctx: Ctx) -> ActionOutcome:
    kp = ctx.kp("keypoint_label")
    target = np.array([kp.position_m[0], kp.position_m[1], kp.top_z_m + ctx.args["height"]])
    return ctx.motion.move_to(ctx.top_down(target, ctx.grasp_yaw(kp)), what=f"point above {kp.label!r}")


@primitive("move_relative")
def move_relative(ctx: Ctx) -> ActionOutcome:
    a = ctx.args
    start = ctx.tcp
    return ctx.motion.move_line(start.translated([a["dx"], a["dy"], a["dz"]]), what="relative target")


@primitive("retract")
def retract(ctx: Ctx) -> ActionOutcome:
    return ctx.motion.move_line(ctx.tcp.translated([0, 0, ctx.args["distance"]]), what="retract height")


@primitive("lift")
def lift(ctx: Ctx) -> ActionOutcome:
    if not ctx.holding():
        return ctx.fail("lift with nothing in the gripper")
    out = ctx.motion.move_line(ctx.tcp.translated([0, 0, ctx.args["height"]]), speed_m_s=0.12, what="lift height")
    if out.ok and not ctx.holding():
        return ctx.fail("object slipped out of the gripper while lifting")
    return out


@primitive("go_home")
def go_home(ctx: Ctx) -> ActionOutcome:
    """Rise straight up to the home height first (never sweep low through what was just opened or placed),
    then move in joint space to the home configuration."""
    kin = ctx.world.kinematics[ctx.arm]
    home_z = float(kin.fk(kin.robot.home_q_rad).position_m[2])
    tcp = ctx.tcp
    if tcp.position_m[2] < home_z - 0.05:
        ctx.motion.move_line(tcp.translated([0, 0, min(0.15, home_z - tcp.position_m[2])]), check=False)
    return ctx.motion.move_joints(kin.robot.home_q_rad, what="home configuration")


@primitive("wait")
def wait(ctx: Ctx) -> ActionOutcome:
    ctx.world.settle(ctx.args["duration"], ctx.arm)
    return ActionOutcome.success(0.0)


@primitive("lower_until_contact")
def lower_until_contact(ctx: Ctx) -> ActionOutcome:
    out = ctx.motion.move_line(
        ctx.tcp.translated([0, 0, -ctx.args["max_distance"]]),
        speed_m_s=0.05,
        stop=ctx.contact(),
        what="lowest point",
        check=False,
    )
    if not out.detail.get("stopped_early"):
        return ctx.fail(f"no contact within {ctx.args['max_distance']:.2f} m")
    return out


@primitive("rotate_wrist")
def rotate_wrist(ctx: Ctx) -> ActionOutcome:
    pose = Pose(ctx.tcp.position_m, top_down_rotation(wrap_grasp_yaw(ctx.args["yaw"])))
    return ctx.motion.move_line(pose, what="wrist yaw")


@primitive("tilt_wrist")
def tilt_wrist(ctx: Ctx) -> ActionOutcome:
    tcp = ctx.tcp
    return ctx.motion.move_line(Pose(tcp.position_m, tcp.rotation @ rot_x(ctx.args["angle"])), what="wrist tilt")


@primitive("wiggle")
def wiggle(ctx: Ctx) -> ActionOutcome:
    start = ctx.tcp
    amp = ctx.args["amplitude"]
    for _ in range(ctx.args["n_cycles"]):
        for d in ((amp, 0), (-amp, 0), (0, amp), (0, -amp)):
            ctx.motion.move_line(start.translated([d[0], d[1], 0]), speed_m_s=0.1, check=False)
    out = ctx.motion.move_line(start, speed_m_s=0.1, what="wiggle start")
    return out if out.ok else ActionOutcome.fail(out.reason, FailureKind.CONTROL)
