"""Pouring from a held container."""

from __future__ import annotations

import numpy as np

from ...control.ik import Unreachable
from ...control.pose import Pose, rot_y
from ..protocols import ActionOutcome, FailureKind
from .base import Ctx, primitive


@primitive("pour")
def pour(ctx: Ctx) -> ActionOutcome:
    """Carry the held container over the target, tilt it about the finger axis, hold, and return upright.

    The opening swings along the TCP x axis; of the two tilt directions the first whose upright and tilted
    poses both have IK solutions is used.
    """
    if not ctx.holding():
        return ctx.fail("pour with nothing in the gripper")
    target = ctx.kp("target_label")
    angle = ctx.args["pour_angle"]
    yaw = ctx.current_yaw()
    lip = 0.05  # the container's opening sits about this far from the grasp point once tilted
    x_axis = ctx.tcp.rotation[:, 0] / max(np.linalg.norm(ctx.tcp.rotation[:2, 0]), 1e-6)
    for sign in (1.0, -1.0):
        pos = np.array([*(target.position_m[:2] - sign * x_axis[:2] * lip), target.top_z_m + 0.13])
        upright = ctx.top_down(pos, yaw)
        tilted = Pose(pos, upright.rotation @ rot_y(-sign * angle))
        try:
            q_up = ctx.motion.ik(upright, what="pouring pose")
            ctx.motion.ik(tilted, q_up, what="tilted pouring pose")
        except Unreachable:
            continue
        out = ctx.motion.move_to(upright, what=f"pouring pose over {target.label!r}")
        if not out.ok:
            return out
        out = ctx.motion.move_line(tilted, speed_m_s=0.05, what="pour tilt", check=False)
        if not out.ok:
            return out
        ctx.world.settle(1.0, ctx.arm)
        ctx.motion.move_line(upright, speed_m_s=0.05, check=False)
        if not ctx.holding():
            return ctx.fail("dropped the container while pouring")
        return ActionOutcome.success(0.0, tilt_sign=sign)
    return ActionOutcome.fail(f"no reachable pouring pose over {target.label!r} in either tilt direction",
                              FailureKind.KINEMATIC_LIMIT)
