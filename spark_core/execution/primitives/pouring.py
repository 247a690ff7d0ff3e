"""Pouring from a held container."""

from __future__ import annotations

import numpy as np

from ...control.pose import Pose, rot_y
from ..protocols import ActionOutcome
from .base import Ctx, primitive


@primitive("pour")
def pour(ctx: Ctx) -> ActionOutcome:
    """Carry the held container over the target, tilt it about the finger axis, hold, and return upright."""
    if not ctx.holding():
        return ctx.fail("pour with nothing in the gripper")
    target = ctx.kp("target_label")
    angle = ctx.args["pour_angle"]
    yaw = ctx.current_yaw()
    lip = 0.05  # the container's opening sits about this far from the grasp point once tilted
    direction = ctx.tcp.rotation[:, 0]  # tilting about TCP y swings the opening along TCP x
    direction = direction / max(np.linalg.norm(direction[:2]), 1e-6)
    pos = np.array([*(target.position_m[:2] - direction[:2] * lip), target.top_z_m + 0.13])
    out = ctx.motion.move_to(ctx.top_down(pos, yaw), what=f"pouring pose over {target.label!r}")
    if not out.ok:
        return out
    upright = ctx.tcp
    out = ctx.motion.move_line(Pose(upright.position_m, upright.rotation @ rot_y(-angle)), speed_m_s=0.05, what="pour tilt",
                               check=False)
    ctx.world.settle(1.0, ctx.arm)
    ctx.motion.move_line(upright, speed_m_s=0.05, check=False)
    if not ctx.holding():
        return ctx.fail("dropped the container while pouring")
    return ActionOutcome.success(0.0)
